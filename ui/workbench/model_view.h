#pragma once
// The workbench's model page (issue 21 items 5-7): the identified model of the rail (or of a
// DC table axis) and its
// fit (MATLAB compare's NRMSE on held-out velocity), the loop designed from it, the prediction
// of the verification moves against what they measured, and the Bode plot of the identified
// open loop with its margins; beside the autotune, the relay (Ziegler-Nichols) experiment.
#include <QWidget>

#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/frequency_response.h"
#include "core/tuning/rail_autotune.h"
#include "core/tuning/rail_identification.h"
#include "host/tuning/relay_comparison.h"

class QCustomPlot;
class QLabel;

namespace trilho {
namespace ui {

class ModelView : public QWidget {
    Q_OBJECT
  public:
    explicit ModelView(QWidget* parent = nullptr);
    void showIdentification(const RailIdentification& id, const FrequencyView& frequency,
                            const LoopGains& gains);
    void showAutotune(const AutotuneResult& result);
    /// The relay experiment's Ku, Tu and Ziegler-Nichols gains beside the model-based gains,
    /// and what each did on the same 10 mm step.
    void showRelay(const RelayComparison& comparison);
    /// The DC table's axis: its model (PWM-driven motor, no speed loop), PI design.
    void showDcIdentification(const DcAxisIdentification& id, const FrequencyView& frequency,
                              const DcEngineeredGains& gains);
    void showDcAutotune(const DcAutotuneResult& result);
    void showMessage(const QString& text);
    QLabel* summary() const { return summary_; }
    QCustomPlot* bode() const { return bode_; }

  private:
    void plotBode(const FrequencyView& frequency);
    QString identificationHtml(const RailIdentification& id) const;
    QString dcIdentificationHtml(const DcAxisIdentification& id) const;
    QString marginsHtml(const FrequencyView& frequency) const;
    /// The prediction-against-measurement table, the machine time and the verdict.
    QString verificationHtml(const MoveResult& predictedStep, const MoveResult& measuredStep,
                             const MoveResult& predictedLong, const MoveResult& measuredLong,
                             double machineTimeS, bool ok, const QString& error) const;
    QLabel* summary_;
    QCustomPlot* bode_;
};

}  // namespace ui
}  // namespace trilho
