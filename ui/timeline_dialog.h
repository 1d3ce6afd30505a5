#pragma once
// History > Timeline (issue 31 item 7): the alarm timeline of past runs, read from the journal
// (off the screens' thread: it may be megabytes), as the strip the plots have and a list of its
// marks; a click on a mark selects its line in the list.
#include <QDialog>

#include "core/timeline/timeline.h"

class QLabel;
class QListWidget;

namespace trilho {
namespace ui {

class TimelineStrip;

class TimelineDialog : public QDialog {
    Q_OBJECT
  public:
    /// Reads the journal at journalPath (its rotated files too; the last 100,000 entries).
    explicit TimelineDialog(const QString& journalPath, QWidget* parent = nullptr);
    bool loaded() const { return loaded_; }
    const Timeline& timeline() const { return timeline_; }
    TimelineStrip* strip() const { return strip_; }
    QListWidget* list() const { return list_; }

  signals:
    void timelineLoaded();

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void showTimeline(Timeline timeline);
    void retranslate();
    Timeline timeline_;
    TimelineStrip* strip_;
    QListWidget* list_;
    QLabel* summary_;
    QString journal_;
    bool loaded_ = false;
};

}  // namespace ui
}  // namespace trilho
