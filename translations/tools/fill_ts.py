#!/usr/bin/env python3
"""Fills unfinished entries of the .ts files from ui_texts.tsv (source<TAB>pt_BR<TAB>es).

Run after lupdate has added new source texts (translations/tools/update.sh does all of it):
  /usr/lib/qt6/bin/lupdate -I . -no-obsolete -locations none core ui app hal host -ts translations/trilho_*.ts
  python3 translations/tools/fill_ts.py
A trilho_LANG.ts.old beside a file (a copy from before regenerating it) also supplies texts.
Entries with no row in the table stay unfinished and are listed, so nothing is missed quietly.
"""
import csv
import pathlib
import sys
import xml.etree.ElementTree as ET

here = pathlib.Path(__file__).resolve().parent
table = {}
with open(here / "ui_texts.tsv", encoding="utf-8") as f:
    for row in csv.reader(f, delimiter="\t", quoting=csv.QUOTE_NONE):
        if row and not row[0].startswith("#"):
            table[row[0]] = {"pt_BR": row[1], "es": row[2]}

def previous_translations(path):
    """Translations already in a file (e.g. a copy made before regenerating it)."""
    found = {}
    if path.exists():
        for message in ET.parse(path).getroot().iter("message"):
            t = message.find("translation")
            if t is not None and t.get("type") != "unfinished" and t.text:
                found.setdefault(message.find("source").text, t.text)
    return found

missing = 0
for lang in ("pt_BR", "es"):
    path = here.parent / f"trilho_{lang}.ts"
    keep = previous_translations(path.with_suffix(".ts.old"))
    for source, text in keep.items():
        table.setdefault(source, {}).setdefault(lang, text)
    tree = ET.parse(path)
    for message in tree.getroot().iter("message"):
        translation = message.find("translation")
        if translation.get("type") != "unfinished":
            continue
        source = message.find("source").text
        if source in table and lang in table[source]:
            translation.text = table[source][lang]
            del translation.attrib["type"]
        else:
            missing += 1
            print(f"{lang}: no translation for {source!r}", file=sys.stderr)
    tree.write(path, encoding="utf-8", xml_declaration=True)
sys.exit(1 if missing else 0)
