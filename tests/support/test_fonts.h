#pragma once
// The fonts the widget tests measure with (issue 35): named files from Debian packages that
// scripts/deps.sh installs, loaded into the test process and set as the application font and
// as the screens' fixed-pitch font, so that a layout passes or fails the same way on every
// machine, whatever fonts its desktop or a screenshot tool brought.
#include <QList>
#include <QMetaType>
#include <QString>
#include <QStringList>

namespace trilho {
namespace testing {

/// One set of fonts: the application's (proportional) and the fixed-pitch one, by file.
struct FontSet {
    QString name;           ///< for a failure message: "DejaVu 9 pt"
    QStringList sansFiles;  ///< the first file's family becomes the application font
    QStringList monoFiles;  ///< the first file's family becomes ui::fixedFamily()
    int pointSize = 9;      ///< the application font's size, in points
};

/// DejaVu Sans and DejaVu Sans Mono (fonts-dejavu-core) at 9 pt, what a Debian 12 desktop and
/// Qt's offscreen platform use by default: the set every widget test starts with.
FontSet dejaVuFonts(int pointSize = 9);
/// DejaVu Sans with Noto Sans Mono (fonts-noto-mono) as the fixed-pitch font: what fontconfig
/// picks for "Monospace" once fonts-noto-mono is installed (ImageMagick's dependencies bring it).
FontSet dejaVuWithNotoMono(int pointSize = 9);
/// Noto Sans and Noto Sans Mono (fonts-noto-core, fonts-noto-mono): what fontconfig picks for
/// "Sans Serif" once fonts-noto-core is installed, and KDE Plasma's desktop font (at 10 pt). Its
/// line is 17 px at 9 pt against DejaVu's 14.
FontSet notoFonts(int pointSize = 9);
/// Liberation Sans and Liberation Mono (fonts-liberation2): the metric-compatible Arial and
/// Courier New that Debian's desktops (GNOME, LibreOffice) install.
FontSet liberationFonts(int pointSize = 9);
/// Nimbus Sans and Nimbus Mono PS (fonts-urw-base35): what Ghostscript and ImageMagick bring,
/// and what fontconfig picks for "Helvetica", "Arial" and "Courier" where Liberation is absent.
FontSet urwFonts(int pointSize = 9);
/// Every set above, at one size: the layout tests run with each (issue 35 item 3).
QList<FontSet> everyFontSet(int pointSize);

/// Loads the set's files and makes them the application's and the screens' fonts, for the
/// widgets made from now on. Returns an empty string, or what went wrong naming the file.
QString useFonts(const FontSet& set);
/// useFonts, or the process ends with the message: for a test's main, before any widget.
void useFontsOrDie(const FontSet& set);

}  // namespace testing
}  // namespace trilho

Q_DECLARE_METATYPE(trilho::testing::FontSet)
