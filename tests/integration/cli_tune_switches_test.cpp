// Issue 33 item 9 at the CLI: `tune step --anti-windup on|off --encoder-noise N
// --dac-quantisation on|off` (docs/teaching.md lessons 17 and 18): the figures the lessons
// print, the sidecar that records them, and every bad value refused with its option named.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;
using trilho::test::writeIn;

QJsonObject json(const CliResult& r) {
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8());
    EXPECT_TRUE(d.isObject()) << r.out.toStdString() << r.err.toStdString();
    return d.object();
}

class CliTuneSwitches : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QStringList step(const QStringList& more) {
        return QStringList{QStringLiteral("tune"), QStringLiteral("step"),
                           QStringLiteral("--json")} +
               more;
    }
};

TEST_F(CliTuneSwitches, TheAntiWindupLessonsOvershootWithAndWithout) {
    const QString profile = writeIn(dir, QStringLiteral("rail-ferror-400.json"),
                                    R"({"kind": "rail", "loop": {"followingErrorLimitMm": 400,
                    "minFollowingErrorMm": 400}})");
    const QStringList common{QStringLiteral("--machine"),     profile,
                             QStringLiteral("--amplitude"),   QStringLiteral("30"),
                             QStringLiteral("--mass-factor"), QStringLiteral("6"),
                             QStringLiteral("--ki"),          QStringLiteral("2")};
    const CliResult on = runCli(step(common));
    const CliResult off =
        runCli(step(common + QStringList{QStringLiteral("--anti-windup"), QStringLiteral("off")}));
    ASSERT_EQ(on.exit, 0) << on.err.toStdString();
    ASSERT_EQ(off.exit, 0) << off.err.toStdString();
    const QJsonObject a = json(on), b = json(off);
    EXPECT_NEAR(a[QStringLiteral("overshoot_pct")].toDouble(), 11.842, 0.01);
    EXPECT_NEAR(b[QStringLiteral("overshoot_pct")].toDouble(), 17.398, 0.01);
    EXPECT_NEAR(a[QStringLiteral("settling_time_1count_s")].toDouble(), 1.709, 0.002);
    EXPECT_NEAR(b[QStringLiteral("settling_time_1count_s")].toDouble(), 2.147, 0.002);
    EXPECT_TRUE(a[QStringLiteral("anti_windup")].toBool());
    EXPECT_FALSE(b[QStringLiteral("anti_windup")].toBool());
    // The text report says the switch.
    const CliResult text =
        runCli(QStringList{QStringLiteral("tune"), QStringLiteral("step")} + common +
               QStringList{QStringLiteral("--anti-windup"), QStringLiteral("off")});
    EXPECT_TRUE(text.out.contains(QStringLiteral("anti-windup off"))) << text.out.toStdString();
}

TEST_F(CliTuneSwitches, NoiseAndQuantizationAreRecordedInTheSidecar) {
    const QString trace = dir.filePath(QStringLiteral("n.csv"));
    const CliResult r = runCli(
        step({QStringLiteral("--machine"), QStringLiteral("rail"), QStringLiteral("--amplitude"),
              QStringLiteral("10"), QStringLiteral("--encoder-noise"), QStringLiteral("2"),
              QStringLiteral("--dac-quantisation"), QStringLiteral("off"),
              QStringLiteral("--trace"), trace}));
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_EQ(json(r)[QStringLiteral("encoder_noise_counts")].toInt(), 2);
    QFile side(trace + QStringLiteral(".run.json"));
    if (!side.exists()) side.setFileName(dir.filePath(QStringLiteral("n.run.json")));
    ASSERT_TRUE(side.open(QIODevice::ReadOnly)) << side.fileName().toStdString();
    const QJsonObject s = QJsonDocument::fromJson(side.readAll()).object();
    EXPECT_EQ(s[QStringLiteral("encoder_noise_counts")].toInt(), 2);
    EXPECT_FALSE(s[QStringLiteral("dac_quantisation")].toBool(true));
    EXPECT_TRUE(s[QStringLiteral("anti_windup")].toBool(false));
}

TEST_F(CliTuneSwitches, BadValuesAreRefusedWithTheirOptionNamed) {
    struct Case {
        QStringList args;
        const char* says;
    };
    const Case cases[] = {
        {{QStringLiteral("--anti-windup"), QStringLiteral("maybe")},
         "--anti-windup must be on or off"},
        {{QStringLiteral("--dac-quantisation"), QStringLiteral("")},
         "--dac-quantisation must be on or off"},
        {{QStringLiteral("--encoder-noise"), QStringLiteral("-1")}, "--encoder-noise must be"},
        {{QStringLiteral("--encoder-noise"), QStringLiteral("101")}, "--encoder-noise must be"},
        {{QStringLiteral("--encoder-noise"), QStringLiteral("1.5")}, "--encoder-noise must be"},
        {{QStringLiteral("--encoder-noise"), QStringLiteral("1e9")}, "--encoder-noise must be"},
        {{QStringLiteral("--law"), QStringLiteral("classic"), QStringLiteral("--anti-windup"),
          QStringLiteral("off")},
         "no anti-windup to turn off"},
        {{QStringLiteral("--law"), QStringLiteral("classic"), QStringLiteral("--dac-quantisation"),
          QStringLiteral("off")},
         "engineered law"},
    };
    for (const Case& c : cases) {
        const CliResult r =
            runCli(step(QStringList{QStringLiteral("--amplitude"), QStringLiteral("10")} + c.args));
        EXPECT_EQ(r.exit, 2) << c.args.join(' ').toStdString();
        EXPECT_TRUE(r.err.contains(QLatin1String(c.says)))
            << c.args.join(' ').toStdString() << ": " << r.err.toStdString();
    }
    const CliResult table = runCli(
        step({QStringLiteral("--machine"), QStringLiteral("xy_dc_table"), QStringLiteral("--axis"),
              QStringLiteral("x"), QStringLiteral("--amplitude"), QStringLiteral("10"),
              QStringLiteral("--encoder-noise"), QStringLiteral("1")}));
    EXPECT_EQ(table.exit, 2);
    EXPECT_TRUE(table.err.contains(QStringLiteral("the rail's"))) << table.err.toStdString();
}

}  // namespace
