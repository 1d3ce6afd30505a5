// Issue 22 item 9: the XY table's alarms name the table and its axes, never the rail, its
// platform or its centre, in every language; the history line of an XY alarm carries them.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QRegularExpression>

#include "core/machine/event_text.h"
#include "core/xy/xy_event_text.h"
#include "translations/i18n.h"

namespace trilho {
namespace {

void ensureApp() {
    static int argc = 1;
    static char name[] = "xy_alarm_text_test";
    static char* argv[] = {name, nullptr};
    if (!QCoreApplication::instance()) new QCoreApplication(argc, argv);
}

struct Language {
    const char* lang;
    const char* forbidden;  ///< the rail's words, as a case-insensitive regular expression
    const char* table;      ///< the table
    const char* axis;       ///< an axis
};
const Language kLanguages[] = {
    {"en", R"(\b(rail|platform|centre|center)\b)", "table", "axis"},
    {"pt_BR", R"(\b(trilho|plataforma|centro|central|carro)\b)", "mesa", "eixo"},
    {"es", R"(\b(riel|carril|plataforma|centro|central|carro)\b)", "mesa", "eje"},
};

// The alarms a DC table raises about its motion or its drives: each names the table and an axis.
const AlarmCode kTableAlarms[] = {AlarmCode::FollowingError,    AlarmCode::SoftLimitStop,
                                  AlarmCode::InPositionTimeout, AlarmCode::FinalPositionOff,
                                  AlarmCode::EncoderStalled,    AlarmCode::OverCurrent,
                                  AlarmCode::SeedLawRunaway};

TEST(XyAlarmTexts, NameTheTableNeverTheRailInEveryLanguage) {
    ensureApp();
    for (const Language& l : kLanguages) {
        ASSERT_TRUE(installLanguage(QString::fromLatin1(l.lang))) << l.lang;
        const QRegularExpression rail(QString::fromLatin1(l.forbidden),
                                      QRegularExpression::CaseInsensitiveOption |
                                          QRegularExpression::UseUnicodePropertiesOption);
        for (int c = 1; c < static_cast<int>(AlarmCode::Count_); ++c) {
            const auto code = static_cast<AlarmCode>(c);
            const QString text = xyAlarmText(code, 12.5);
            EXPECT_FALSE(text.isEmpty()) << l.lang << " alarm " << c;
            EXPECT_FALSE(text.contains(rail))
                << l.lang << " alarm " << c << ": " << text.toStdString();
            EXPECT_FALSE(text.contains(QLatin1String("%1"))) << l.lang << " alarm " << c;
            if (const char* source = xyAlarmSource(code)) {
                if (QLatin1String(l.lang) != QLatin1String("en")) {
                    EXPECT_NE(QCoreApplication::translate("Controller", source),
                              QString::fromUtf8(source))
                        << l.lang << " alarm " << c << " is not translated";
                }
                if (QString::fromUtf8(source).contains(QLatin1String("%1"))) {
                    EXPECT_TRUE(text.contains(QLatin1String("12.5"))) << l.lang << " alarm " << c;
                }
            }
        }
        for (AlarmCode code : kTableAlarms) {
            const QString text = xyAlarmText(code, 3.0);
            EXPECT_TRUE(text.contains(QLatin1String(l.table)))
                << l.lang << ": " << text.toStdString();
            EXPECT_TRUE(text.contains(QLatin1String(l.axis)))
                << l.lang << ": " << text.toStdString();
            // Both axes by name: "x or y", "x ou y", "x o y".
            static const QRegularExpression axes(QStringLiteral("\\bx (or|ou|o) y\\b"));
            EXPECT_TRUE(text.contains(axes)) << l.lang << ": " << text.toStdString();
        }
    }
    installLanguage(QStringLiteral("en"));
}

// Issue 30 item 6: the soft-limit guard's alarm under seed 004's law says why the table got
// there (the law's |e|, the direction fixed for the move) and where it was stopped.
TEST(XyAlarmTexts, TheSeedLawsRunawayNamesTheLawAndTheLimit) {
    ensureApp();
    for (const Language& l : kLanguages) {
        ASSERT_TRUE(installLanguage(QString::fromLatin1(l.lang))) << l.lang;
        for (const QString& text : {xyAlarmText(AlarmCode::SeedLawRunaway, 0.0),
                                    alarmText(AlarmCode::SeedLawRunaway, 0.0)}) {
            EXPECT_TRUE(text.contains(QLatin1String("004")))
                << l.lang << ": " << text.toStdString();
            EXPECT_TRUE(text.contains(QLatin1String("|e|")))
                << l.lang << ": " << text.toStdString();
            EXPECT_TRUE(text.contains(QLatin1String(" 0 mm")))
                << l.lang << ": " << text.toStdString();
        }
    }
    installLanguage(QStringLiteral("en"));
}

TEST(XyAlarmTexts, TheHistoryLineCarriesTheTablesText) {
    ensureApp();
    installLanguage(QStringLiteral("pt_BR"));
    ControllerEvent e;
    e.kind = EventKind::AlarmRaised;
    e.alarm = AlarmCode::FollowingError;
    e.value = 8.1;
    const QString line = xyHistoryLine(e);
    EXPECT_TRUE(line.startsWith(
        QStringLiteral("Alarme 3: Erro de seguimento: um eixo da mesa (x ou y) ficou 8.1 mm")))
        << line.toStdString();
    EXPECT_FALSE(line.contains(QStringLiteral("plataforma"))) << line.toStdString();
    // A warning keeps its frame.
    e.alarm = AlarmCode::FinalPositionOff;
    e.value = 0.25;
    EXPECT_TRUE(xyHistoryLine(e).contains(QStringLiteral("com a mesa a 0.25 mm")))
        << xyHistoryLine(e).toStdString();
    // The rail keeps its own text.
    EXPECT_TRUE(historyLine(e).contains(QStringLiteral("plataforma")))
        << historyLine(e).toStdString();
    installLanguage(QStringLiteral("en"));
}

}  // namespace
}  // namespace trilho
