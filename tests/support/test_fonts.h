#pragma once
// The fonts the widget tests measure with (issue 35): named files from Debian packages that
// scripts/deps.sh installs, loaded into the test process and set as the application font and
// as the screens' fixed-pitch font, so that a layout passes or fails the same way on every
// machine, whatever fonts its desktop or a screenshot tool brought.
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

/// Loads the set's files and makes them the application's and the screens' fonts, for the
/// widgets made from now on. Returns an empty string, or what went wrong naming the file.
QString useFonts(const FontSet& set);
/// useFonts, or the process ends with the message: for a test's main, before any widget.
void useFontsOrDie(const FontSet& set);

}  // namespace testing
}  // namespace trilho

Q_DECLARE_METATYPE(trilho::testing::FontSet)
