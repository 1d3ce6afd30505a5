// trilho-cli check, the pre-run check (issue 31 item 8): its cycle time against the run of the
// same program in virtual time on each machine, a program that leaves the soft limits, an
// alarm met, the worst following error's line, programs that never end, and bad inputs.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::CliResult;
using trilho::test::runCli;

QString program(const char* name) {
    return QStringLiteral(TRILHO_PROGRAMS_DIR "/") + QString::fromLatin1(name);
}

QJsonObject json(const CliResult& r) {
    QJsonParseError e{};
    const QJsonDocument d = QJsonDocument::fromJson(r.out.toUtf8(), &e);
    EXPECT_EQ(e.error, QJsonParseError::NoError) << r.out.toStdString() << r.err.toStdString();
    return d.object();
}

class CliCheck : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& content) {
        return trilho::test::writeIn(dir, name, content);
    }
    /// `check --json` of file with extra options.
    static QJsonObject check(const QStringList& options, const QString& file, int expectExit) {
        const CliResult r = runCli(QStringList{QStringLiteral("check"), QStringLiteral("--json")} +
                                   options + QStringList{file});
        EXPECT_EQ(r.exit, expectExit) << r.out.toStdString() << r.err.toStdString();
        return json(r);
    }
    /// `run --virtual-time --json --continue-after 0` (the check continues an m00 at once).
    static QJsonObject run(const QStringList& options, const QString& file) {
        const CliResult r =
            runCli(QStringList{QStringLiteral("run"), QStringLiteral("--virtual-time"),
                               QStringLiteral("--json"), QStringLiteral("--continue-after"),
                               QStringLiteral("0")} +
                   options + QStringList{file});
        return json(r);
    }
};

TEST_F(CliCheck, TheCycleTimeAgreesWithTheVirtualRunWithinOnePercentOnEachMachine) {
    // A rail under the 1996 law at its 10 ms (a step setpoint, no plan): another loop, another
    // period.
    const QString classicRail =
        write(QStringLiteral("classic.json"),
              R"({"kind": "rail", "loop": {"law": "classic", "samplePeriodS": 0.01}})");
    struct Case {
        QStringList options;
        QString file;
    };
    const Case cases[] = {
        {{}, program("ciclo_carga.G")},  // dwells, an m00, g92, incremental moves
        {{QStringLiteral("--mass-factor"), QStringLiteral("3")}, program("ciclo_carga.G")},
        {{}, program("passo_incremental.G")},
        {{QStringLiteral("--machine"), classicRail}, program("exemplo_documento.G")},
        {{QStringLiteral("--machine"), QStringLiteral("xy_dc_table")},
         program("mesa_xy_quadrado.G")},
        {{QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
          QStringLiteral("--mass-factor"), QStringLiteral("3")},
         program("mesa_xy_exemplo_anexo7.G")},
        {{QStringLiteral("--machine"), QStringLiteral("xy_plotter")}, program("plotter_texto.G")},
        {{QStringLiteral("--machine"), QStringLiteral("xy_plotter")}, program("plotter_circulo.G")},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE((c.options.join(QLatin1Char(' ')) + QLatin1Char(' ') + c.file).toStdString());
        const QJsonObject checked = check(c.options, c.file, 0);
        const QJsonObject ran = run(c.options, c.file);
        ASSERT_TRUE(checked[QStringLiteral("ok")].toBool());
        ASSERT_TRUE(ran[QStringLiteral("ok")].toBool());
        const double cycle = checked[QStringLiteral("cycle_time_s")].toDouble();
        const double runCycle = ran[QStringLiteral("cycle_time_s")].toDouble();
        EXPECT_GT(runCycle, 0.5);
        EXPECT_NEAR(cycle, runCycle, 0.01 * runCycle);
        // And homing plus the cycle is the run's whole time, homing and all.
        const double whole = checked[QStringLiteral("homing_s")].toDouble() + cycle;
        const double runWhole = ran[QStringLiteral("duration_s")].toDouble();
        EXPECT_NEAR(whole, runWhole, 0.01 * runWhole);
        EXPECT_EQ(checked[QStringLiteral("ended_at_s")].toDouble(), runWhole);
    }
    // The payload is applied: three times the mass is a longer cycle on the rail.
    const double light =
        check({}, program("ciclo_carga.G"), 0)[QStringLiteral("cycle_time_s")].toDouble();
    const double heavy = check({QStringLiteral("--mass-factor"), QStringLiteral("3")},
                               program("ciclo_carga.G"), 0)[QStringLiteral("cycle_time_s")]
                             .toDouble();
    EXPECT_GT(heavy, light * 1.05);
}

TEST_F(CliCheck, AProgramThatLeavesTheSoftLimitsIsNotOkWithTheLine) {
    // The 1996 law under twice the payload: alarm 11 cuts the drive before the limit at 1270 mm
    // and the platform coasts past it (the servo's prediction is from the measured state).
    const QString classicRail =
        write(QStringLiteral("classic.json"),
              R"({"kind": "rail", "loop": {"law": "classic", "samplePeriodS": 0.01}})");
    const QString file =
        write(QStringLiteral("limits.G"), "G90\nG00 X1270 ; to the soft limit\nG00 X-1270\nM02\n");
    const QStringList heavy{QStringLiteral("--machine"), classicRail,
                            QStringLiteral("--mass-factor"), QStringLiteral("2")};
    const QJsonObject o = check(heavy, file, 3);
    EXPECT_FALSE(o[QStringLiteral("ok")].toBool());
    const QJsonArray outside = o[QStringLiteral("outside_soft_limits")].toArray();
    ASSERT_EQ(outside.size(), 1);
    EXPECT_EQ(outside[0].toObject()[QStringLiteral("axis")].toString(), QStringLiteral("x"));
    EXPECT_EQ(outside[0].toObject()[QStringLiteral("line")].toInt(), 2);
    const double beyond = outside[0].toObject()[QStringLiteral("beyond_mm")].toDouble();
    EXPECT_GT(beyond, 0.5);
    const double max =
        o[QStringLiteral("envelope_mm")][QStringLiteral("x")][QStringLiteral("max")].toDouble();
    EXPECT_NEAR(max, 1270.0 + beyond, 1e-3);
    EXPECT_TRUE(o[QStringLiteral("reason")].toString().contains(file + QStringLiteral(":2")))
        << o[QStringLiteral("reason")].toString().toStdString();
    EXPECT_TRUE(o[QStringLiteral("reason")].toString().contains(QStringLiteral("beyond its soft")));
    // Where the run says the platform came to rest is inside that envelope (the coast counted).
    const QJsonObject ran = run(heavy, file);
    EXPECT_LE(ran[QStringLiteral("plant_position_mm")].toDouble(), max + 0.05);
    EXPECT_GT(ran[QStringLiteral("plant_position_mm")].toDouble(), 1270.5);

    // The engineered law on the same program stays inside: ok, nothing outside.
    const QJsonObject inside = check({}, file, 0);
    EXPECT_TRUE(inside[QStringLiteral("ok")].toBool());
    EXPECT_TRUE(inside[QStringLiteral("outside_soft_limits")].toArray().isEmpty());
    EXPECT_LE(inside[QStringLiteral("envelope_mm")][QStringLiteral("x")][QStringLiteral("max")]
                  .toDouble(),
              1270.5);
}

TEST_F(CliCheck, AnAlarmMetIsReportedWithItsCodeAndLine) {
    // x6 on the rail: above x5.5 the platform cannot follow a rapid (following error, 3); x20
    // on the DC table the same. The move is on line 3 of each.
    const QString rail = write(QStringLiteral("heavy.G"), "G90\nG04 X1\nG00 X600\nG00 X0\nM02\n");
    const QString table =
        write(QStringLiteral("heavy_xy.G"), "G90\nG04 X0.5\nG01 X100 Y100 F100\nM02\n");
    struct Case {
        QStringList options;
        QString file;
    };
    const Case cases[] = {
        {{QStringLiteral("--mass-factor"), QStringLiteral("6")}, rail},
        {{QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
          QStringLiteral("--mass-factor"), QStringLiteral("20")},
         table},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file.toStdString());
        const QJsonObject o = check(c.options, c.file, 3);
        EXPECT_FALSE(o[QStringLiteral("ok")].toBool());
        EXPECT_EQ(o[QStringLiteral("end")].toString(), QStringLiteral("alarm"));
        const QJsonArray alarms = o[QStringLiteral("alarms")].toArray();
        ASSERT_EQ(alarms.size(), 1);
        const QJsonObject a = alarms[0].toObject();
        EXPECT_EQ(a[QStringLiteral("code")].toInt(), 3);
        EXPECT_EQ(a[QStringLiteral("line")].toInt(), 3);
        EXPECT_EQ(a[QStringLiteral("severity")].toString(), QStringLiteral("alarm"));
        EXPECT_FALSE(a[QStringLiteral("during_homing")].toBool());
        EXPECT_TRUE(a[QStringLiteral("text")].toString().startsWith(QStringLiteral("Following")));
        EXPECT_TRUE(o[QStringLiteral("reason")].toString().startsWith(
            QStringLiteral("alarm 3 at ") + c.file + QStringLiteral(":3: ")))
            << o[QStringLiteral("reason")].toString().toStdString();
        // The run of the same program meets the same alarm, at the same time.
        const QJsonObject ran = run(c.options, c.file);
        EXPECT_EQ(
            ran[QStringLiteral("alarms")].toArray()[0].toObject()[QStringLiteral("code")].toInt(),
            3);
        EXPECT_NEAR(o[QStringLiteral("cycle_time_s")].toDouble(),
                    ran[QStringLiteral("cycle_time_s")].toDouble(), 1e-9);
        // The error that tripped it is the worst, on that line.
        EXPECT_EQ(o[QStringLiteral("worst_following_error_line")].toInt(), 3);
    }
    // A homing the payload cannot do: the alarm is said as homing's, with no line.
    const QJsonObject homing =
        check({QStringLiteral("--mass-factor"), QStringLiteral("12")}, rail, 3);
    const QJsonObject a = homing[QStringLiteral("alarms")].toArray()[0].toObject();
    EXPECT_TRUE(a[QStringLiteral("during_homing")].toBool());
    EXPECT_TRUE(a[QStringLiteral("line")].isNull());
    EXPECT_TRUE(homing[QStringLiteral("cycle_time_s")].isNull());
    EXPECT_TRUE(homing[QStringLiteral("reason")].toString().contains(QStringLiteral("homing")));
}

TEST_F(CliCheck, TheWorstFollowingErrorIsOnTheFastMove) {
    // Slow feeds around one rapid: the rapid's line (4 on the rail, 3 on the table) is where
    // the platform lags most.
    const QString rail = write(QStringLiteral("fast.G"),
                               "G90\nG01 X-100 F5\nG01 X-200 F10\nG00 X1000\nG01 X900 F5\nM02\n");
    const QJsonObject r = check({}, rail, 0);
    EXPECT_EQ(r[QStringLiteral("worst_following_error_line")].toInt(), 4);
    EXPECT_GT(r[QStringLiteral("worst_following_error_mm")].toDouble(), 0.0);
    EXPECT_TRUE(r[QStringLiteral("summary")].toString().endsWith(QStringLiteral(" at line 4")))
        << r[QStringLiteral("summary")].toString().toStdString();
    const QString table = write(QStringLiteral("fast_xy.G"),
                                "G90\nG01 X10 Y10 F5\nG00 X250 Y250\nG01 X240 Y240 F5\nM02\n");
    const QJsonObject t =
        check({QStringLiteral("--machine"), QStringLiteral("xy_dc_table")}, table, 0);
    EXPECT_EQ(t[QStringLiteral("worst_following_error_line")].toInt(), 3);
    // The line moves with the rapid: put it last.
    const QString last = write(QStringLiteral("fast_last.G"),
                               "G90\nG01 X-100 F5\nG01 X-200 F10\nG01 X-190 F5\nG00 X1000\nM02\n");
    EXPECT_EQ(check({}, last, 0)[QStringLiteral("worst_following_error_line")].toInt(), 5);
}

TEST_F(CliCheck, AProgramThatNeverEndsEndsAtTheBoundWithTheReason) {
    // The endless shuttle at the default bound (3600 s of machine time, about 1 s here).
    const QJsonObject o = check({}, program("ciclo_continuo.G"), 4);
    EXPECT_FALSE(o[QStringLiteral("ok")].toBool());
    EXPECT_EQ(o[QStringLiteral("end")].toString(), QStringLiteral("time_limit"));
    EXPECT_EQ(o[QStringLiteral("bound_s")].toDouble(), 3600.0);
    EXPECT_GE(o[QStringLiteral("ended_at_s")].toDouble(), 3600.0 - 1e-6);
    EXPECT_LE(o[QStringLiteral("ended_at_s")].toDouble(), 3600.0 + 0.001 + 1e-6);
    EXPECT_TRUE(o[QStringLiteral("cycle_time_s")].isNull());
    EXPECT_TRUE(o[QStringLiteral("reason")].toString().startsWith(
        QStringLiteral("the program did not end within 3600 s")));
    // A dwell longer than the bound, a loop through an m00, on each machine, at --max-seconds.
    const QString dwell = write(QStringLiteral("dwell.G"), "G04 X99999\nM02\n");
    const QString m00 = write(QStringLiteral("m00.G"), "N10 M00\nN20 G04 X0.1\nN30 M03 X10\nM02\n");
    for (const char* machine : {"rail", "xy_dc_table", "xy_plotter"})
        for (const QString& f : {dwell, m00}) {
            SCOPED_TRACE(std::string(machine) + " " + f.toStdString());
            const QJsonObject b = check({QStringLiteral("--machine"), QLatin1String(machine),
                                         QStringLiteral("--max-seconds"), QStringLiteral("20")},
                                        f, 4);
            EXPECT_EQ(b[QStringLiteral("end")].toString(), QStringLiteral("time_limit"));
            EXPECT_GE(b[QStringLiteral("ended_at_s")].toDouble(), 20.0 - 1e-6);
            EXPECT_LE(b[QStringLiteral("ended_at_s")].toDouble(), 20.0 + 0.005 + 1e-6);
        }
    // A loop that neither moves nor waits is held by the controller at once (warning 15).
    const QJsonObject held =
        check({}, write(QStringLiteral("still.G"), "N10 G04 X0\nN20 M03 X10\nM02\n"), 3);
    EXPECT_EQ(held[QStringLiteral("end")].toString(), QStringLiteral("held"));
    const QJsonObject w = held[QStringLiteral("alarms")].toArray()[0].toObject();
    EXPECT_EQ(w[QStringLiteral("code")].toInt(), 15);
    EXPECT_EQ(w[QStringLiteral("line")].toInt(), 2);
    EXPECT_LT(held[QStringLiteral("ended_at_s")].toDouble(), 5.0);
}

TEST_F(CliCheck, ItsTextSaysTheSameInOneLineForTheCycleStartQuestion) {
    const CliResult r = runCli({QStringLiteral("check"), program("ciclo_carga.G")});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString();
    const QJsonObject o = check({}, program("ciclo_carga.G"), 0);
    const QStringList lines = r.out.split(QLatin1Char('\n'));
    ASSERT_GE(lines.size(), 2);
    EXPECT_TRUE(lines[0].endsWith(QStringLiteral(": ok"))) << lines[0].toStdString();
    EXPECT_EQ(lines[1], o[QStringLiteral("summary")].toString());
    EXPECT_EQ(lines[1],
              QStringLiteral("cycle %1 s, worst following error %2 mm at line %3")
                  .arg(o[QStringLiteral("cycle_time_s")].toDouble(), 0, 'f', 1)
                  .arg(o[QStringLiteral("worst_following_error_mm")].toDouble(), 0, 'f', 1)
                  .arg(o[QStringLiteral("worst_following_error_line")].toInt()));
    EXPECT_TRUE(r.out.contains(QStringLiteral("m00: 1 stop(s) continued at once")));
}

TEST_F(CliCheck, BadInputsAreRefusedNamingThePlace) {
    const QString ok = write(QStringLiteral("ok.G"), "G1 X10 F50\nM2\n");
    struct Case {
        QStringList args;
        int exit;
        QString said;  ///< in stderr (usage) or stdout (compile errors)
    };
    const Case cases[] = {
        {{dir.filePath(QStringLiteral("missing.G"))}, 2, QStringLiteral("missing.G")},
        {{dir.path()}, 2, QStringLiteral("it is a directory")},
        {{QStringLiteral("--mass-factor"), QStringLiteral("0"), ok},
         2,
         QStringLiteral("--mass-factor must be a number from 0.1 to 20 (got '0')")},
        {{QStringLiteral("--mass-factor"), QStringLiteral("-1"), ok}, 2, QStringLiteral("'-1'")},
        {{QStringLiteral("--mass-factor"), QStringLiteral("nan"), ok}, 2, QStringLiteral("'nan'")},
        {{QStringLiteral("--mass-factor"), QStringLiteral("1e300"), ok},
         2,
         QStringLiteral("'1e300'")},
        {{QStringLiteral("--machine"), QStringLiteral("xy_plotter"),
          QStringLiteral("--mass-factor"), QStringLiteral("2"), ok},
         2,
         QStringLiteral("no mass")},
        {{QStringLiteral("--max-seconds"), QStringLiteral("0"), ok},
         2,
         QStringLiteral("--max-seconds must be")},
        {{QStringLiteral("--max-seconds"), QStringLiteral("86401"), ok},
         2,
         QStringLiteral("from 0.001 to 86400 (got '86401')")},
        {{QStringLiteral("--machine"),
          write(QStringLiteral("bad.json"),
                "{\"kind\": \"rail\", "
                "\"loop\": {\"law\": 5}}"),
          ok},
         2,
         QStringLiteral("loop.law")},
        {{QStringLiteral("--machine"), QStringLiteral("no_such_machine"), ok},
         2,
         QStringLiteral("no_such_machine")},
        {{ok, ok}, 2, QStringLiteral("expected exactly one FILE")},
        {{write(QStringLiteral("err.G"), "G1 X10 F50\nG1 X5000\nM2\n")},
         1,
         QStringLiteral("err.G:2:4: error[soft-limit]")},
        {{QStringLiteral("--machine"), QStringLiteral("xy_dc_table"),
          write(QStringLiteral("beyond.G"), "G1 X10 Y400 F50\nM2\n")},
         1,
         QStringLiteral("beyond.G:1:")},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args.join(QLatin1Char(' ')).toStdString());
        const CliResult r = runCli(QStringList{QStringLiteral("check")} + c.args);
        EXPECT_EQ(r.exit, c.exit) << r.err.toStdString() << r.out.toStdString();
        const QString said = c.exit == 1 ? r.out : r.err;
        EXPECT_TRUE(said.contains(c.said)) << said.toStdString();
        if (c.exit == 2) {
            EXPECT_TRUE(r.err.startsWith(QStringLiteral("trilho-cli check: ")));
        }
    }
    // Compile errors in JSON: not ok, nothing checked, each diagnostic with its place.
    const QJsonObject o = check({}, write(QStringLiteral("err2.G"), "G1 X10 F50\nG77\nM2\n"), 1);
    EXPECT_FALSE(o[QStringLiteral("ok")].toBool());
    EXPECT_EQ(o[QStringLiteral("end")].toString(), QStringLiteral("compile_errors"));
    EXPECT_TRUE(o[QStringLiteral("cycle_time_s")].isNull());
    EXPECT_TRUE(o[QStringLiteral("diagnostics")].toArray()[0].toString().contains(
        QStringLiteral("err2.G:2:1")));
}

}  // namespace
