#include "ui/gcode_highlighter.h"

namespace trilho {
namespace ui {

GcodeHighlighter::GcodeHighlighter(QTextDocument* document) : QSyntaxHighlighter(document) {
    auto format = [](QColor c, bool bold = false, bool italic = false) {
        QTextCharFormat f;
        f.setForeground(c);
        if (bold) f.setFontWeight(QFont::Bold);
        f.setFontItalic(italic);
        return f;
    };
    const auto ci = QRegularExpression::CaseInsensitiveOption;
    rules_ = {
        {QRegularExpression(QStringLiteral("\\bn\\d+"), ci), format(QColor(120, 120, 120))},
        {QRegularExpression(QStringLiteral("g\\d+"), ci), format(QColor(0, 0, 170), true)},
        {QRegularExpression(QStringLiteral("m\\d+"), ci), format(QColor(160, 0, 120), true)},
        {QRegularExpression(QStringLiteral("[xy][-+]?[\\d.]+"), ci), format(QColor(0, 120, 0))},
        {QRegularExpression(QStringLiteral("f[-+]?[\\d.]+"), ci), format(QColor(170, 90, 0))},
        {QRegularExpression(QStringLiteral("\\([^)]*\\)?|;.*$")),
         format(QColor(110, 110, 110), false, true)},
    };
}

void GcodeHighlighter::highlightBlock(const QString& text) {
    for (const Rule& rule : rules_) {
        auto it = rule.pattern.globalMatch(text);
        while (it.hasNext()) {
            const auto m = it.next();
            setFormat(static_cast<int>(m.capturedStart()), static_cast<int>(m.capturedLength()),
                      rule.format);
        }
    }
}

}  // namespace ui
}  // namespace trilho
