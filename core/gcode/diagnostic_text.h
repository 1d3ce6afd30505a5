#pragma once
// Diagnostic and summary messages in the UI language, through Qt Linguist translations
// (translations/trilho_*.ts). English is the source language; pt_BR holds the 1996 texts.
#include <QString>

#include "core/gcode/diagnostic.h"

namespace trilho {

/// The message of one diagnostic, e.g. "Erro: Seqüência n errada no bloco n=20".
QString diagnosticMessage(const Diagnostic& d);

/// Where a diagnostic is, as its message names it: "in block n=40" when the line has a block
/// number, "on line 6" otherwise (translated).
QString diagnosticPlace(const Diagnostic& d);

/// The closing line of a capped list: "... and 4002 more diagnostic(s) not listed".
QString omittedDiagnostics(std::size_t count);

/// "N compile error(s)" or "Compilation completed successfully", translated.
QString compileSummary(std::size_t errorCount);

/// The untranslated source text of a message (for tests that check every id is translated).
const char* diagnosticSourceText(MessageId id);

/// Replaces %1..%9 in text with args without Qt's warnings for placeholders a translation
/// leaves out (the pt_BR originals name fewer values than the English texts).
QString substitute(const QString& text, std::initializer_list<QString> args);

}  // namespace trilho
