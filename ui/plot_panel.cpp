#include "ui/plot_panel.h"

#include <qcustomplot.h>
#include <QBuffer>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <cmath>

#include "core/files/atomic_file.h"
#include "ui/plot_legend.h"
#include "ui/timeline_strip.h"

namespace trilho {
namespace ui {

namespace {
QCustomPlot* makePlot(QWidget* parent) {
    auto* p = new QCustomPlot(parent);
    p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    p->axisRect()->setRangeZoom(Qt::Horizontal | Qt::Vertical);
    p->setMinimumHeight(150);
    p->setNotAntialiasedElements(QCP::aeAll);  // cheap redraws at 25 Hz
    placeLegendAbove(p);
    return p;
}
}  // namespace

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent) {
    position_ = makePlot(this);
    error_ = makePlot(this);
    setpointGraph_ = position_->addGraph();
    setpointGraph_->setPen(QPen(QColor(200, 0, 0), 1, Qt::DashLine));
    positionGraph_ = position_->addGraph();
    positionGraph_->setPen(QPen(QColor(0, 90, 200), 1.5));
    position_->legend->setVisible(true);
    errorGraph_ = error_->addGraph();
    errorGraph_->setPen(QPen(QColor(200, 0, 0)));
    error_->yAxis2->setVisible(true);
    error_->yAxis2->setRange(0, 255);
    driveGraph_ = error_->addGraph(error_->xAxis, error_->yAxis2);
    driveGraph_->setPen(QPen(QColor(0, 130, 0)));
    error_->legend->setVisible(true);
    error_->xAxis->setLabel(QStringLiteral("t (s)"));

    pause_ = new QPushButton(this);
    pause_->setCheckable(true);
    png_ = new QPushButton(this);
    csv_ = new QPushButton(this);
    window_ = new QSpinBox(this);
    window_->setRange(2, 600);
    window_->setValue(20);
    window_->setSuffix(QStringLiteral(" s"));
    // The timeline under both plots, on their time axis (the position plot's, which the error
    // plot shares), in one row with the plots' buttons: a row of its own made the dock 24 px
    // taller and the 1996 form scroll at 1024x768.
    strip_ = new TimelineStrip(this);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(strip_, 1);
    buttons->addWidget(pause_);
    buttons->addWidget(window_);
    buttons->addWidget(png_);
    buttons->addWidget(csv_);
    auto* v = new QVBoxLayout(this);
    // Side by side: on a 768-line screen the dock is about 200 px high, and two plots stacked
    // there were 60 px each, their tick labels overprinted.
    auto* plots = new QHBoxLayout;
    plots->addWidget(position_, 1);
    plots->addWidget(error_, 1);
    v->addLayout(plots, 1);
    v->addLayout(buttons);
    strip_->followAxisOf(position_);  // under the position plot's time axis, px for px
    connect(pause_, &QPushButton::toggled, this, &PlotPanel::setPaused);
    connect(png_, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Export PNG"), QString(),
                                                       QStringLiteral("PNG (*.png)"));
        QString error;
        if (!f.isEmpty() && !exportPng(f, &error))
            QMessageBox::warning(this, tr("Export PNG"), error);
    });
    connect(csv_, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Export CSV"), QString(),
                                                       QStringLiteral("CSV (*.csv)"));
        QString error;
        if (!f.isEmpty() && !exportCsv(f, &error))
            QMessageBox::warning(this, tr("Export CSV"), error);
    });
    retranslate();
}

void PlotPanel::retranslate() {
    pause_->setText(tr("Pause"));
    png_->setText(tr("Export PNG"));
    csv_->setText(tr("Export CSV"));
    window_->setToolTip(tr("Rolling window"));
    setpointGraph_->setName(tr("setpoint"));
    positionGraph_->setName(tr("position"));
    position_->yAxis->setLabel(tr("position (mm)"));
    // Short axis titles: a 150-px plot clipped "following error (mm)"; the legend names them.
    error_->yAxis->setLabel(tr("error (mm)"));
    error_->yAxis2->setLabel(tr("DAC"));
    errorGraph_->setName(tr("following error (mm)"));
    driveGraph_->setName(tr("drive (DAC code)"));
    replot();
}

void PlotPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

void PlotPanel::setPaused(bool paused) {
    paused_ = paused;
    if (pause_->isChecked() != paused) pause_->setChecked(paused);
    if (!paused) replot();  // back to the live end
}

void PlotPanel::showMoment(double timeS) {
    setPaused(true);
    const double w = window_->value();
    for (QCustomPlot* p : {position_, error_}) {
        p->xAxis->setRange(timeS - w / 2, timeS + w / 2);
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

int PlotPanel::sampleCount() const {
    return static_cast<int>(positionGraph_->data()->size());
}

void PlotPanel::addSample(const ControllerStatus& s) {
    if (s.timeS <= lastT_) return;
    lastT_ = s.timeS;
    const double t = s.timeS;
    setpointGraph_->addData(t, s.servo.setpointMm);
    positionGraph_->addData(t, s.servo.positionMm);
    errorGraph_->addData(t, s.servo.errorMm);
    driveGraph_->addData(t, s.servo.loop.code);
    // Keep 10 minutes at most: memory stays flat in a long run.
    const double keepFrom = t - 600.0;
    for (QCPGraph* g : {setpointGraph_, positionGraph_, errorGraph_, driveGraph_})
        g->data()->removeBefore(keepFrom);
    // Moving, the plots scroll at the sample rate (25 Hz); at rest, flat lines scroll at 5 Hz:
    // two plots side by side are more pixels, and an idle screen must stay cheap.
    const bool active = s.servo.mode == ServoMode::Move || std::abs(s.servo.velocityMmS) > 0.5 ||
                        std::abs(s.servo.errorMm) > 0.05;
    if (!paused_ && (active || ++restFrames_ % 5 == 0)) replot();
}

void PlotPanel::replot() {
    if (lastT_ < 0) return;
    const double w = window_->value();
    for (QCustomPlot* p : {position_, error_}) {
        p->xAxis->setRange(lastT_ - w, lastT_);
        {
            bool found = false;
            QCPRange r =
                p->graph(0)->getValueRange(found, QCP::sdBoth, QCPRange(lastT_ - w, lastT_));
            if (p == position_) {
                bool f2 = false;
                r.expand(p->graph(1)->getValueRange(f2, QCP::sdBoth, QCPRange(lastT_ - w, lastT_)));
                found |= f2;
            }
            if (found)
                p->yAxis->setRange(r.lower - 0.05 * r.size() - 0.01,
                                   r.upper + 0.05 * r.size() + 0.01);
        }
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

bool PlotPanel::exportPng(const QString& path, QString* error) {
    // Both plots, as on screen (side by side): the position alone hid the error and the drive.
    const QPixmap left = position_->toPixmap();
    const QPixmap right = error_->toPixmap();
    QImage image(left.width() + right.width(), std::max(left.height(), right.height()),
                 QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.drawPixmap(0, 0, left);
    painter.drawPixmap(left.width(), 0, right);
    painter.end();
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        if (error) *error = tr("cannot write '%1': the image could not be encoded").arg(path);
        return false;
    }
    return saveFileAtomically(path, png, error);
}

bool PlotPanel::exportCsv(const QString& path, QString* error) {
    QByteArray out = "t_s,setpoint_mm,position_mm,error_mm,drive\n";
    auto sp = setpointGraph_->data(), pos = positionGraph_->data(), err = errorGraph_->data(),
         drv = driveGraph_->data();
    for (int i = 0; i < pos->size(); ++i) {
        out += QByteArray::number(pos->at(i)->key, 'f', 4) + ',' +
               QByteArray::number(sp->at(i)->value, 'f', 4) + ',' +
               QByteArray::number(pos->at(i)->value, 'f', 4) + ',' +
               QByteArray::number(err->at(i)->value, 'f', 4) + ',' +
               QByteArray::number(drv->at(i)->value, 'f', 0) + '\n';
    }
    return saveFileAtomically(path, out, error);
}

}  // namespace ui
}  // namespace trilho
