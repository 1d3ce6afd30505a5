#pragma once
// The workbench's teaching switches (issue 33 item 9), under the gain boxes: the engineered
// law's anti-windup, the encoder's read noise and the DAC's quantization, as `trilho-cli tune
// step --anti-windup on|off --encoder-noise N --dac-quantisation on|off` gives them to a test
// (host/tuning/step_experiment.h). Each is enabled only where the test takes it: the
// anti-windup under an engineered law (rail or DC table), the noise on the rail, the
// quantization on the rail's engineered law; a disabled switch is the machine's own setting.
#include <QGroupBox>

#include "host/tuning/step_experiment.h"

class QCheckBox;
class QLabel;
class QSpinBox;

namespace trilho {
namespace ui {

class TeachingSwitches : public QGroupBox {
    Q_OBJECT
  public:
    explicit TeachingSwitches(QWidget* parent = nullptr);
    /// Which switches apply: the machine (rail or DC table) and the law the test will run.
    void setLaw(bool rail, bool engineered);
    /// Writes the enabled switches into a test (the others stay the machine's own).
    void apply(StepTestSpec& spec) const;
    QCheckBox* antiWindup() const { return antiWindup_; }
    QSpinBox* encoderNoise() const { return noise_; }
    QCheckBox* dacQuantisation() const { return quantisation_; }

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QCheckBox* antiWindup_;
    QLabel* noiseLabel_;
    QSpinBox* noise_;
    QCheckBox* quantisation_;
};

}  // namespace ui
}  // namespace trilho
