#include "ui/history_panel.h"

#include <QEvent>
#include <QFileDialog>
#include <QFontMetrics>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>

#include "core/journal/journal.h"
#include "ui/background_pool.h"
#include "ui/timeline_dialog.h"

namespace trilho {
namespace ui {

HistoryPanel::HistoryPanel(QWidget* parent) : QWidget(parent) {
    table_ = new QTableWidget(0, 4, this);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->hide();
    table_->setWordWrap(false);  // one line a row: a long text is read in its tooltip
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    ack_ = new QPushButton(this);
    export_ = new QPushButton(this);
    timeline_ = new QPushButton(this);
    timeline_->setObjectName(QStringLiteral("historyTimeline"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(ack_);
    buttons->addStretch();
    buttons->addWidget(timeline_);
    buttons->addWidget(export_);
    auto* v = new QVBoxLayout(this);
    v->addLayout(buttons);
    v->addWidget(table_);
    connect(ack_, &QPushButton::clicked, this, &HistoryPanel::acknowledgeRequested);
    connect(timeline_, &QPushButton::clicked, this, [this] { openTimeline(); });
    connect(export_, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Export history"), QString(),
                                                       QStringLiteral("CSV (*.csv)"));
        if (f.isEmpty()) return;
        // The journal may be megabytes over several rotated files: export off the GUI thread.
        export_->setEnabled(false);
        auto* watcher = new QFutureWatcher<QString>(this);
        connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher] {
            watcher->deleteLater();
            export_->setEnabled(true);
            if (!watcher->result().isEmpty())
                QMessageBox::warning(this, tr("Export history"), watcher->result());
            emit exported();
        });
        watcher->setFuture(QtConcurrent::run(backgroundPool(), [journal = journal_, f] {
            QString error;
            return Journal::exportJournalCsv(journal, f, &error) ? QString() : error;
        }));
    });
    retranslate();
}

TimelineDialog* HistoryPanel::openTimeline() {
    auto* d = new TimelineDialog(journal_, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
    return d;
}

QString HistoryPanel::kindText(const QString& kind) {
    if (kind == QLatin1String("alarm")) return tr("alarm");
    if (kind == QLatin1String("warning")) return tr("warning");
    if (kind == QLatin1String("ack")) return tr("acknowledged");
    if (kind == QLatin1String("status")) return tr("status");
    // The timeline's marks (core/timeline/timeline.h's journalKindOf).
    if (kind == QLatin1String("hold")) return tr("hold");
    if (kind == QLatin1String("resume")) return tr("resume");
    if (kind == QLatin1String("halt")) return tr("stopped");
    if (kind == QLatin1String("mode")) return tr("mode");
    if (kind == QLatin1String("run_start")) return tr("run start");
    if (kind == QLatin1String("run_end")) return tr("run end");
    if (kind == QLatin1String("override")) return tr("override");
    if (kind == QLatin1String("dnc_write")) return tr("DNC write");
    // The screens' marks (Journal::markStart and close).
    if (kind == QLatin1String("start")) return tr("start");
    if (kind == QLatin1String("stop")) return tr("stop");
    return kind;
}

void HistoryPanel::retranslate() {
    table_->setHorizontalHeaderLabels({tr("Time"), tr("Kind"), tr("Code"), tr("Text")});
    // Time and Kind wide enough for their longest text in this font and language (a fixed
    // width: measuring 10,000 rows at each line would cost the screens' thread); Text takes
    // the rest.
    const QFontMetrics fm = table_->fontMetrics();
    constexpr int kPad = 16;  // the cell's margins and the grid line
    table_->setColumnWidth(0,
                           std::max(fm.horizontalAdvance(QStringLiteral("8888-88-88 88:88:88.888")),
                                    fm.horizontalAdvance(tr("Time"))) +
                               kPad);
    int kindWidth = fm.horizontalAdvance(tr("Kind"));
    for (const char* kind : {"alarm", "warning", "ack", "status", "start", "stop", "hold", "resume",
                             "halt", "mode", "run_start", "run_end", "override", "dnc_write"})
        kindWidth = std::max(kindWidth, fm.horizontalAdvance(kindText(QLatin1String(kind))));
    table_->setColumnWidth(1, kindWidth + kPad);
    table_->setColumnWidth(
        2, std::max(fm.horizontalAdvance(QStringLiteral("88")), fm.horizontalAdvance(tr("Code"))) +
               kPad);
    for (int r = 0; r < table_->rowCount(); ++r)
        if (QTableWidgetItem* k = table_->item(r, 1))
            k->setText(kindText(k->data(Qt::UserRole).toString()));
    ack_->setText(tr("Acknowledge alarms"));
    export_->setText(tr("Export CSV"));
    timeline_->setText(tr("Timeline"));
    timeline_->setToolTip(
        tr("The alarms, warnings, holds, overrides, mode changes and DNC "
           "writes of the history on a time axis"));
}

void HistoryPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

void HistoryPanel::add(const QString& when, const QString& kind, int code, const QString& text) {
    const int row = table_->rowCount();
    table_->insertRow(row);
    table_->setItem(row, 0, new QTableWidgetItem(when));
    auto* k = new QTableWidgetItem(kindText(kind));
    k->setData(Qt::UserRole, kind);  // the journal's word; the cell shows it translated
    table_->setItem(row, 1, k);
    table_->setItem(row, 2, new QTableWidgetItem(code ? QString::number(code) : QString()));
    auto* t = new QTableWidgetItem(text);
    t->setToolTip(text);
    if (kind == QLatin1String("alarm")) t->setForeground(Qt::darkRed);
    if (kind == QLatin1String("warning")) t->setForeground(QColor(150, 90, 0));  // amber
    table_->setItem(row, 3, t);
    if (table_->rowCount() > 10000) table_->removeRow(0);  // the journal keeps everything
    table_->scrollToBottom();
}

bool HistoryPanel::exportCsv(const QString& path, QString* error) {
    return Journal::exportJournalCsv(journal_, path, error);  // streamed, every rotated file
}

}  // namespace ui
}  // namespace trilho
