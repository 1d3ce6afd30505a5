// trilho-cli run and profile on the DC XY table (xy.md B): exit statuses, the XY trace and the
// JSON axes, in virtual time.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

#include "tests/integration/cli_process.h"

namespace {

using trilho::test::runCli;

const QString kTable = QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json");

class CliXy : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& content) {
        const QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(content);
        return path;
    }
    static QString program(const char* name) {
        return QStringLiteral(TRILHO_PROGRAMS_DIR "/") + QString::fromLatin1(name);
    }
};

TEST_F(CliXy, ProfileChecksAndPrintsTheTable) {
    const auto r = runCli({QStringLiteral("profile"), kTable});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("xy-dc-table"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("2.12"))) << r.out.toStdString();
}

TEST_F(CliXy, RunsAProgramWithTraceAndJsonAxes) {
    const QString trace = dir.filePath(QStringLiteral("t.csv"));
    const auto r =
        runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                QStringLiteral("--machine"), kTable, QStringLiteral("--trace"), trace,
                write(QStringLiteral("m.G"), "G00 X100 Y50\nG01 X70 Y130 F50\nM02\n")});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(o[QStringLiteral("ok")].toBool());
    const QJsonObject axes = o[QStringLiteral("axes_mm")].toObject();
    EXPECT_NEAR(axes[QStringLiteral("x")].toDouble(), 70.0, 0.11);
    EXPECT_NEAR(axes[QStringLiteral("y")].toDouble(), 130.0, 0.11);
    EXPECT_EQ(o[QStringLiteral("final_position_mm")].toDouble(),
              axes[QStringLiteral("x")].toDouble());
    EXPECT_EQ(o[QStringLiteral("history")].toArray().last().toString(),
              QStringLiteral("Program finished !"));

    QFile f(trace);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().split('\n');
    EXPECT_EQ(lines.front(), QByteArray("t_s,block_n,x_setpoint_mm,x_position_mm,y_setpoint_mm,"
                                        "y_position_mm,x_drive,y_drive,pen"));
    // Both setpoints reach the first block's end in the same row (the same 5 ms sample), and
    // the pen column is empty on the table.
    int endX = -1, endY = -1;
    double worstDrive = 0.0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> c = lines[i].split(',');
        if (c.size() != 9) continue;
        EXPECT_TRUE(c[8].isEmpty());
        if (endX < 0 && c[2].toDouble() == 100.0) endX = static_cast<int>(i);
        if (endY < 0 && c[4].toDouble() == 50.0) endY = static_cast<int>(i);
        worstDrive = std::max({worstDrive, std::abs(c[6].toDouble()), std::abs(c[7].toDouble())});
    }
    EXPECT_GT(endX, 1);
    EXPECT_EQ(endX, endY);
    EXPECT_LE(worstDrive, 50.0);  // seed 004: PWM clamped to 50 %
    EXPECT_GT(worstDrive, 20.0);
}

TEST_F(CliXy, ExampleProgramsRun) {
    for (const char* name : {"mesa_xy_quadrado.G", "mesa_xy_exemplo_anexo7.G"}) {
        const auto r =
            runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                    QStringLiteral("--json"), QStringLiteral("--machine"), kTable, program(name)});
        EXPECT_EQ(r.exit, 0) << name << r.out.toStdString() << r.err.toStdString();
        const QJsonObject axes =
            QJsonDocument::fromJson(r.out.toUtf8()).object()[QStringLiteral("axes_mm")].toObject();
        EXPECT_NEAR(axes[QStringLiteral("x")].toDouble(), 0.0, 0.11) << name;
        EXPECT_NEAR(axes[QStringLiteral("y")].toDouble(), 0.0, 0.11) << name;
    }
}

TEST_F(CliXy, TargetOutsideTheTableIsACompileError) {
    const auto r = runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"),
                           QStringLiteral("--machine"), kTable,
                           write(QStringLiteral("far.G"), "G00 X-30 Y80\nM02\n")});
    EXPECT_EQ(r.exit, 1);
}

TEST_F(CliXy, RailJsonHasItsAxisToo) {
    const auto r =
        runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                write(QStringLiteral("r.G"), "G00 X100\nM02\n")});
    ASSERT_EQ(r.exit, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const QJsonObject axes = o[QStringLiteral("axes_mm")].toObject();
    EXPECT_EQ(axes.keys(), QStringList{QStringLiteral("x")});
    EXPECT_EQ(axes[QStringLiteral("x")].toDouble(),
              o[QStringLiteral("final_position_mm")].toDouble());
}

TEST_F(CliXy, PlotterDrawsTheSeedsSquareWithThePenInTheTrace) {
    const QString trace = dir.filePath(QStringLiteral("p.csv"));
    const auto r =
        runCli({QStringLiteral("run"), QStringLiteral("--virtual-time"), QStringLiteral("--json"),
                QStringLiteral("--machine"), QStringLiteral(TRILHO_MACHINES_DIR "/xy_plotter.json"),
                QStringLiteral("--trace"), trace, program("plotter_quadrado.G")});
    ASSERT_EQ(r.exit, 0) << r.err.toStdString() << r.out.toStdString();
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const QJsonObject axes = o[QStringLiteral("axes_mm")].toObject();
    // Open loop: the head ends exactly on the last point's step, (366, 202) steps.
    EXPECT_NEAR(axes[QStringLiteral("x")].toDouble(), 36.6, 1e-9);
    EXPECT_NEAR(axes[QStringLiteral("y")].toDouble(), 20.2, 1e-9);
    QFile f(trace);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().split('\n');
    int down = 0, up = 0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> c = lines[i].split(',');
        if (c.size() != 9) continue;
        down += c[8] == "1" ? 1 : 0;
        up += c[8] == "0" ? 1 : 0;
        EXPECT_TRUE(c[8] == "1" || c[8] == "0") << c[8].toStdString();
    }
    EXPECT_GT(down, 100);  // the four sides, drawn
    EXPECT_GT(up, 10);     // the travel to the first corner
}

}  // namespace
