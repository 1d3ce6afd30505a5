// What trilho's shipped texts say of themselves (issue 32 item 10): a document a profile or a
// document cites exists, and no text still calls seed 004's law `classic`, which the profile
// loader refuses since issue 22 (the law is `seed`, `seed-signed` or `engineered`).
#include <gtest/gtest.h>

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QStringList>

namespace {

const QString kRoot = QStringLiteral(TRILHO_RESOURCES_DIR "/..");

QString readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

/// README.md, docs/*.md and resources/machines/*.json: the texts an operator and a teacher read.
QStringList shippedTexts() {
    QStringList files{kRoot + QStringLiteral("/README.md")};
    for (const auto& [dir, filter] :
         {std::pair{QStringLiteral("/docs"), QStringLiteral("*.md")},
          std::pair{QStringLiteral("/resources/machines"), QStringLiteral("*.json")}}) {
        QDirIterator it(kRoot + dir, {filter}, QDir::Files);
        while (it.hasNext())
            files << it.next();
    }
    return files;
}

}  // namespace

TEST(ShippedTexts, EveryDocumentCitedExists) {
    const QRegularExpression cited(QStringLiteral("\\bdocs/[A-Za-z0-9_.-]+\\.md\\b"));
    int checked = 0;
    for (const QString& file : shippedTexts()) {
        const QString text = readAll(file);
        ASSERT_FALSE(text.isEmpty()) << file.toStdString();
        for (auto m = cited.globalMatch(text); m.hasNext();) {
            const QString doc = m.next().captured(0);
            ++checked;
            EXPECT_TRUE(QFile::exists(kRoot + QLatin1Char('/') + doc))
                << QDir(kRoot).relativeFilePath(file).toStdString() << " cites "
                << doc.toStdString() << ", which does not exist";
        }
    }
    EXPECT_GT(checked, 10);  // the scan found the citations it is meant to check
}

TEST(ShippedTexts, SeedFoursLawIsNotCalledClassic) {
    // The words that named it before issue 22: "'classic' runs seed 004's difference equations
    // exactly", "the seed's law as `classic`".
    const QRegularExpression old(
        QStringLiteral("'classic' runs seed 004|seed's law as `classic`|law: 'classic'"));
    for (const QString& file : shippedTexts()) {
        const auto m = old.match(readAll(file));
        EXPECT_FALSE(m.hasMatch()) << QDir(kRoot).relativeFilePath(file).toStdString() << ": \""
                                   << m.captured(0).toStdString() << "\"";
    }
}
