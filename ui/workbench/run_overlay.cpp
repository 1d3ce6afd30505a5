#include "ui/workbench/run_overlay.h"

#include "ui/workbench/run_plot.h"

#include "host/labsheet/lab_sheet.h"

#include <qcustomplot.h>
#include <QEvent>
#include <QHeaderView>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

namespace trilho {
namespace ui {

QColor workbenchColor(int index) {
    return labSheetColor(index);  // one palette: the lab sheet's curves are the overlay's
}

namespace {

// Each row: a label and a value in display units (ms for times: a servo's figures are tens of
// milliseconds). NaN is "not reached".
struct MetricRow {
    const char* label;
    double (*value)(const StepMetrics&);
    int decimals;
};

const MetricRow kRows[] = {
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Rise time 10-90 % (ms)"),
     [](const StepMetrics& m) { return m.riseTimeS * 1e3; }, 1},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Settling time 2 % (ms)"),
     [](const StepMetrics& m) { return m.settlingTimeS * 1e3; }, 1},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Settling time +-1 count (ms)"),
     [](const StepMetrics& m) { return m.settlingTime1CountS * 1e3; }, 1},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Overshoot (%)"),
     [](const StepMetrics& m) { return m.overshootPct; }, 2},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Peak (mm)"),
     [](const StepMetrics& m) { return m.peakMm; }, 3},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Peak time (ms)"),
     [](const StepMetrics& m) { return m.peakTimeS * 1e3; }, 1},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Steady-state error (counts)"),
     [](const StepMetrics& m) { return m.steadyStateErrorCounts; }, 2},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "IAE (mm.s)"),
     [](const StepMetrics& m) { return m.iae; }, 4},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "ITAE (mm.s2)"),
     [](const StepMetrics& m) { return m.itae; }, 5},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "ISE (mm2.s)"),
     [](const StepMetrics& m) { return m.ise; }, 5},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Following error max (mm)"),
     [](const StepMetrics& m) { return m.followingErrorMaxMm; }, 3},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Following error RMS (mm)"),
     [](const StepMetrics& m) { return m.followingErrorRmsMm; }, 3},
    {QT_TRANSLATE_NOOP("trilho::ui::RunOverlay", "Time saturated (ms)"),
     [](const StepMetrics& m) { return m.saturatedTimeS * 1e3; }, 1},
};
constexpr int kMetricRows = static_cast<int>(std::size(kRows));

}  // namespace

RunOverlay::RunOverlay(QWidget* parent) : QWidget(parent) {
    plot_ = new QCustomPlot(this);
    plot_->setObjectName(QStringLiteral("overlayPlot"));
    plot_->setMinimumHeight(150);
    plot_->legend->setVisible(true);
    plot_->legend->setFont(QFont(font().family(), 8));
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    table_ = new QTableWidget(this);
    table_->setObjectName(QStringLiteral("metricsTable"));
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectColumns);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setMinimumHeight(80);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(plot_);
    split->addWidget(table_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(split);
    connect(table_->horizontalHeader(), &QHeaderView::sectionClicked, this,
            &RunOverlay::runSelected);
    connect(table_, &QTableWidget::cellClicked, this,
            [this](int, int column) { emit runSelected(column); });
    rebuild();
}

QStringList RunOverlay::metricNames() {
    QStringList names;
    for (const MetricRow& r : kRows)
        names << tr(r.label);
    return names;
}

QString RunOverlay::metricText(const WorkbenchRun& run, int row) {
    if (row < 0 || row >= kMetricRows) return {};
    if (!run.metrics.ok) return tr("no step");
    const double v = kRows[row].value(run.metrics);
    if (!std::isfinite(v)) return tr("not reached");
    return QString::number(v, 'f', kRows[row].decimals);
}

void RunOverlay::setRuns(const std::vector<WorkbenchRunPtr>& runs, const std::vector<bool>& shown) {
    runs_ = runs;
    shown_ = shown;
    shown_.resize(runs_.size(), true);
    rebuild();
}

void RunOverlay::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) rebuild();
    QWidget::changeEvent(e);
}

void RunOverlay::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    if (std::exchange(stale_, false)) plot_->replot();
}

void RunOverlay::rebuild() {
    plot_->clearGraphs();
    plot_->xAxis->setLabel(tr("time from the step (s)"));
    plot_->yAxis->setLabel(tr("displacement (mm)"));
    double maxT = 0.1;
    for (std::size_t k = 0; k < runs_.size(); ++k) {
        const WorkbenchRunPtr& run = runs_[k];
        if (!shown_[k] || !run->plot) continue;
        const RunPlot& points = *run->plot;
        if (!points.response->isEmpty())
            maxT = std::max(maxT, (points.response->constEnd() - 1)->key);
        QCPGraph* g = plot_->addGraph();
        g->setName(run->name);
        g->setData(points.response);
        setRunPen(g, QPen(run->color, 1.6));
        QCPGraph* s = plot_->addGraph();
        s->setData(points.setpoint);
        setRunPen(s, QPen(run->color, 1, Qt::DashLine));
        s->removeFromLegend();
    }
    plot_->rescaleAxes();
    plot_->xAxis->setRange(std::min(-0.01, plot_->xAxis->range().lower), maxT);
    // The runs' alarm timelines (issue 31 item 7): a vertical line at each mark, on the run's
    // own time from its step; alarms red, warnings amber, the rest dotted in the run's colour.
    plot_->clearItems();
    for (std::size_t k = 0; k < runs_.size(); ++k) {
        const WorkbenchRunPtr& run = runs_[k];
        if (!shown_[k] || !run->plot) continue;
        std::size_t drawn = 0;
        for (const TimelineMark& m : run->events.marks()) {
            if (++drawn > kMaxOverlayMarks) break;  // a flood of warnings: the first ones
            auto* line = new QCPItemStraightLine(plot_);
            const double x = m.timeS - run->plot->timeOriginS;
            line->point1->setCoords(x, 0.0);
            line->point2->setCoords(x, 1.0);
            const QPen pen = m.kind == MarkKind::Alarm     ? QPen(QColor(200, 0, 0), 1.5)
                             : m.kind == MarkKind::Warning ? QPen(QColor(230, 150, 0), 1.5)
                                                           : QPen(run->color, 1, Qt::DotLine);
            line->setPen(pen);
        }
    }
    replotIfShown(this, plot_, stale_);

    table_->clear();
    table_->setRowCount(kMetricRows + 1);
    table_->setColumnCount(static_cast<int>(runs_.size()));
    QStringList rows = metricNames();
    rows << tr("Stopped");
    table_->setVerticalHeaderLabels(rows);
    for (std::size_t col = 0; col < runs_.size(); ++col) {
        const WorkbenchRun& run = *runs_[col];
        auto* header = new QTableWidgetItem(QString::number(col + 1));
        header->setForeground(run.color);
        header->setToolTip(run.name);
        table_->setHorizontalHeaderItem(static_cast<int>(col), header);
        for (int row = 0; row < kMetricRows; ++row)
            table_->setItem(row, static_cast<int>(col), new QTableWidgetItem(metricText(run, row)));
        table_->setItem(
            kMetricRows, static_cast<int>(col),
            new QTableWidgetItem(run.abortReason.isEmpty() ? tr("no") : run.abortReason));
    }
}

}  // namespace ui
}  // namespace trilho
