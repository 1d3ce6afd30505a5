#pragma once
// The workbench's Poles page (issue 33 item 6): from the identified model and the gains, law
// and period in the boxes, the discrete closed loop in the z-plane (core/tuning/
// closed_loop_poles.h, the numbers `trilho-cli tune poles` prints): the unit circle, the poles
// (x) and zeros (o), the root locus as Kp sweeps (the boxes' Kp marked by the poles), and the
// dominant pair's damping and natural frequency. Worked out on this thread: 200 eigenvalue
// problems of order 4 take about a millisecond.
#include <QWidget>
#include <optional>

#include "core/tuning/closed_loop_poles.h"

class QCustomPlot;
class QLabel;

namespace trilho {
namespace ui {

class PolesView : public QWidget {
    Q_OBJECT
  public:
    explicit PolesView(QWidget* parent = nullptr);
    /// The model the poles are of (an identification's); none until one is accepted.
    void setModel(const RailModel& model);
    /// Forgets the model (another DC table axis was chosen): no poles until the next one.
    void clearModel();
    /// The law, gains and period of the boxes, the engineered law's velocity filter, and on a
    /// DC table axis its screw and seed gains (spec.model is ignored: the view's own).
    void setLoop(const DiscreteLoopSpec& spec);
    /// Seed 004's law as written (|e| with a fixed direction bit) has no poles: none are shown,
    /// the page says why, in the screen's language (the view makes the text, so a language
    /// change retranslates it). The next setLoop shows poles again.
    void setSeedLawAsWritten();
    bool hasModel() const { return model_.has_value(); }
    /// The model the poles are of, when one was accepted (the lab sheet prints it).
    const std::optional<RailModel>& model() const { return model_; }
    /// The poles shown (empty until there is a model).
    const ClosedLoopPoles& poles() const { return poles_; }
    const RootLocus& locus() const { return locus_; }
    QLabel* summary() const { return summary_; }
    QCustomPlot* plane() const { return plane_; }

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void recompute();
    void plot();
    QString summaryText() const;
    QLabel* summary_;
    QCustomPlot* plane_;
    std::optional<RailModel> model_;
    DiscreteLoopSpec spec_;
    ClosedLoopPoles poles_;
    RootLocus locus_;
    bool seedLawAsWritten_ = false;  ///< the law has no poles (seed 004's as written)
};

}  // namespace ui
}  // namespace trilho
