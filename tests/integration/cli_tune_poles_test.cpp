// Issue 33 item 6: `trilho-cli tune poles`: the keys the issue names, the model it works from
// (the one `tune identify` prints), and agreement with the simulation: gains whose poles leave
// the unit circle make `tune step` alarm or chatter on the drive's clamp, gains inside it settle.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>
#include <complex>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;

QJsonObject jsonOf(const CliResult& r) {
    QJsonParseError e{};
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8(), &e);
    EXPECT_EQ(e.error, QJsonParseError::NoError) << r.out.toStdString() << r.err.toStdString();
    return d.object();
}

QJsonObject poles(QStringList more) {
    QStringList args{QStringLiteral("tune"), QStringLiteral("poles"), QStringLiteral("--machine"),
                     QStringLiteral("rail"), QStringLiteral("--json")};
    args += more;
    const CliResult r = runCli(args);
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    return jsonOf(r);
}

struct Step {
    int exit = 0;
    QJsonObject json;
};
Step step(QStringList more) {
    QStringList args{QStringLiteral("tune"),        QStringLiteral("step"),
                     QStringLiteral("--machine"),   QStringLiteral("rail"),
                     QStringLiteral("--amplitude"), QStringLiteral("10"),
                     QStringLiteral("--json")};
    args += more;
    const CliResult r = runCli(args);
    return {r.exit, jsonOf(r)};
}

TEST(CliTunePoles, JsonHasThePolesOfTheIdentifiedModel) {
    const QJsonObject o = poles({});
    const QJsonArray p = o[QStringLiteral("closed_loop_poles_z")].toArray();
    ASSERT_EQ(p.size(), 4);  // plant 2, integral 1, velocity filter 1
    EXPECT_DOUBLE_EQ(o[QStringLiteral("sample_period_s")].toDouble(), 0.001);
    EXPECT_EQ(o[QStringLiteral("law")].toString(), QStringLiteral("engineered"));
    EXPECT_DOUBLE_EQ(o[QStringLiteral("kp")].toDouble(), 1.2);
    // The model is `tune identify`'s, the same seed and start.
    const CliResult id =
        runCli({QStringLiteral("tune"), QStringLiteral("identify"), QStringLiteral("--machine"),
                QStringLiteral("rail"), QStringLiteral("--json")});
    const QJsonObject m = jsonOf(id);
    EXPECT_DOUBLE_EQ(o[QStringLiteral("speed_gain_mm_s_per_code")].toDouble(),
                     m[QStringLiteral("speed_gain_mm_s_per_code")].toDouble());
    EXPECT_DOUBLE_EQ(o[QStringLiteral("time_constant_s")].toDouble(),
                     m[QStringLiteral("time_constant_s")].toDouble());
    // The poles are the characteristic polynomial's roots: their product is its last
    // coefficient (n even), their sum minus its second.
    const QJsonArray ch = o[QStringLiteral("characteristic_polynomial")].toArray();
    ASSERT_EQ(ch.size(), 5);
    std::complex<double> product = 1.0, sum = 0.0;
    double largest = 0.0;
    for (const QJsonValue& v : p) {
        const std::complex<double> z(v[QStringLiteral("re")].toDouble(),
                                     v[QStringLiteral("im")].toDouble());
        product *= z;
        sum += z;
        largest = std::max(largest, std::abs(z));
    }
    EXPECT_NEAR(product.real(), ch[4].toDouble(), 1e-12);
    EXPECT_NEAR(sum.real(), -ch[1].toDouble(), 1e-12);
    EXPECT_DOUBLE_EQ(o[QStringLiteral("largest_pole_magnitude")].toDouble(), largest);
    EXPECT_LT(largest, 1.0);
    EXPECT_TRUE(o[QStringLiteral("stable")].toBool());
    // The dominant pole is real (SIMC's derivative cancels the lag): damping 1, and wn the
    // rate of its decay, s = ln z / T.
    const double zd = o[QStringLiteral("dominant_pole_z")][QStringLiteral("re")].toDouble();
    EXPECT_DOUBLE_EQ(o[QStringLiteral("dominant_damping")].toDouble(), 1.0);
    EXPECT_NEAR(o[QStringLiteral("dominant_natural_frequency_rad_s")].toDouble(),
                -std::log(zd) / 0.001, 1e-9);
    EXPECT_GT(o[QStringLiteral("dominant_natural_frequency_rad_s")].toDouble(), 5.0);
    // The loop leaves the circle between Kp 130 and 160 (the agreement test's two).
    const double limit = o[QStringLiteral("kp_stability_limit")].toDouble();
    EXPECT_GT(limit, 130.0);
    EXPECT_LT(limit, 160.0);
}

TEST(CliTunePoles, TheClassicLawAtItsOwnPeriod) {
    const QJsonObject o = poles({QStringLiteral("--law"), QStringLiteral("classic")});
    EXPECT_DOUBLE_EQ(o[QStringLiteral("sample_period_s")].toDouble(), 0.01);
    EXPECT_DOUBLE_EQ(o[QStringLiteral("kp")].toDouble(), 0.2);
    EXPECT_EQ(o[QStringLiteral("closed_loop_poles_z")].toArray().size(), 4);
    EXPECT_TRUE(o[QStringLiteral("stable")].toBool());
    // At 1 ms the same per-tick gains: a tenth of the time between ticks, ten times the D.
    const QJsonObject fast = poles({QStringLiteral("--law"), QStringLiteral("classic"),
                                    QStringLiteral("--period"), QStringLiteral("0.001")});
    EXPECT_DOUBLE_EQ(fast[QStringLiteral("sample_period_s")].toDouble(), 0.001);
    EXPECT_NE(fast[QStringLiteral("largest_pole_magnitude")].toDouble(),
              o[QStringLiteral("largest_pole_magnitude")].toDouble());
    // --locus: every point of the sweep, Kp / 100 to x 1000, each with its four poles.
    const QJsonObject l =
        poles({QStringLiteral("--law"), QStringLiteral("classic"), QStringLiteral("--locus")});
    const QJsonArray locus = l[QStringLiteral("root_locus")].toArray();
    ASSERT_EQ(locus.size(), 200);
    EXPECT_NEAR(locus.first()[QStringLiteral("kp")].toDouble(), 0.002, 1e-15);
    EXPECT_NEAR(locus.last()[QStringLiteral("kp")].toDouble(), 200.0, 1e-9);
    for (const QJsonValue& pt : locus)
        EXPECT_EQ(pt[QStringLiteral("poles_z")].toArray().size(), 4);
    EXPECT_FALSE(o.contains(QStringLiteral("root_locus")));  // only when asked
}

TEST(CliTunePoles, BadInputIsAUsageErrorThatSaysWhich) {
    const struct {
        QStringList args;
        const char* says;
    } cases[] = {
        {{QStringLiteral("--law"), QStringLiteral("fuzzy")}, "--law"},
        {{QStringLiteral("--period"), QStringLiteral("0.5")}, "--period"},
        {{QStringLiteral("--period"), QStringLiteral("nan")}, "--period"},
        {{QStringLiteral("--kp"), QStringLiteral("abc")}, "--kp"},
        {{QStringLiteral("--axis"), QStringLiteral("y")}, "--axis"},
        {{QStringLiteral("extra")}, "extra"},
    };
    for (const auto& c : cases) {
        QStringList args{QStringLiteral("tune"), QStringLiteral("poles"),
                         QStringLiteral("--machine"), QStringLiteral("rail")};
        args += c.args;
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exit, 2) << c.says;
        EXPECT_TRUE(r.err.contains(QString::fromLatin1(c.says))) << r.err.toStdString();
    }
    const CliResult table = runCli({QStringLiteral("tune"), QStringLiteral("poles"),
                                    QStringLiteral("--machine"), QStringLiteral("xy_dc_table")});
    EXPECT_EQ(table.exit, 2);
    EXPECT_TRUE(table.err.contains(QStringLiteral("--axis"))) << table.err.toStdString();
    const CliResult plotter = runCli({QStringLiteral("tune"), QStringLiteral("poles"),
                                      QStringLiteral("--machine"), QStringLiteral("xy_plotter")});
    EXPECT_EQ(plotter.exit, 2);
    EXPECT_TRUE(plotter.err.contains(QStringLiteral("tune margin"))) << plotter.err.toStdString();
    for (const char* wrong : {"--kd", "--b0"}) {
        const CliResult r =
            runCli({QStringLiteral("tune"), QStringLiteral("poles"), QStringLiteral("--machine"),
                    QStringLiteral("xy_dc_table"), QStringLiteral("--axis"), QStringLiteral("x"),
                    QString::fromLatin1(wrong), QStringLiteral("1")});
        EXPECT_EQ(r.exit, 2) << wrong;
        EXPECT_TRUE(r.err.contains(QString::fromLatin1(wrong))) << r.err.toStdString();
    }
}

// A DC table axis: its PI at 5 ms on the model `tune identify --axis x` finds; gains past the
// locus's limit trip the over-current comparator in `tune step`, gains inside it settle.
TEST(CliTunePoles, TheDcTableAxisAgreesWithItsStepTest) {
    auto table = [](QStringList more) {
        return QStringList{QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
                           QStringLiteral("--axis"), QStringLiteral("x")} +
               more;
    };
    auto run = [](const char* sub, QStringList args) {
        return runCli(QStringList{QStringLiteral("tune"), QString::fromLatin1(sub)} + args +
                      QStringList{QStringLiteral("--json")});
    };
    const CliResult id = run("identify", table({}));
    const CliResult p0 = run("poles", table({}));
    ASSERT_EQ(p0.exit, 0) << p0.err.toStdString();
    const QJsonObject o = jsonOf(p0);
    EXPECT_DOUBLE_EQ(o[QStringLiteral("speed_gain_mm_s_per_pct")].toDouble(),
                     jsonOf(id)[QStringLiteral("speed_gain_mm_s_per_pct")].toDouble());
    EXPECT_DOUBLE_EQ(o[QStringLiteral("sample_period_s")].toDouble(), 0.005);
    EXPECT_EQ(o[QStringLiteral("closed_loop_poles_z")].toArray().size(), 3);  // PI: no filter
    EXPECT_FALSE(o.contains(QStringLiteral("kd")));
    const double limit = o[QStringLiteral("kp_stability_limit")].toDouble();
    EXPECT_GT(limit, 80.0);
    EXPECT_LT(limit, 200.0);
    for (const char* kp : {"14", "80"}) {
        const CliResult p = run("poles", table({QStringLiteral("--kp"), QString::fromLatin1(kp)}));
        EXPECT_TRUE(jsonOf(p)[QStringLiteral("stable")].toBool()) << kp;
        const CliResult s = run("step", table({QStringLiteral("--amplitude"), QStringLiteral("10"),
                                               QStringLiteral("--kp"), QString::fromLatin1(kp)}));
        EXPECT_EQ(s.exit, 0) << kp << s.out.toStdString();
        EXPECT_TRUE(jsonOf(s)[QStringLiteral("ok")].toBool()) << kp;
    }
    const CliResult p = run("poles", table({QStringLiteral("--kp"), QStringLiteral("200")}));
    EXPECT_FALSE(jsonOf(p)[QStringLiteral("stable")].toBool());
    EXPECT_GT(jsonOf(p)[QStringLiteral("largest_pole_magnitude")].toDouble(), 1.05);
    const CliResult s = run("step", table({QStringLiteral("--amplitude"), QStringLiteral("10"),
                                           QStringLiteral("--kp"), QStringLiteral("200")}));
    EXPECT_EQ(s.exit, 3);
    EXPECT_TRUE(
        jsonOf(s)[QStringLiteral("abort_reason")].toString().contains(QStringLiteral("alarm 17")))
        << s.out.toStdString();
    // Seed 004's law on the signed error: b0 and b1 in the JSON, its three poles.
    const CliResult seed =
        run("poles", table({QStringLiteral("--law"), QStringLiteral("seed-signed")}));
    const QJsonObject so = jsonOf(seed);
    EXPECT_TRUE(so.contains(QStringLiteral("b0")));
    EXPECT_FALSE(so.contains(QStringLiteral("kp")));
    EXPECT_EQ(so[QStringLiteral("closed_loop_poles_z")].toArray().size(), 3);
}

TEST(CliTunePoles, AgreesWithTheStepTest) {
    auto gains = [](const char* kp, const char* ki) {
        return QStringList{QStringLiteral("--kp"), QString::fromLatin1(kp), QStringLiteral("--ki"),
                           QString::fromLatin1(ki)};
    };
    // Inside the circle: the tuned gains and Kp 130 settle, the drive off its clamp.
    for (const char* kp : {"1.2", "130"}) {
        const QJsonObject p = poles(gains(kp, "0.5"));
        EXPECT_TRUE(p[QStringLiteral("stable")].toBool()) << kp;
        const Step s = step(gains(kp, "0.5"));
        EXPECT_EQ(s.exit, 0) << kp;
        EXPECT_TRUE(s.json[QStringLiteral("ok")].toBool()) << kp;
        EXPECT_LT(s.json[QStringLiteral("saturated_time_s")].toDouble(), 0.05) << kp;
    }
    // Ki 300 takes the integral's pole out (|z| 1.008): the step never settles, an alarm.
    {
        const QJsonObject p = poles(gains("1.2", "300"));
        EXPECT_FALSE(p[QStringLiteral("stable")].toBool());
        EXPECT_GT(p[QStringLiteral("largest_pole_magnitude")].toDouble(), 1.0);
        const Step s = step(gains("1.2", "300"));
        EXPECT_EQ(s.exit, 3);
        EXPECT_TRUE(s.json[QStringLiteral("aborted")].toBool());
        EXPECT_TRUE(s.json[QStringLiteral("abort_reason")].toString().contains(
            QStringLiteral("never settled")))
            << s.json[QStringLiteral("abort_reason")].toString().toStdString();
    }
    // Kp 160 (|z| 1.004): the growing oscillation is bounded by the drive's clamp (the speed
    // the setpoint needs plus 30 mm/s, position_loop.h), so the platform stays within a count
    // while the drive chatters between its limits: saturated over half the test.
    {
        const QJsonObject p = poles(gains("160", "0.5"));
        EXPECT_FALSE(p[QStringLiteral("stable")].toBool());
        const Step s = step(gains("160", "0.5"));
        const double saturated = s.json[QStringLiteral("saturated_time_s")].toDouble();
        const double duration = s.json[QStringLiteral("duration_s")].toDouble();
        EXPECT_GT(saturated, 0.5 * (duration - 0.15)) << saturated << " of " << duration;
    }
}

}  // namespace
