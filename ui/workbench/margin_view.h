#pragma once
// The workbench's page for the plotter (issue 21 item 1: "the plotter: a speed/acceleration
// margin test, it has no encoder"): what host/tuning/plotter_margin_sweep found, the numbers
// `trilho-cli tune margin` prints, as a summary (the highest speed and acceleration with no
// lost step, the profile's margin against each) and every trial of both sweeps, one row each.
#include <QWidget>
#include <optional>
#include <utility>

#include "host/tuning/plotter_margin_sweep.h"

class QLabel;
class QTableWidget;

namespace trilho {
namespace ui {

class MarginView : public QWidget {
    Q_OBJECT
  public:
    explicit MarginView(QWidget* parent = nullptr);
    void showResult(const MarginResult& result, char axis);
    QLabel* summary() const { return summary_; }
    QTableWidget* trials() const { return trials_; }

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QString limitText(const QString& what, double max, bool found, double configured, double margin,
                      const QString& unit) const;
    QLabel* summary_;
    QTableWidget* trials_;
    std::optional<std::pair<MarginResult, char>> shown_;  ///< re-said in a new language
};

}  // namespace ui
}  // namespace trilho
