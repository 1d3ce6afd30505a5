// Every diagnostic message has a pt_BR and an es translation, and pt_BR gives the 1996 texts.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QXmlStreamReader>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/gcode/diagnostic_text.h"
#include "core/machine/event_text.h"
#include "translations/i18n.h"

namespace trilho {
namespace {

QCoreApplication& app() {
    // One application for the whole test binary (data_paths_test needs one too).
    static int argc = 1;
    static char name[] = "translation_test";
    static char* argv[] = {name, nullptr};
    if (!QCoreApplication::instance()) new QCoreApplication(argc, argv);
    return *QCoreApplication::instance();
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
              QStringLiteral("Erro: Seqüência n errada na linha 10"));  // the VB's own place
    EXPECT_EQ(diagnosticMessage(p.diagnostics[1]),
              QStringLiteral("Erro: Comando g inválido na linha 10"));
    EXPECT_EQ(diagnosticMessage(p.diagnostics[2]),
              QStringLiteral("Erro: Programa requer m02 (END) no final"));
    EXPECT_EQ(compileSummary(3), QStringLiteral("Há 3 erro(s) de compilação !"));
    EXPECT_EQ(compileSummary(0), QStringLiteral("Compilação completada com sucesso !"));
    installLanguage(QStringLiteral("en"));
    EXPECT_EQ(diagnosticMessage(p.diagnostics[1]),
              QStringLiteral("invalid g command in line n=10 (g05)"));
}

// Issue 9: "on line N" used to name the block number while the prefix gave the file line. A
// message now says "block n=40" for the block number and "line 6" for the file line.
TEST(DiagnosticPlace, BlockNumberAndFileLineAreNamedDistinctly) {
    app();
    Program p = compile("N10 G0 X1\nG0 X2\n\n\n(c)\nG7\nN40 G7\nM2\n", {Dialect::Standard, {}});
    ASSERT_EQ(p.diagnostics.size(), 2u);
    ASSERT_EQ(p.diagnostics[0].line, 6u);
    ASSERT_EQ(p.diagnostics[1].line, 7u);
    const struct {
        const char* lang;
        const char* line6;
        const char* block40;
    } expected[] = {
        {"en", "invalid g command on line 6 (G7)", "invalid g command in block n=40 (G7)"},
        {"pt_BR", "Erro: Comando g inválido na linha 6", "Erro: Comando g inválido no bloco n=40"},
        {"es", "comando g inválido en la línea 6 (G7)",
         "comando g inválido en el bloque n=40 (G7)"},
    };
    for (const auto& e : expected) {
        ASSERT_TRUE(installLanguage(QString::fromLatin1(e.lang)));
        EXPECT_EQ(diagnosticMessage(p.diagnostics[0]), QString::fromUtf8(e.line6)) << e.lang;
        EXPECT_EQ(diagnosticMessage(p.diagnostics[1]), QString::fromUtf8(e.block40)) << e.lang;
    }
    installLanguage(QStringLiteral("en"));
    Program g = compile("N20 M3 X99\nN30 M2\n", {Dialect::Standard, {}});
    ASSERT_EQ(g.diagnostics.size(), 1u);
    EXPECT_EQ(diagnosticMessage(g.diagnostics[0]),
              QStringLiteral("invalid GO TO in block n=20: block n=99 does not exist"));
    Program f = compile("G1 X1 F0.05\nM2\n", {Dialect::Standard, {}});
    ASSERT_EQ(f.diagnostics.size(), 1u);
    EXPECT_EQ(diagnosticMessage(f.diagnostics[0]),
              QStringLiteral("feed f0.05 out of range on line 1: must be from 0.1 % to 100 %"));
    EXPECT_EQ(omittedDiagnostics(4002),
              QStringLiteral("... and 4002 more diagnostic(s) not listed"));
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

/// Every source text and its translation in a .ts file (contexts merged).
std::vector<std::pair<QString, QString>> translatedTexts(const char* lang) {
    std::vector<std::pair<QString, QString>> texts;
    QFile f(QStringLiteral(TRILHO_TRANSLATIONS_DIR "/trilho_%1.ts").arg(QLatin1String(lang)));
    if (!f.open(QIODevice::ReadOnly)) return texts;
    QXmlStreamReader xml(&f);
    QString source;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        if (xml.name() == QLatin1String("source")) source = xml.readElementText();
        if (xml.name() == QLatin1String("translation"))
            texts.emplace_back(source, xml.readElementText());
    }
    return texts;
}

// Issue 31 item 6: a text that tells the operator to press a safety-bar button names it as the
// button does in that language (pt_BR and es said "Liberar" on the button and "Rearme" in the
// status bar's line, two words for one action).
TEST(TranslationFiles, TextsNameTheSafetyButtonsAsTheButtonsDo) {
    for (const char* lang : {"pt_BR", "es"}) {
        const auto texts = translatedTexts(lang);
        ASSERT_GT(texts.size(), 150u) << lang;
        for (const char* button : {"Reset E-stop", "Acknowledge"}) {
            QString word;
            for (const auto& [source, translation] : texts)
                if (source == QLatin1String(button)) word = translation;
            ASSERT_FALSE(word.isEmpty()) << lang << ": " << button;
            // The verb's stem: a sentence conjugates it ("Reconhecer" on the button,
            // "Reconheça" in a sentence), but never says another verb ("Rearme").
            word = word.left(6);
            for (const auto& [source, translation] : texts) {
                if (source == QLatin1String(button) || !source.contains(QLatin1String(button)))
                    continue;
                EXPECT_TRUE(translation.contains(word, Qt::CaseInsensitive))
                    << lang << ": '" << source.toStdString() << "' -> '"
                    << translation.toStdString() << "' does not say '" << word.toStdString() << "'";
            }
        }
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

namespace trilho {
namespace {

// Issue 10: every alarm says what happened and what to do next, in the three languages. The
// next step is one of the operator's actions, named as the screens name them.
TEST(AlarmTexts, EveryAlarmHasACauseAndANextStepInEveryLanguage) {
    app();
    const struct {
        const char* lang;
        std::vector<const char*> nextSteps;
    } languages[] = {
        {"en",
         {"cknowledge", "Correct the", "Move it back", "run it again", "Reset E-stop", "check the",
          "press Stop"}},
        {"pt_BR",
         {"econheça", "Corrija", "Leve-a de volta", "execute de novo", "Liberar emergência",
          "verifique", "Parar"}},
        {"es",
         {"econozca", "Corrija", "Llévela de vuelta", "ejecútelo de nuevo", "Liberar emergencia",
          "revise", "Detener"}},
    };
    for (const auto& l : languages) {
        ASSERT_TRUE(installLanguage(QString::fromLatin1(l.lang)));
        for (int c = 1; c < static_cast<int>(AlarmCode::Count_); ++c) {
            const auto code = static_cast<AlarmCode>(c);
            const QString source = QString::fromUtf8(alarmSource(code));
            const QString text = alarmText(code, -1270.0);
            EXPECT_FALSE(text.isEmpty()) << l.lang << " alarm " << c;
            if (QLatin1String(l.lang) != QLatin1String("en")) {
                EXPECT_NE(QCoreApplication::translate("Controller", alarmSource(code)), source)
                    << l.lang << " alarm " << c;
            }
            // A cause, then a next step: at least two sentences.
            EXPECT_GE(text.count(QLatin1Char('.')) + text.count(QLatin1Char('!')), 2)
                << l.lang << " alarm " << c << ": " << text.toStdString();
            bool hasNextStep = false;
            for (const char* step : l.nextSteps)
                hasNextStep = hasNextStep || text.contains(QString::fromUtf8(step));
            EXPECT_TRUE(hasNextStep) << l.lang << " alarm " << c << ": " << text.toStdString();
            // The figure the alarm carries is shown wherever the text has a place for it.
            if (source.contains(QLatin1String("%1"))) {
                EXPECT_TRUE(text.contains(QLatin1String("1270"))) << l.lang << " alarm " << c;
            }
            EXPECT_FALSE(text.contains(QLatin1String("%1"))) << l.lang << " alarm " << c;
        }
    }
    installLanguage(QStringLiteral("en"));
}

// "Soft limit reached" says where: the limit the platform stopped at.
TEST(AlarmTexts, SoftLimitNamesThePosition) {
    app();
    installLanguage(QStringLiteral("en"));
    EXPECT_TRUE(alarmText(AlarmCode::SoftLimit, -1270.0).contains(QLatin1String("x=-1270 mm")));
    EXPECT_TRUE(alarmText(AlarmCode::SoftLimit, 1270.0).contains(QLatin1String("x=1270 mm")));
}

}  // namespace
}  // namespace trilho

namespace trilho {
namespace {

// Issue 31 item 6: warnings (the machine goes on) were listed in History and the journal as
// Kind "alarm", under the line "Warning 14: ...".
TEST(JournalKind, AWarningIsNotAnAlarm) {
    ControllerEvent e;
    e.kind = EventKind::AlarmRaised;
    e.alarm = AlarmCode::CounterCorrected;
    EXPECT_EQ(journalKind(e), QStringLiteral("warning"));
    EXPECT_TRUE(historyLine(e).startsWith(QStringLiteral("Warning ")));
    e.alarm = AlarmCode::FollowingError;
    EXPECT_EQ(journalKind(e), QStringLiteral("alarm"));
    e.kind = EventKind::AlarmAcknowledged;
    EXPECT_EQ(journalKind(e), QStringLiteral("ack"));
    e.kind = EventKind::Rapid;
    e.alarm = AlarmCode::None;
    EXPECT_EQ(journalKind(e), QStringLiteral("status"));
    // Every alarm: "warning" exactly when its line says "Warning".
    for (int a = 1; a < static_cast<int>(AlarmCode::Count_); ++a) {
        e.kind = EventKind::AlarmRaised;
        e.alarm = static_cast<AlarmCode>(a);
        EXPECT_EQ(journalKind(e) == QLatin1String("warning"),
                  historyLine(e).startsWith(QStringLiteral("Warning ")))
            << a;
    }
}

}  // namespace
}  // namespace trilho
