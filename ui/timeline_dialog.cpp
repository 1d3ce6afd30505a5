#include "ui/timeline_dialog.h"

#include <QDateTime>
#include <QEvent>
#include <QFutureWatcher>
#include <QLabel>
#include <QListWidget>
#include <QPointer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>

#include "core/journal/journal.h"
#include "ui/background_pool.h"
#include "ui/timeline_strip.h"

namespace trilho {
namespace ui {

TimelineDialog::TimelineDialog(const QString& journalPath, QWidget* parent)
    : QDialog(parent), journal_(journalPath) {
    setObjectName(QStringLiteral("timelineDialog"));
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    strip_ = new TimelineStrip(this);
    strip_->setTimeline(&timeline_);
    list_ = new QListWidget(this);
    auto* v = new QVBoxLayout(this);
    v->addWidget(summary_);
    v->addWidget(strip_);
    v->addWidget(list_, 1);
    resize(720, 420);
    connect(strip_, &TimelineStrip::markClicked, this, [this](const TimelineMark& m) {
        const auto& marks = timeline_.marks();
        const auto it = std::find(marks.begin(), marks.end(), m);
        if (it == marks.end()) return;
        const int row = static_cast<int>(it - marks.begin());
        list_->setCurrentRow(row);
        list_->scrollToItem(list_->item(row));
    });
    retranslate();
    auto* watcher = new QFutureWatcher<Timeline>(this);
    connect(watcher, &QFutureWatcher<Timeline>::finished, this, [this, watcher] {
        watcher->deleteLater();
        showTimeline(watcher->result());
    });
    watcher->setFuture(QtConcurrent::run(
        backgroundPool(), [path = journal_] { return timelineFromJournal(Journal::read(path)); }));
}

void TimelineDialog::showTimeline(Timeline timeline) {
    timeline_ = std::move(timeline);
    loaded_ = true;
    const double end = timeline_.empty() ? 0.0 : timeline_.marks().back().timeS;
    // The whole journal on the strip, a little room at each end.
    const double margin = std::max(1.0, end * 0.02);
    strip_->setTimeRange(-margin, end + margin);
    strip_->setTimeline(&timeline_);
    list_->clear();
    for (const TimelineMark& m : timeline_.marks()) {
        auto* item = new QListWidgetItem(TimelineStrip::describe(m), list_);
        item->setForeground(TimelineStrip::colourOf(m.kind));
    }
    retranslate();
    emit timelineLoaded();
}

void TimelineDialog::retranslate() {
    setWindowTitle(tr("History timeline"));
    if (!loaded_)
        summary_->setText(tr("Reading the history..."));
    else if (timeline_.empty())
        summary_->setText(
            tr("The history has no alarm, warning, hold, override, mode change or "
               "DNC write."));
    else
        summary_->setText(tr("Marks from the history: %1; times in seconds from its first "
                             "entry. Click a mark to find it in the list.")
                              .arg(timeline_.size()));
}

void TimelineDialog::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
