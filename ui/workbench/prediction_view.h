#pragma once
// The workbench's Prediction page (issue 33 item 9): the step the identified model predicts
// for the law, gains and period in the boxes (core/tuning/model_step_prediction.h, the Poles
// page's loop run in time), redrawn as a box or its slider changes, so dragging a gain's
// slider moves the response live, as MATLAB's PID Tuner does; in grey the response at the
// gains a drag started from. Linear like the poles (no clamp, no feed-forward): what the run
// adds to it is what the page does not model.
#include <QWidget>
#include <optional>

#include "core/tuning/model_step_prediction.h"

class QCustomPlot;
class QLabel;

namespace trilho {
namespace ui {

class PredictionView : public QWidget {
    Q_OBJECT
  public:
    explicit PredictionView(QWidget* parent = nullptr);
    /// The model (none: nothing to predict), the loop (spec.model is replaced by the model)
    /// and the step, mm. Recomputes and redraws.
    void setLoop(const std::optional<RailModel>& model, const DiscreteLoopSpec& spec,
                 double amplitudeMm);
    /// Seed 004's law as written: |e| with a fixed direction bit is not a linear loop, so
    /// there is nothing to predict (the Poles page says the same); the curves are cleared.
    void setSeedLawAsWritten();
    /// The response now becomes the grey reference (a slider was pressed).
    void keepReference();
    const ModelStepPrediction& prediction() const { return prediction_; }
    const ModelStepPrediction& reference() const { return reference_; }
    QLabel* summary() const { return summary_; }
    QCustomPlot* plot() const { return plot_; }

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void redraw();
    QString summaryText() const;
    QLabel* summary_;
    QCustomPlot* plot_;
    bool hasModel_ = false;
    bool seedLaw_ = false;  ///< setSeedLawAsWritten() until the next setLoop()
    DiscreteLoopSpec spec_;
    double amplitudeMm_ = 10.0;
    ModelStepPrediction prediction_;
    ModelStepPrediction reference_;
};

}  // namespace ui
}  // namespace trilho
