#pragma once
// The full alarm and status history with times, acknowledge, CSV export (from the journal).
#include <QWidget>

class QPushButton;
class QTableWidget;

namespace trilho {
namespace ui {

class TimelineDialog;

class HistoryPanel : public QWidget {
    Q_OBJECT
  public:
    explicit HistoryPanel(QWidget* parent = nullptr);
    void add(const QString& when, const QString& kind, int code, const QString& text);
    QTableWidget* table() const { return table_; }
    void setJournalPath(const QString& path) { journal_ = path; }
    bool exportCsv(const QString& path, QString* error = nullptr);
    /// The Kind column's text for the journal's word (alarm, ack, status) in the UI language.
    static QString kindText(const QString& kind);
    /// History > Timeline: the journal's marks in a dialog of their own (non-modal).
    TimelineDialog* openTimeline();

  signals:
    void acknowledgeRequested();
    void exported();  ///< an export from the button finished (its warning, if any, shown)

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QTableWidget* table_;
    QPushButton *ack_, *export_, *timeline_;
    QString journal_;
};

}  // namespace ui
}  // namespace trilho
