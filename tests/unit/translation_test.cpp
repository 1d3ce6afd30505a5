// Every diagnostic message has a pt_BR and an es translation, and pt_BR gives the 1996 texts.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QXmlStreamReader>

#include "core/compiler.h"
#include "core/diagnostic_text.h"
#include "core/event_text.h"
#include "translations/i18n.h"

namespace trilho {
namespace {

QCoreApplication& app() {
    static int argc = 1;
    static char name[] = "translation_test";
    static char* argv[] = {name, nullptr};
    static QCoreApplication instance(argc, argv);
    return instance;
}

class Translations : public ::testing::TestWithParam<const char*> {
  protected:
    void SetUp() override { app(); }
    void TearDown() override { installLanguage(QStringLiteral("en")); }
};

TEST_P(Translations, EveryMessageIsTranslated) {
    ASSERT_TRUE(installLanguage(QString::fromLatin1(GetParam())));
    for (int i = 0; i < kMessageCount; ++i) {
        const char* source = diagnosticSourceText(static_cast<MessageId>(i));
        const QString translated = QCoreApplication::translate("Diagnostic", source);
        EXPECT_NE(translated, QString::fromUtf8(source)) << GetParam() << ": " << source;
        EXPECT_FALSE(translated.isEmpty());
    }
    EXPECT_NE(compileSummary(0), QStringLiteral("Compilation completed successfully"));
    EXPECT_NE(compileSummary(3), QStringLiteral("3 compile error(s)"));
}

INSTANTIATE_TEST_SUITE_P(Languages, Translations, ::testing::Values("pt_BR", "es"));

TEST(TranslationsPtBr, OriginalTexts) {
    app();
    ASSERT_TRUE(installLanguage(QStringLiteral("pt_BR")));
    Program p = compile("n0020 g90\nn0010 g05\n", {Dialect::Classic, {}});
    ASSERT_EQ(p.diagnostics.size(), 3u);
    EXPECT_EQ(diagnosticMessage(p.diagnostics[0]),
              QStringLiteral("Erro: Seqüência n errada na linha 10"));
    EXPECT_EQ(diagnosticMessage(p.diagnostics[1]),
              QStringLiteral("Erro: Comando g inválido na linha 10"));
    EXPECT_EQ(diagnosticMessage(p.diagnostics[2]),
              QStringLiteral("Erro: Programa requer m02 (END) no final"));
    EXPECT_EQ(compileSummary(3), QStringLiteral("Há 3 erro(s) de compilação !"));
    EXPECT_EQ(compileSummary(0), QStringLiteral("Compilação completada com sucesso !"));
    installLanguage(QStringLiteral("en"));
    EXPECT_EQ(diagnosticMessage(p.diagnostics[1]),
              QStringLiteral("invalid g command on line 10 (g05)"));
}

TEST(TranslationsLanguages, UnknownLanguageIsRefused) {
    app();
    EXPECT_FALSE(installLanguage(QStringLiteral("xx")));
}

}  // namespace
}  // namespace trilho

namespace trilho {
namespace {

// Every text lupdate found in the sources has a translation in both files (translations/tools/
// update.sh regenerates them and fails on a missing text; this guards the committed files).
TEST(TranslationFiles, NoUnfinishedOrEmptyTranslation) {
    for (const char* lang : {"pt_BR", "es"}) {
        QFile f(QStringLiteral(TRILHO_TRANSLATIONS_DIR "/trilho_%1.ts").arg(QLatin1String(lang)));
        ASSERT_TRUE(f.open(QIODevice::ReadOnly)) << lang;
        QXmlStreamReader xml(&f);
        int messages = 0;
        QString source;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement()) continue;
            if (xml.name() == QLatin1String("source")) source = xml.readElementText();
            if (xml.name() == QLatin1String("translation")) {
                EXPECT_NE(xml.attributes().value(QLatin1String("type")),
                          QLatin1String("unfinished"))
                    << lang << ": " << source.toStdString();
                EXPECT_FALSE(xml.readElementText().isEmpty())
                    << lang << ": " << source.toStdString();
                ++messages;
            }
        }
        EXPECT_FALSE(xml.hasError()) << xml.errorString().toStdString();
        EXPECT_GT(messages, 150) << lang;
    }
}

}  // namespace
}  // namespace trilho

namespace trilho {
namespace {

TEST(OnlineStatus, EveryEventThatSetsItHasAText) {
    for (int k = 0; k < static_cast<int>(EventKind::Count_); ++k) {
        const auto kind = static_cast<EventKind>(k);
        EXPECT_EQ(onlineSource(kind) != nullptr, setsOnlineStatus(kind)) << k;
        EXPECT_NE(historySource(kind), nullptr) << k;
    }
}

}  // namespace
}  // namespace trilho
