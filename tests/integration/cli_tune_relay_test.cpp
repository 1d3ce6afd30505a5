// Issue 21 item 6: `trilho-cli tune relay`, the relay experiment and its Ziegler-Nichols gains
// beside the model-based gains of `tune auto`, both run on the same 10 mm step.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;

QJsonObject json(const CliResult& r) {
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8());
    EXPECT_TRUE(d.isObject()) << r.out.toStdString() << r.err.toStdString();
    return d.object();
}

CliResult relay(const QStringList& args) {
    return runCli(QStringList{QStringLiteral("tune"), QStringLiteral("relay")} + args);
}

double at(const QJsonObject& o, const char* a, const char* b = nullptr, const char* c = nullptr) {
    QJsonValue v = o.value(QLatin1String(a));
    if (b) v = v.toObject().value(QLatin1String(b));
    if (c) v = v.toObject().value(QLatin1String(c));
    EXPECT_TRUE(v.isDouble()) << a << " " << (b ? b : "") << " " << (c ? c : "");
    return v.toDouble(std::nan(""));
}

TEST(CliTuneRelay, MeasuresKuAndTuAndDerivesZieglerNicholsFromThem) {
    const CliResult r =
        relay({QStringLiteral("--machine"), QStringLiteral("rail"), QStringLiteral("--json")});
    ASSERT_EQ(r.exit, 0) << r.out.toStdString() << r.err.toStdString();
    const QJsonObject o = json(r);
    EXPECT_TRUE(o.value(QStringLiteral("ok")).toBool());
    const QJsonObject rel = o.value(QStringLiteral("relay")).toObject();
    EXPECT_EQ(rel.value(QStringLiteral("relay_codes")).toInt(), 3);
    // Bounded: at most 3 s of machine time, back at its start within a count.
    EXPECT_LE(at(rel, "experiment_time_s"), 3.0);
    EXPECT_LE(at(rel, "return_error_counts"), 1.0);
    const double a = at(rel, "amplitude_mm");
    const double tu = at(rel, "ultimate_period_s");
    const double ku = at(rel, "ultimate_gain_code_per_mm");
    // A cycle of a few counts (one count is 0.0439 mm), well under the experiment's 100 mm,
    // several periods within its 2.1 s of relay.
    EXPECT_GT(a, 0.04);
    EXPECT_LT(a, 5.0);
    EXPECT_GT(tu, 0.005);
    EXPECT_LT(tu, 0.5);
    // Ku = 4 d / (pi a), d = 3 codes.
    EXPECT_NEAR(ku, 4.0 * 3.0 / (M_PI * a), 1e-9 * ku);
    // Classic Ziegler-Nichols PID: Kp = 0.6 Ku, Ti = Tu / 2, Td = Tu / 8.
    const QJsonObject zn = o.value(QStringLiteral("ziegler_nichols")).toObject();
    const double kp = at(zn, "gains", "kp_code_per_mm");
    EXPECT_NEAR(kp, 0.6 * ku, 1e-9 * kp);
    EXPECT_NEAR(at(zn, "gains", "ki_code_per_mm_s"), kp / (tu / 2.0), 1e-9 * kp / tu);
    EXPECT_NEAR(at(zn, "gains", "kd_code_per_mm_s"), kp * tu / 8.0, 1e-9 * kp * tu);
    EXPECT_TRUE(
        zn.value(QStringLiteral("step")).toObject().contains(QStringLiteral("overshoot_pct")));
    // Beside it, the model-based result is `tune auto`'s, the same numbers.
    const QJsonObject model = o.value(QStringLiteral("model_based")).toObject();
    ASSERT_TRUE(model.value(QStringLiteral("ok")).toBool()) << r.out.toStdString();
    const QJsonObject autoRun =
        json(runCli({QStringLiteral("tune"), QStringLiteral("auto"), QStringLiteral("--machine"),
                     QStringLiteral("rail"), QStringLiteral("--json")}));
    for (const char* k : {"kp_code_per_mm", "ki_code_per_mm_s", "kd_code_per_mm_s"})
        EXPECT_EQ(at(model, "gains", k), at(autoRun, "gains", k)) << k;
    // The model-based gains settle the step to a count with no overshoot beyond one count.
    const QJsonObject simcStep = model.value(QStringLiteral("step")).toObject();
    EXPECT_FALSE(simcStep.value(QStringLiteral("aborted")).toBool(true));
    EXPECT_TRUE(simcStep.value(QStringLiteral("settling_time_1count_s")).isDouble());
    EXPECT_LE(std::abs(at(simcStep, "steady_state_error_counts")), 1.0);
}

TEST(CliTuneRelay, IsDeterministicAndALargerReliefGivesALargerCycle) {
    const CliResult a =
        relay({QStringLiteral("--json"), QStringLiteral("--seed"), QStringLiteral("7")});
    const CliResult b =
        relay({QStringLiteral("--json"), QStringLiteral("--seed"), QStringLiteral("7")});
    ASSERT_EQ(a.exit, 0) << a.out.toStdString();
    EXPECT_EQ(a.out, b.out);
    const CliResult big =
        relay({QStringLiteral("--json"), QStringLiteral("--seed"), QStringLiteral("7"),
               QStringLiteral("--amplitude"), QStringLiteral("8")});
    ASSERT_EQ(big.exit, 0) << big.out.toStdString();
    const QJsonObject small = json(a), large = json(big);
    EXPECT_EQ(large.value(QStringLiteral("relay"))
                  .toObject()
                  .value(QStringLiteral("relay_codes"))
                  .toInt(),
              8);
    EXPECT_GT(at(large, "relay", "amplitude_mm"), at(small, "relay", "amplitude_mm"));
}

TEST(CliTuneRelay, TheTextPutsBothResultsSideBySide) {
    const CliResult r = relay({});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("ultimate gain Ku = 4 d / (pi a) = ")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Ziegler-Nichols (relay)")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("model-based (SIMC)")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("settling to 1 count, s")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("not the default tuning")));
}

TEST(CliTuneRelay, BadInputIsNamed) {
    struct Case {
        QStringList args;
        const char* says;
    };
    const Case cases[] = {
        {{QStringLiteral("--amplitude"), QStringLiteral("0")}, "--amplitude must be a number"},
        {{QStringLiteral("--amplitude"), QStringLiteral("21")}, "--amplitude must be a number"},
        {{QStringLiteral("--amplitude"), QStringLiteral("2.5")}, "a whole number of DAC codes"},
        {{QStringLiteral("--hysteresis"), QStringLiteral("x")}, "--hysteresis must be a number"},
        {{QStringLiteral("--mass-factor"), QStringLiteral("30")}, "--mass-factor must be"},
        {{QStringLiteral("--axis"), QStringLiteral("y")}, "the rail has only the x axis"},
        {{QStringLiteral("--axis"), QStringLiteral("z")}, "--axis must be x or y"},
        {{QStringLiteral("--machine"), QStringLiteral("xy_dc_table")}, "is not a rail"},
        {{QStringLiteral("--seed"), QStringLiteral("-1")}, "--seed must be"},
        {{QStringLiteral("extra")}, "unexpected argument 'extra'"},
    };
    for (const Case& c : cases) {
        const CliResult r = relay(c.args);
        EXPECT_EQ(r.exit, 2) << c.says;
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli tune relay: ")))
            << r.err.toStdString();
        EXPECT_TRUE(r.err.contains(QString::fromLatin1(c.says))) << r.err.toStdString();
        EXPECT_EQ(r.err.count(QLatin1Char('\n')), 1) << r.err.toStdString();
        EXPECT_TRUE(r.out.isEmpty());
    }
}

}  // namespace
