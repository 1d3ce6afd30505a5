// Issue 33 item 8: the lab sheet's content and drawing (host/labsheet). Its rows are the
// metrics' own (stepMetricLines), a run without its sidecar says "not recorded", a run with no
// step beside a measured one keeps every metric row, the plot's ticks are round, and a run of a
// million ticks is drawn as its envelope with its one-tick peak kept.
#include <gtest/gtest.h>

#include <QGuiApplication>
#include <QImage>
#include <cstdlib>

#include "host/labsheet/lab_sheet.h"
#include "host/labsheet/lab_sheet_file.h"
#include "host/labsheet/lab_sheet_painter.h"
#include "host/labsheet/lab_sheet_plot.h"
#include "host/tuning/reports/metrics_report.h"

namespace trilho {
namespace {

/// A step of `amplitude` mm at 10 ms, first-order response (tau 50 ms), n ticks of dt.
std::shared_ptr<RunRecord> stepRecord(std::size_t n, double dt, double amplitude) {
    auto r = std::make_shared<RunRecord>();
    RunChannels& c = r->channels;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * dt;
        const double sp = t >= 0.01 ? amplitude : 0.0;
        const double pos = t >= 0.01 ? amplitude * (1.0 - std::exp(-(t - 0.01) / 0.05)) : 0.0;
        c.timeS.push_back(t);
        c.blockN.push_back(0);
        c.setpointMm.push_back(sp);
        c.positionMm.push_back(pos);
        c.errorMm.push_back(sp - pos);
        c.velocityMmS.push_back(0.0);
        c.drive.push_back(128.0);
    }
    return r;
}

LabSheetRun runOf(std::shared_ptr<RunRecord> r, int index) {
    LabSheetRun run;
    run.label = QStringLiteral("%1: synthetic").arg(index + 1);
    run.color = labSheetColor(index);
    run.metrics = measureRun(r->channels, 22.8);
    run.record = std::move(r);
    return run;
}

int pixelsNear(const QImage& image, QColor colour, int top, int height) {
    int n = 0;
    for (int y = top; y < top + height; ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) < 40 &&
                std::abs(c.green() - colour.green()) < 40 &&
                std::abs(c.blue() - colour.blue()) < 40)
                ++n;
        }
    return n;
}

TEST(LabSheet, TicksAreRound) {
    const std::vector<double> t = labSheetTicks(-0.01, 1.4, 8);
    ASSERT_EQ(t.size(), 8u);
    EXPECT_DOUBLE_EQ(t.front(), 0.0);
    EXPECT_NEAR(t[1], 0.2, 1e-12);
    EXPECT_NEAR(t.back(), 1.4, 1e-12);
    const std::vector<double> y = labSheetTicks(-265.0, 15.0, 7);
    ASSERT_FALSE(y.empty());
    EXPECT_DOUBLE_EQ(y.front(), -250.0);
    EXPECT_NEAR(y[1] - y[0], 50.0, 1e-9);
    EXPECT_TRUE(labSheetTicks(1.0, 1.0, 8).empty());  // no range: no ticks, no endless loop
    EXPECT_TRUE(labSheetTicks(0.0, std::nan(""), 8).empty());
}

// The teaching switches a run was made with are on its sheet (a run with anti-windup off is
// another experiment than the machine's): "as the machine" when none is switched.
TEST(LabSheet, TheTeachingSwitchesOfEachRunAreSaid) {
    LabSheet sheet;
    auto plain = stepRecord(1000, 0.001, 10.0);
    plain->hasConditions = true;
    auto switched = stepRecord(1000, 0.001, 10.0);
    switched->hasConditions = true;
    switched->conditions.antiWindup = false;
    switched->conditions.encoderNoiseCounts = 2;
    switched->conditions.dacQuantisation = false;
    sheet.runs.push_back(runOf(plain, 0));
    sheet.runs.push_back(runOf(switched, 1));
    bool found = false;
    for (const LabSheetRow& row : labSheetRows(sheet)) {
        if (row.name != QLatin1String("teaching switches")) continue;
        found = true;
        ASSERT_EQ(row.cells.size(), 2u);
        EXPECT_EQ(row.cells[0], QStringLiteral("as the machine"));
        EXPECT_EQ(row.cells[1], QStringLiteral("anti-windup off; encoder noise +-2 counts; DAC "
                                               "quantisation off"));
    }
    EXPECT_TRUE(found);
}

TEST(LabSheet, RowsAreTheMetricsOwnAndABareTraceSaysNotRecorded) {
    LabSheet sheet;
    sheet.runs.push_back(runOf(stepRecord(1000, 0.001, 10.0), 0));
    ASSERT_TRUE(sheet.runs[0].metrics.ok);
    const std::vector<LabSheetRow> rows = labSheetRows(sheet);
    const std::vector<StepMetricLine> lines = stepMetricLines(sheet.runs[0].metrics);
    ASSERT_EQ(lines.size(), 14u);
    std::size_t metric = 0;
    for (const LabSheetRow& row : rows) {
        ASSERT_EQ(row.cells.size(), 1u);
        if (!row.metric) {
            if (row.name != QLatin1String("record")) {
                EXPECT_EQ(row.cells[0], QStringLiteral("not recorded")) << row.name.toStdString();
            }
            continue;
        }
        ASSERT_LT(metric, lines.size());
        EXPECT_EQ(row.name, lines[metric].name);
        EXPECT_EQ(row.cells[0], lines[metric].value);
        ++metric;
    }
    EXPECT_EQ(metric, 14u);
    EXPECT_EQ(rows.back().cells[0], stepMetricLines(sheet.runs[0].metrics).back().value);
    EXPECT_EQ(labSheetMachines(sheet), QStringLiteral("not recorded"));
}

TEST(LabSheet, ARunWithNoStepFirstKeepsTheOthersMetricRows) {
    LabSheet sheet;
    sheet.runs.push_back(runOf(stepRecord(1000, 0.001, 0.0), 0));  // the setpoint never moves
    sheet.runs.push_back(runOf(stepRecord(1000, 0.001, 10.0), 1));
    ASSERT_FALSE(sheet.runs[0].metrics.ok);
    int metricRows = 0;
    for (const LabSheetRow& row : labSheetRows(sheet)) {
        if (!row.metric) continue;
        ++metricRows;
        EXPECT_EQ(row.cells[0], QStringLiteral("no step"));
        EXPECT_NE(row.cells[1], QStringLiteral("no step"));
    }
    EXPECT_EQ(metricRows, 14);
}

TEST(LabSheet, AMillionTicksAreDrawnWithTheirOneTickPeak) {
    // The same run twice, once with one tick 20 mm above the rest: the peak must show.
    auto plain = stepRecord(1'000'000, 0.0001, 10.0);
    auto spiked = stepRecord(1'000'000, 0.0001, 10.0);
    spiked->channels.positionMm[600'000] += 20.0;
    // Beside each, the same 30 mm run, so both sheets' axes are the same (0 to 30 mm).
    auto tall = stepRecord(1000, 0.001, 30.0);
    LabSheet a, b;
    a.runs.push_back(runOf(plain, 0));
    b.runs.push_back(runOf(spiked, 0));
    a.runs.push_back(runOf(tall, 1));
    b.runs.push_back(runOf(tall, 1));
    const QImage ia = labSheetImage(a), ib = labSheetImage(b);
    ASSERT_EQ(ia.size(), QSize(kLabSheetWidthPx, kLabSheetHeightPx));
    const QColor blue = labSheetColor(0);
    const int pa = pixelsNear(ia, blue, 190, 600), pb = pixelsNear(ib, blue, 190, 600);
    EXPECT_GT(pa, 2000);
    // The spike: a line up and down over half the plot's height (about 200 px), 3 px wide;
    // drawn one point a pixel column it is lost.
    EXPECT_GT(pb, pa + 300) << pa << " " << pb;
}

TEST(LabSheet, FormatsByExtension) {
    EXPECT_EQ(labSheetFormatFor(QStringLiteral("a.PDF")), LabSheetFormat::Pdf);
    EXPECT_EQ(labSheetFormatFor(QStringLiteral("/x/y.png")), LabSheetFormat::Png);
    EXPECT_FALSE(labSheetFormatFor(QStringLiteral("a.jpg")));
    EXPECT_FALSE(labSheetFormatFor(QStringLiteral("pdf")));
}

TEST(LabSheet, ThePdfIsOneA4Page) {
    LabSheet sheet;
    sheet.runs.push_back(runOf(stepRecord(1000, 0.001, 10.0), 0));
    const QByteArray pdf = labSheetPdf(sheet);
    ASSERT_TRUE(pdf.startsWith("%PDF-"));
    EXPECT_EQ(pdf.count("/Type /Page\n") + pdf.count("/Type /Page "), 1);
    EXPECT_TRUE(pdf.contains("/MediaBox [0 0 595")) << "not A4";
}

}  // namespace
}  // namespace trilho

int main(int argc, char** argv) {
    // Drawing text needs Qt GUI's application; no window is shown.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
