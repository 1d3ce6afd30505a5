// Issue 21 items 1 and 8 on the XY machines: `trilho-cli tune identify|auto --machine
// xy_dc_table --axis x|y` and `tune margin --machine xy_plotter`, headless in virtual time:
// the keys with units, exit statuses, the written profile `run` takes, and the refusals.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;

QJsonObject jsonOf(const CliResult& r) {
    QJsonParseError e{};
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8(), &e);
    EXPECT_EQ(e.error, QJsonParseError::NoError) << r.out.toStdString();
    return d.object();
}

QStringList table(const char* sub, const char* axis, QStringList more = {}) {
    QStringList a{QStringLiteral("tune"),      QString::fromLatin1(sub),
                  QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
                  QStringLiteral("--axis"),    QString::fromLatin1(axis)};
    return a + more;
}

TEST(CliTuneDcTable, IdentifyFindsEachAxisMotor) {
    for (const char* axis : {"x", "y"}) {
        const CliResult r = runCli(table("identify", axis, {QStringLiteral("--json")}));
        ASSERT_EQ(r.exit, 0) << axis << r.err.toStdString();
        const QJsonObject o = jsonOf(r);
        EXPECT_TRUE(o[QStringLiteral("ok")].toBool());
        EXPECT_EQ(o[QStringLiteral("axis")].toString(), QString::fromLatin1(axis));
        // The profile's motor: 400 mm/s at 100 % PWM, 30 ms, 3 % friction (+-10 % by seed).
        EXPECT_NEAR(o[QStringLiteral("speed_gain_mm_s_per_pct")].toDouble(), 4.0, 0.12);
        EXPECT_NEAR(o[QStringLiteral("time_constant_s")].toDouble(), 0.030, 0.006);
        EXPECT_NEAR(o[QStringLiteral("coulomb_friction_pct")].toDouble(), 3.0, 0.35);
        EXPECT_GE(o[QStringLiteral("fit_velocity_pct")].toDouble(), 90.0);
        EXPECT_LE(o[QStringLiteral("experiment_time_s")].toDouble(), 3.0);
        EXPECT_LE(o[QStringLiteral("max_excursion_mm")].toDouble(), 100.0);
        EXPECT_EQ(o[QStringLiteral("return_error_counts")].toDouble(), 0.0);
    }
}

TEST(CliTuneDcTable, AutoWritesAProfileThatRunTakes) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("tuned.json"));
    const CliResult r = runCli(
        table("auto", "x", {QStringLiteral("--json"), QStringLiteral("--write-profile"), out}));
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = jsonOf(r);
    for (const char* key : {"gains", "predicted", "measured", "identification", "frequency",
                            "design", "machine_time_s"})
        EXPECT_TRUE(o.contains(QString::fromLatin1(key))) << key;
    const QJsonObject gains = o[QStringLiteral("gains")].toObject();
    // SIMC PI on 4 mm/s per %, tau 30 ms, 5 ms period: Kc = 1 / (K 2 theta_eff), theta_eff =
    // 7.5 + 15 ms: 5.56 %/mm; tau_I = 8 theta_eff = 0.18 s; kff = 1 / K.
    EXPECT_NEAR(gains[QStringLiteral("kp_pct_per_mm")].toDouble(), 5.56, 0.3);
    EXPECT_NEAR(gains[QStringLiteral("ki_pct_per_mm_s")].toDouble(), 30.9, 2.5);
    EXPECT_NEAR(gains[QStringLiteral("kff_pct_per_mm_s")].toDouble(), 0.25, 0.008);
    const QJsonObject step =
        o[QStringLiteral("measured")].toObject()[QStringLiteral("step")].toObject();
    for (const char* key : {"overshoot_pct", "settling_time_s", "settling_time_1count_s",
                            "rise_time_s", "steady_state_error_counts", "iae", "itae"})
        EXPECT_TRUE(step.contains(QString::fromLatin1(key))) << key;
    const CliResult check = runCli({QStringLiteral("profile"), out});
    EXPECT_EQ(check.exit, 0) << check.err.toStdString();
    const CliResult run = runCli(
        {QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--machine"), out,
         QStringLiteral(TRILHO_PROGRAMS_DIR) + QStringLiteral("/mesa_xy_quadrado.G")});
    EXPECT_EQ(run.exit, 0) << run.out.toStdString() << run.err.toStdString();
}

TEST(CliTuneDcTable, RefusalsAreUsageErrors) {
    const QStringList bad[] = {
        // The table has two axes: the one to tune must be named.
        {QStringLiteral("tune"), QStringLiteral("identify"), QStringLiteral("--machine"),
         QStringLiteral("xy_dc_table")},
        table("auto", "z"),
        {QStringLiteral("tune"), QStringLiteral("identify"), QStringLiteral("--machine"),
         QStringLiteral("xy_plotter")},
        {QStringLiteral("tune"), QStringLiteral("margin"), QStringLiteral("--machine"),
         QStringLiteral("xy_dc_table")},
        {QStringLiteral("tune"), QStringLiteral("margin"), QStringLiteral("--axis"),
         QStringLiteral("z")},
    };
    for (const QStringList& args : bad) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exit, 2) << args.join(QLatin1Char(' ')).toStdString();
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli tune")))
            << args.join(QLatin1Char(' ')).toStdString() << ": " << r.err.toStdString();
    }
}

TEST(CliTuneMargin, ReportsTheLimitsAndTheMargins) {
    const CliResult r =
        runCli({QStringLiteral("tune"), QStringLiteral("margin"), QStringLiteral("--machine"),
                QStringLiteral("xy_plotter"), QStringLiteral("--json")});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    const QJsonObject o = jsonOf(r);
    EXPECT_TRUE(o[QStringLiteral("simulation_only")].toBool());
    const double speed = o[QStringLiteral("max_speed_mm_s")].toDouble();
    const double accel = o[QStringLiteral("max_acceleration_mm_s2")].toDouble();
    EXPECT_NEAR(o[QStringLiteral("speed_margin")].toDouble(),
                speed / o[QStringLiteral("configured_speed_mm_s")].toDouble(), 1e-12);
    EXPECT_NEAR(o[QStringLiteral("acceleration_margin")].toDouble(),
                accel / o[QStringLiteral("configured_acceleration_mm_s2")].toDouble(), 1e-12);
    // The last trial of each sweep lost steps; every trial at or under the limit kept them.
    for (const char* sweep : {"speed_sweep", "acceleration_sweep"}) {
        const QJsonArray trials = o[QString::fromLatin1(sweep)].toArray();
        ASSERT_FALSE(trials.isEmpty()) << sweep;
        for (const QJsonValue& v : trials) {
            const QJsonObject t = v.toObject();
            const bool under = std::string(sweep) == "speed_sweep"
                                   ? t[QStringLiteral("speed_mm_s")].toDouble() <= speed
                                   : t[QStringLiteral("acceleration_mm_s2")].toDouble() <= accel;
            const bool ok = t[QStringLiteral("ok")].toBool();
            EXPECT_TRUE(!under || ok) << sweep;
            EXPECT_TRUE(ok || t[QStringLiteral("lost_steps")].toDouble() > 0 ||
                        t[QStringLiteral("return_error_steps")].toDouble() != 0)
                << sweep;
        }
    }
    const CliResult text = runCli({QStringLiteral("tune"), QStringLiteral("margin")});
    EXPECT_EQ(text.exit, 0);
    EXPECT_TRUE(text.out.contains(QStringLiteral("simulation only"))) << text.out.toStdString();
}

}  // namespace
