#include "tests/support/test_fonts.h"

#include <QApplication>
#include <QFileInfo>
#include <QFont>
#include <QFontDatabase>
#include <QHash>
#include <cstdio>
#include <cstdlib>

#include "ui/fixed_font.h"

namespace trilho {
namespace testing {

namespace {
const QString kDejaVu = QStringLiteral("/usr/share/fonts/truetype/dejavu/");
const QString kNoto = QStringLiteral("/usr/share/fonts/truetype/noto/");
const QString kLiberation = QStringLiteral("/usr/share/fonts/truetype/liberation2/");
const QString kUrw = QStringLiteral("/usr/share/fonts/opentype/urw-base35/");

QStringList dejaVuSans() {
    return {kDejaVu + QStringLiteral("DejaVuSans.ttf"),
            kDejaVu + QStringLiteral("DejaVuSans-Bold.ttf"),
            kDejaVu + QStringLiteral("DejaVuSans-Oblique.ttf"),
            kDejaVu + QStringLiteral("DejaVuSans-BoldOblique.ttf")};
}

/// Loads a font file once per process; the family it holds, or an error naming the file.
QString loadFile(const QString& path, QString* error) {
    static QHash<QString, QString> loaded;  // path -> family
    if (auto it = loaded.constFind(path); it != loaded.constEnd()) return *it;
    if (!QFileInfo::exists(path)) {
        *error = QStringLiteral(
                     "font file %1 is missing (install the package that holds it: "
                     "scripts/deps.sh)")
                     .arg(path);
        return {};
    }
    const int id = QFontDatabase::addApplicationFont(path);
    const QStringList families =
        id < 0 ? QStringList() : QFontDatabase::applicationFontFamilies(id);
    if (families.isEmpty()) {
        *error = QStringLiteral("font file %1 could not be loaded by Qt").arg(path);
        return {};
    }
    loaded.insert(path, families.first());
    return families.first();
}

/// Loads every file; the first one's family.
QString loadFiles(const QStringList& files, QString* error) {
    QString family;
    for (const QString& f : files) {
        const QString got = loadFile(f, error);
        if (!error->isEmpty()) return {};
        if (family.isEmpty()) family = got;
    }
    if (family.isEmpty()) *error = QStringLiteral("a font set with no file");
    return family;
}
}  // namespace

FontSet dejaVuFonts(int pointSize) {
    return {QStringLiteral("DejaVu %1 pt").arg(pointSize),
            dejaVuSans(),
            {kDejaVu + QStringLiteral("DejaVuSansMono.ttf"),
             kDejaVu + QStringLiteral("DejaVuSansMono-Bold.ttf")},
            pointSize};
}

FontSet dejaVuWithNotoMono(int pointSize) {
    return {QStringLiteral("DejaVu Sans, Noto Sans Mono %1 pt").arg(pointSize),
            dejaVuSans(),
            {kNoto + QStringLiteral("NotoSansMono-Regular.ttf"),
             kNoto + QStringLiteral("NotoSansMono-Bold.ttf")},
            pointSize};
}

FontSet notoFonts(int pointSize) {
    return {
        QStringLiteral("Noto %1 pt").arg(pointSize),
        {kNoto + QStringLiteral("NotoSans-Regular.ttf"),
         kNoto + QStringLiteral("NotoSans-Bold.ttf"), kNoto + QStringLiteral("NotoSans-Italic.ttf"),
         kNoto + QStringLiteral("NotoSans-BoldItalic.ttf")},
        {kNoto + QStringLiteral("NotoSansMono-Regular.ttf"),
         kNoto + QStringLiteral("NotoSansMono-Bold.ttf")},
        pointSize};
}

FontSet liberationFonts(int pointSize) {
    return {QStringLiteral("Liberation %1 pt").arg(pointSize),
            {kLiberation + QStringLiteral("LiberationSans-Regular.ttf"),
             kLiberation + QStringLiteral("LiberationSans-Bold.ttf"),
             kLiberation + QStringLiteral("LiberationSans-Italic.ttf"),
             kLiberation + QStringLiteral("LiberationSans-BoldItalic.ttf")},
            {kLiberation + QStringLiteral("LiberationMono-Regular.ttf"),
             kLiberation + QStringLiteral("LiberationMono-Bold.ttf")},
            pointSize};
}

FontSet urwFonts(int pointSize) {
    return {QStringLiteral("URW Nimbus %1 pt").arg(pointSize),
            {kUrw + QStringLiteral("NimbusSans-Regular.otf"),
             kUrw + QStringLiteral("NimbusSans-Bold.otf"),
             kUrw + QStringLiteral("NimbusSans-Italic.otf"),
             kUrw + QStringLiteral("NimbusSans-BoldItalic.otf")},
            {kUrw + QStringLiteral("NimbusMonoPS-Regular.otf"),
             kUrw + QStringLiteral("NimbusMonoPS-Bold.otf")},
            pointSize};
}

QList<FontSet> everyFontSet(int pointSize) {
    return {dejaVuFonts(pointSize), dejaVuWithNotoMono(pointSize), notoFonts(pointSize),
            liberationFonts(pointSize), urwFonts(pointSize)};
}

QString useFonts(const FontSet& set) {
    QString error;
    const QString sans = loadFiles(set.sansFiles, &error);
    if (!error.isEmpty()) return set.name + QStringLiteral(": ") + error;
    const QString mono = loadFiles(set.monoFiles, &error);
    if (!error.isEmpty()) return set.name + QStringLiteral(": ") + error;
    // A desktop's font is a few points either side of 9; outside 4..48 pt it is a typo.
    if (set.pointSize < 4 || set.pointSize > 48)
        return set.name + QStringLiteral(": point size %1 outside 4..48").arg(set.pointSize);
    QApplication::setFont(QFont(sans, set.pointSize));
    ui::setFixedFamily(mono);
    return {};
}

void useFontsOrDie(const FontSet& set) {
    const QString error = useFonts(set);
    if (error.isEmpty()) return;
    std::fprintf(stderr, "trilho widget test: %s\n", qPrintable(error));
    std::exit(2);
}

}  // namespace testing
}  // namespace trilho
