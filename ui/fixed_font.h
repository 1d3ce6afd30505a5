#pragma once
// The fixed-pitch font of the screens: the program editors, the plotter's communication log and
// the readout's digits. One place, so that the widget tests can name the file they measure
// with (issue 35: the readout's height, and with it the rail form's fit at 1024x768, moved
// with whichever monospace the machine's fontconfig picked).
#include <QFont>
#include <QString>

namespace trilho {
namespace ui {

/// The family asked for: fontconfig's "Monospace" alias unless setFixedFamily named one.
QString fixedFamily();
/// Names the fixed-pitch family for every widget made from now on (empty: back to the alias).
/// Call before the widgets are made; the tests do, with a font file they loaded.
void setFixedFamily(const QString& family);
/// A fixed-pitch font of fixedFamily() with the size left unresolved, so that a widget given
/// it keeps the size it inherits (the application's) unless the caller sets one: the editors'.
QFont fixedFont();
/// The desktop's own fixed-pitch font (QFontDatabase::systemFont, which a KDE or GNOME
/// platform theme takes from the desktop's settings), or fixedFamily() once one was named:
/// the readout's digits, whose size the readout sets.
QFont desktopFixedFont();

}  // namespace ui
}  // namespace trilho
