#include "core/gcode/diagnostic_text.h"

#include <QCoreApplication>

namespace trilho {
namespace {

constexpr const char* kContext = "Diagnostic";

// Placeholders: %1 where: "in block n=40" when the line has a block number, "on line 6"
// otherwise (the diagnostic's prefix always gives the file line), %2 the offending text, %3 a
// value (a limit, the previous n, a digit count).
constexpr const char* kSource[kMessageCount] = {
    QT_TRANSLATE_NOOP("Diagnostic", "every line must start with n (found '%2')"),
    QT_TRANSLATE_NOOP("Diagnostic", "wrong n sequence %1: must be greater than %3"),
    QT_TRANSLATE_NOOP("Diagnostic", "sequence number alone %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "separating spaces required %1 (found '%2')"),
    QT_TRANSLATE_NOOP("Diagnostic", "there can be no more commands after %2 %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "g00 requires an x word %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "g01 requires an x word %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "g04 without x word (time) %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "g92 requires an x word %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "m03 without x word (block) %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid value after g04 %1: the time %2 is negative"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid value after m03 %1: the block %2 is negative"),
    QT_TRANSLATE_NOOP("Diagnostic", "negative f command impossible %1 (%2)"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid g command %1 (%2)"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid m command %1 (%2)"),
    QT_TRANSLATE_NOOP("Diagnostic", "g01 or g00 not defined %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "g01 needs f defined %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character or g00 does not take f %1"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: '%2'"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: malformed number '%2'"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: '%2' must have exactly %3 digits"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: comment not closed"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: word '%2' repeated"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: n must be the first word ('%2')"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid value after m03 %1: '%2' is not a block number"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid character %1: number '%2' longer than %3 digits"),
    QT_TRANSLATE_NOOP("Diagnostic", "program requires m02 (END) at the end"),
    QT_TRANSLATE_NOOP("Diagnostic", "invalid GO TO %1: block n=%2 does not exist"),
    QT_TRANSLATE_NOOP("Diagnostic", "feed f%2 out of range %1: must be from %3 % to 100 %"),
    QT_TRANSLATE_NOOP("Diagnostic", "target %2 mm %1 is beyond the soft limit %3 mm"),
    QT_TRANSLATE_NOOP("Diagnostic", "axis %2 %1 does not exist on this machine"),
    QT_TRANSLATE_NOOP("Diagnostic", "block number '%2' too large %1: at most %3"),
    QT_TRANSLATE_NOOP("Diagnostic", "value '%2' too large %1: at most %3 in magnitude"),
};

QString number(double v) {
    return QString::number(v, 'g', 12);
}

}  // namespace

const char* diagnosticSourceText(MessageId id) {
    return kSource[static_cast<int>(id)];
}

QString substitute(const QString& text, std::initializer_list<QString> args) {
    QString out;
    out.reserve(text.size() + 16);
    for (qsizetype i = 0; i < text.size(); ++i) {
        QChar c = text[i];
        if (c == u'%' && i + 1 < text.size() && text[i + 1].isDigit() && text[i + 1] != u'0') {
            auto index = static_cast<std::size_t>(text[i + 1].digitValue() - 1);
            if (index < args.size()) {
                out += *(args.begin() + index);
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

QString diagnosticPlace(const Diagnostic& d) {
    // The classic dialect says where as the VB did (seed 000, Compilar_click): "na linha " +
    // CStr(programa(i).n), the block number the line starts with (issue 22 item 3).
    if (d.classic && d.n >= 0)
        return substitute(QCoreApplication::translate("Diagnostic", "in line n=%1"),
                          {QString::number(d.n)});
    if (d.n >= 0)
        return substitute(QCoreApplication::translate("Diagnostic", "in block n=%1"),
                          {QString::number(d.n)});
    return substitute(QCoreApplication::translate("Diagnostic", "on line %1"),
                      {QString::number(d.line)});
}

QString diagnosticMessage(const Diagnostic& d) {
    const QString where = diagnosticPlace(d);
    const QString text = QCoreApplication::translate(kContext, diagnosticSourceText(d.id));
    return substitute(text, {where, QString::fromUtf8(d.text), number(d.value)});
}

QString compileSummary(std::size_t errorCount) {
    if (errorCount == 0)
        return QCoreApplication::translate("Diagnostic", "Compilation completed successfully");
    return substitute(QCoreApplication::translate("Diagnostic", "%1 compile error(s)"),
                      {QString::number(errorCount)});
}

QString omittedDiagnostics(std::size_t count) {
    return substitute(
        QCoreApplication::translate("Diagnostic", "... and %1 more diagnostic(s) not listed"),
        {QString::number(count)});
}

}  // namespace trilho
