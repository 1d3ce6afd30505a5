#include "ui/fixed_font.h"

#include <QFontDatabase>

namespace trilho {
namespace ui {

namespace {
/// Set once by a test's main before any widget exists; read on the GUI thread only.
QString& chosenFamily() {
    static QString family;
    return family;
}
}  // namespace

QString fixedFamily() {
    return chosenFamily().isEmpty() ? QStringLiteral("Monospace") : chosenFamily();
}

void setFixedFamily(const QString& family) {
    chosenFamily() = family;
}

QFont fixedFont() {
    QFont mono(fixedFamily());
    mono.setStyleHint(QFont::TypeWriter);
    return mono;
}

QFont desktopFixedFont() {
    if (chosenFamily().isEmpty()) return QFontDatabase::systemFont(QFontDatabase::FixedFont);
    return fixedFont();
}

}  // namespace ui
}  // namespace trilho
