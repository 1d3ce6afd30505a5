#include "ui/workbench/margin_view.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

MarginView::MarginView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("marginView"));
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("marginSummary"));
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    summary_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    trials_ = new QTableWidget(this);
    trials_->setObjectName(QStringLiteral("marginTrials"));
    trials_->setColumnCount(7);
    trials_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    trials_->verticalHeader()->hide();
    trials_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    trials_->horizontalHeader()->setStretchLastSection(true);
    auto* v = new QVBoxLayout(this);
    v->addWidget(summary_);
    v->addWidget(trials_, 1);
    retranslate();
}

void MarginView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

QString MarginView::limitText(const QString& what, double max, bool found, double configured,
                              double margin, const QString& unit) const {
    // The CLI's figures and decimals (app/cli/tune_margin_command.cpp), in the screens' words.
    return found ? tr("%1: no lost step up to %2 %3; the profile's %4 %3 has a margin of %5 "
                      "(%6 %)")
                       .arg(what)
                       .arg(max, 0, 'f', 0)
                       .arg(unit)
                       .arg(configured, 0, 'f', 0)
                       .arg(margin, 0, 'f', 2)
                       .arg((margin - 1.0) * 100.0, 0, 'f', 0)
                 : tr("%1: no lost step in the whole sweep (or as far as the travel lets a move "
                      "reach its speed), up to %2 %3 (margin at least %4)")
                       .arg(what)
                       .arg(max, 0, 'f', 0)
                       .arg(unit)
                       .arg(margin, 0, 'f', 2);
}

void MarginView::showResult(const MarginResult& r, char axis) {
    shown_ = std::make_pair(r, axis);
    if (!r.error.isEmpty()) {
        summary_->setText(tr("Margin test refused: %1").arg(r.error));
        trials_->setRowCount(0);
        return;
    }
    const std::size_t n = r.speedSweep.size() + r.accelerationSweep.size();
    summary_->setText(
        tr("Axis %1: %2 trials out and back, %3 s of machine time (simulation only: the board "
           "reports no step count; on the machine, check a pen mark at the start).")
            .arg(QChar::fromLatin1(axis).toUpper())
            .arg(n)
            .arg(r.machineTimeS, 0, 'f', 1) +
        QStringLiteral("\n") +
        limitText(tr("Speed at the profile's acceleration"), r.maxSpeedMmS, r.speedLimitFound,
                  r.configuredSpeedMmS, r.speedMargin, QStringLiteral("mm/s")) +
        QStringLiteral("\n") +
        limitText(tr("Acceleration at the profile's speed"), r.maxAccelerationMmS2,
                  r.accelerationLimitFound, r.configuredAccelerationMmS2, r.accelerationMargin,
                  QStringLiteral("mm/s²")));
    trials_->setRowCount(static_cast<int>(n));
    int row = 0;
    auto put = [&](const std::vector<MarginTrial>& sweep, const QString& name) {
        for (const MarginTrial& t : sweep) {
            const QStringList cells{name,
                                    QString::number(t.speedMmS, 'f', 1),
                                    QString::number(t.accelerationMmS2, 'f', 0),
                                    QString::number(t.moveMm, 'f', 1),
                                    QString::number(t.lostSteps),
                                    QString::number(t.returnErrorSteps),
                                    t.ok() ? tr("no loss") : tr("lost steps")};
            for (int c = 0; c < cells.size(); ++c) {
                auto* item = new QTableWidgetItem(cells[c]);
                if (c > 0 && c < 6) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                if (!t.ok()) item->setForeground(QColor(0xb0, 0x00, 0x20));
                trials_->setItem(row, c, item);
            }
            ++row;
        }
    };
    put(r.speedSweep, tr("speed"));
    put(r.accelerationSweep, tr("acceleration"));
}

void MarginView::retranslate() {
    trials_->setHorizontalHeaderLabels({tr("Sweep"), tr("Speed (mm/s)"), tr("Acceleration (mm/s²)"),
                                        tr("Move (mm)"), tr("Lost steps"),
                                        tr("Return error (steps)"), tr("Result")});
    if (shown_)
        showResult(shown_->first, shown_->second);
    else
        summary_->setText(
            tr("The plotter has no encoder: its test is the margin of its speed and "
               "acceleration against lost steps. Choose the axis and press Run margin test."));
}

}  // namespace ui
}  // namespace trilho
