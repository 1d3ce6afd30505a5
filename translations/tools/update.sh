#!/usr/bin/env bash
# Regenerates the .ts files from the sources and fills every text from the previous files and
# ui_texts.tsv; fails when a text has no translation. Run from anywhere.
set -euo pipefail
cd "$(dirname "$0")/../.."
LUPDATE=/usr/lib/qt6/bin/lupdate
for lang in pt_BR es; do mv "translations/trilho_$lang.ts" "translations/trilho_$lang.ts.old"; done
trap 'rm -f translations/*.ts.old' EXIT
"$LUPDATE" -I . -no-obsolete -locations none core ui app hal host -ts translations/trilho_pt_BR.ts translations/trilho_es.ts
python3 translations/tools/fill_ts.py
"$LUPDATE" -I . -no-obsolete -locations none core ui app hal host -ts translations/trilho_pt_BR.ts translations/trilho_es.ts >/dev/null
