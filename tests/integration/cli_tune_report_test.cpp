// Issue 33 item 8: `trilho-cli tune report`, the lab sheet of saved runs. The sheet of lesson 1
// (the 1996 law at 10 ms and at 1 ms) is one A4 page, its PNG 1240 x 1754 px with each run's
// curve drawn in its colour, and its metrics are those `tune metrics` prints of each run, to the
// digit. A run that cannot be read is named and left out, the others' sheet still written; a
// full disk keeps the old sheet.
#include "tests/integration/cli_process.h"
#include "tests/support/full_disk.h"

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QRegularExpression>
#include <cstdlib>

namespace {

using trilho::test::CliResult;
using trilho::test::FullDisk;
using trilho::test::runCli;
using trilho::test::writeIn;

/// `tune step --trace` of the rail's classic law at period s, 100 mm (teaching.md lesson 1).
QString classicRun(const QTemporaryDir& dir, const QString& name, const QString& period) {
    const QString path = dir.filePath(name);
    const CliResult r =
        runCli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
                QStringLiteral("rail"), QStringLiteral("--law"), QStringLiteral("classic"),
                QStringLiteral("--period"), period, QStringLiteral("--amplitude"),
                QStringLiteral("100"), QStringLiteral("--trace"), path});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    return path;
}

/// The metric rows `tune metrics` prints of a trace (the lines after "TRACE: N ticks").
QStringList metricsLines(const QString& trace) {
    const CliResult r = runCli({QStringLiteral("tune"), QStringLiteral("metrics"), trace});
    EXPECT_EQ(r.exit, 0) << r.err.toStdString();
    QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    if (!lines.isEmpty()) lines.removeFirst();
    return lines;
}

/// The block `tune report` printed for run `n` ("run N: ..." up to the next run or the end).
QString runBlock(const QString& out, int n) {
    const qsizetype from = out.indexOf(QStringLiteral("run %1: ").arg(n));
    if (from < 0) return {};
    qsizetype to = out.indexOf(QStringLiteral("\nrun %1: ").arg(n + 1), from);
    if (to < 0) to = out.indexOf(QStringLiteral("\nlab sheet written"), from);
    return out.mid(from, to < 0 ? -1 : to - from + 1);  // with its last line's end
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// Pages of a PDF: its page objects ("/Type /Page", not "/Type /Pages").
int pdfPages(const QByteArray& pdf) {
    static const QRegularExpression page(QStringLiteral("/Type\\s*/Page(?![a-zA-Z])"));
    return static_cast<int>(QString::fromLatin1(pdf).count(page));
}

/// Pixels within 40 of colour on each channel (antialiased edges included).
int pixelsNear(const QImage& image, QColor colour) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) < 40 &&
                std::abs(c.green() - colour.green()) < 40 &&
                std::abs(c.blue() - colour.blue()) < 40)
                ++n;
        }
    return n;
}

TEST(CliTuneReport, LessonOneSheetIsOnePageWithTheMetricsOfTuneMetrics) {
    QTemporaryDir dir;
    const QString c10 = classicRun(dir, QStringLiteral("c10.csv"), QStringLiteral("0.01"));
    const QString c1 = classicRun(dir, QStringLiteral("c1.csv"), QStringLiteral("0.001"));
    const QString pdf = dir.filePath(QStringLiteral("sheet.pdf"));
    const QString png = dir.filePath(QStringLiteral("sheet.png"));
    const CliResult r = runCli({QStringLiteral("tune"), QStringLiteral("report"), c10, c1,
                                QStringLiteral("--pdf"), pdf, QStringLiteral("--png"), png});
    ASSERT_EQ(r.exit, 0) << r.out.toStdString() << r.err.toStdString();

    // The PDF: one A4 page (595 x 842 pt).
    const QByteArray pdfBytes = readAll(pdf);
    ASSERT_TRUE(pdfBytes.startsWith("%PDF-")) << pdfBytes.left(16).toStdString();
    EXPECT_EQ(pdfPages(pdfBytes), 1);
    EXPECT_TRUE(pdfBytes.contains("/MediaBox [0 0 595") || pdfBytes.contains("/MediaBox[0 0 595"))
        << "not A4";

    // The PNG: A4 at 150 dpi, each run's curve drawn in its colour (the workbench's first two).
    QImage image;
    ASSERT_TRUE(image.load(png));
    EXPECT_EQ(image.width(), 1240);
    EXPECT_EQ(image.height(), 1754);
    EXPECT_NEAR(image.dotsPerMeterX(), 5906, 1);
    // In the plot (its band of the page, above the table), thousands of pixels each: a 3 px
    // curve across most of the plot's width.
    const QImage plot = image.copy(0, 190, 1240, 600);
    EXPECT_GT(pixelsNear(plot, QColor(31, 119, 180)), 2000);
    EXPECT_GT(pixelsNear(plot, QColor(214, 39, 40)), 2000);

    // The text: each run's metric rows are `tune metrics`' own, and lesson 1's figures.
    const QString b1 = runBlock(r.out, 1), b2 = runBlock(r.out, 2);
    ASSERT_TRUE(b1.startsWith(QStringLiteral("run 1: c10.csv (classic, 10 ms)")))
        << r.out.toStdString();
    ASSERT_TRUE(b2.startsWith(QStringLiteral("run 2: c1.csv (classic, 1 ms)")))
        << r.out.toStdString();
    const QStringList m10 = metricsLines(c10), m1 = metricsLines(c1);
    ASSERT_EQ(m10.size(), 14);  // with the final error (last sample)
    for (const QString& line : m10)
        EXPECT_TRUE(b1.contains(line + QLatin1Char('\n'))) << line.toStdString();
    for (const QString& line : m1)
        EXPECT_TRUE(b2.contains(line + QLatin1Char('\n'))) << line.toStdString();
    EXPECT_TRUE(b1.contains(QStringLiteral("  rise time 10-90 %            0.5800 s\n")));
    EXPECT_TRUE(b2.contains(QStringLiteral("  overshoot                    3.860 %\n")));
    EXPECT_TRUE(b2.contains(QStringLiteral("  settling time (1 count)      not reached\n")));
    EXPECT_TRUE(b1.contains(QStringLiteral("  period                       10 ms\n")));
    EXPECT_TRUE(b2.contains(QStringLiteral("  period                       1 ms\n")));
    EXPECT_TRUE(
        b1.contains(QStringLiteral("  gains                        Kp 0.2, Ki 0.0005, Kd 1\n")));
    EXPECT_TRUE(b1.contains(QStringLiteral("  payload (mass factor)        x 1\n")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("lab sheet written: ") + pdf));
    EXPECT_TRUE(r.out.contains(QStringLiteral("lab sheet written: ") + png));
}

TEST(CliTuneReport, MissingAndGarbageRunsAreNamedAndTheOthersSheetWritten) {
    QTemporaryDir dir;
    const QString good = classicRun(dir, QStringLiteral("good.csv"), QStringLiteral("0.01"));
    const QString missing = dir.filePath(QStringLiteral("missing.csv"));
    const QString garbage =
        writeIn(dir, QStringLiteral("garbage.csv"), QByteArray("t_s,position_mm\n0,x\n"));
    const QString png = dir.filePath(QStringLiteral("sheet.png"));
    const CliResult r = runCli({QStringLiteral("tune"), QStringLiteral("report"), missing, good,
                                garbage, QStringLiteral("--png"), png});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("missing.csv"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(garbage + QStringLiteral(":"))) << r.err.toStdString();
    EXPECT_EQ(r.err.count(QStringLiteral("(left out of the sheet)")), 2) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("2 of 3 runs left out"))) << r.err.toStdString();
    // The good run is the sheet's only one, numbered 1.
    EXPECT_TRUE(r.out.contains(QStringLiteral("lab sheet of 1 run,"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("run 1: good.csv"))) << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("run 2:"))) << r.out.toStdString();
    QImage image;
    EXPECT_TRUE(image.load(png));
    EXPECT_EQ(image.size(), QSize(1240, 1754));
}

TEST(CliTuneReport, NoReadableRunWritesNothing) {
    QTemporaryDir dir;
    const QString garbage =
        writeIn(dir, QStringLiteral("garbage.csv"), QByteArray("\x01\x02\x03 binary\n", 12));
    const QString pdf = dir.filePath(QStringLiteral("sheet.pdf"));
    const CliResult r = runCli(
        {QStringLiteral("tune"), QStringLiteral("report"), garbage, QStringLiteral("--pdf"), pdf});
    EXPECT_EQ(r.exit, 2);
    EXPECT_TRUE(r.err.contains(garbage)) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing written"))) << r.err.toStdString();
    EXPECT_FALSE(QFileInfo::exists(pdf));
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("garbage.csv")});
}

TEST(CliTuneReport, UsageErrors) {
    QTemporaryDir dir;
    const QString run = classicRun(dir, QStringLiteral("c10.csv"), QStringLiteral("0.01"));
    const QString out = dir.filePath(QStringLiteral("same.png"));
    struct Case {
        QStringList args;
        const char* says;
    } cases[] = {
        {{run}, "expected --pdf OUT.pdf, --png OUT.png or both"},
        {{QStringLiteral("--png"), out}, "expected one or more RUN.csv"},
        {{run, QStringLiteral("--pdf"), out, QStringLiteral("--png"), out},
         "--pdf and --png name the same file"},
        {{run, run, run, run, run, run, run, run, run, QStringLiteral("--png"), out},
         "9 runs: at most 8 fit one sheet"},
    };
    for (const Case& c : cases) {
        const CliResult r =
            runCli(QStringList{QStringLiteral("tune"), QStringLiteral("report")} + c.args);
        EXPECT_EQ(r.exit, 2) << c.says;
        EXPECT_TRUE(r.err.contains(QLatin1String(c.says))) << r.err.toStdString();
        EXPECT_FALSE(QFileInfo::exists(out)) << c.says;
    }
}

TEST(CliTuneReport, AnAbortedRunIsMarkedOnTheSheetAndNoSuccess) {
    // teaching.md, saturation: the 1996 clamp at M = 0.3 pins the drive; the test stops itself.
    QTemporaryDir dir;
    const QString trace = dir.filePath(QStringLiteral("sat.csv"));
    const CliResult step =
        runCli({QStringLiteral("tune"), QStringLiteral("step"), QStringLiteral("--machine"),
                QStringLiteral("rail"), QStringLiteral("--amplitude"), QStringLiteral("1000"),
                QStringLiteral("--law"), QStringLiteral("classic"), QStringLiteral("--period"),
                QStringLiteral("0.01"), QStringLiteral("--speed-fraction"), QStringLiteral("0.3"),
                QStringLiteral("--trace"), trace});
    ASSERT_EQ(step.exit, 3) << step.out.toStdString();
    const QString png = dir.filePath(QStringLiteral("sheet.png"));
    const CliResult r = runCli(
        {QStringLiteral("tune"), QStringLiteral("report"), trace, QStringLiteral("--png"), png});
    EXPECT_EQ(r.exit, 3) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("  record                       ABORTED: saturated")))
        << r.out.toStdString();
    EXPECT_TRUE(QFileInfo::exists(png));
}

TEST(CliTuneReport, AFullDiskKeepsTheOldSheet) {
    QTemporaryDir dir;
    const QString run = classicRun(dir, QStringLiteral("c10.csv"), QStringLiteral("0.01"));
    TRILHO_FULL_DISK(disk);
    const QString pdf = disk.path(QStringLiteral("sheet.pdf"));
    const QByteArray good = "%PDF-1.4 the old sheet\n";
    {
        QFile f(pdf);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        ASSERT_EQ(f.write(good), good.size());
    }
    ASSERT_TRUE(disk.fill());
    const CliResult r = runCli(
        {QStringLiteral("tune"), QStringLiteral("report"), run, QStringLiteral("--pdf"), pdf});
    EXPECT_EQ(r.exit, 2) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("No space left on device"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(pdf)) << r.err.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("lab sheet written"))) << r.out.toStdString();
    EXPECT_EQ(FullDisk::read(pdf), good);
    EXPECT_EQ(disk.entries(), QStringList{QStringLiteral("sheet.pdf")});
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
