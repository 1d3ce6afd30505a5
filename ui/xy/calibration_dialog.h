#pragma once
// The DC table's calibration on the host, as a dialog (issue 22 item 8; seed 004, annex 7,
// "Programa para pruebas a lazo abierto"): receives the board's counts from a serial port
// (hal/serial), plots pulses against time and against displacement, computes mm per pulse and
// per turn from the travel measured (core/xy/dc_calibration.h) and saves the profile
// with the measured figure. The same computation as `trilho-cli calibrate`, and the same checks
// (issue 30 item 2): a stream the program cannot have sent is refused as it comes, with its
// reason, the port closed and nothing to save.
#include <QDialog>
#include <QElapsedTimer>
#include <optional>

#include "core/profile/machine_profile.h"
#include "core/xy/dc_calibration.h"

class QCPGraph;
class QComboBox;
class QCustomPlot;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace trilho {
class SerialLine;
namespace ui {

class CalibrationDialog : public QDialog {
    Q_OBJECT
  public:
    /// profile: the table's (its mm per turn is shown and replaced); port, baud: the XY
    /// window's connection, as a start.
    CalibrationDialog(const MachineProfile& profile, const QString& port, int baud,
                      QWidget* parent = nullptr);
    ~CalibrationDialog() override;

    /// Bytes from the board, tS seconds after Start (the serial line calls it; tests too).
    void receive(const QByteArray& bytes, double tS);
    /// Computes from the counts so far and shows the result (the Compute button).
    CalibrationResult compute();
    /// The profile with the measured mm per turn of the axis (after a result with a travel).
    std::optional<MachineProfile> calibratedProfile() const;
    int points() const;          ///< counts plotted (tests)
    QString resultText() const;  ///< the line under the plots: the result, or why there is none
    void setTravelMm(double mm);
    void setAxis(int axis);  ///< 0 x, 1 y

  private:
    void start();
    void stop();
    void save();
    void replot();
    double mmPerPulseShown() const;
    /// The stream's bounds for the axis chosen (its motor's fastest count rate).
    CalibrationLimits limits() const;

    MachineProfile profile_;
    CalibrationRecorder recorder_;
    SerialLine* line_ = nullptr;
    QElapsedTimer clock_;
    QLineEdit* port_;
    QSpinBox* baud_;
    QComboBox* axis_;
    QDoubleSpinBox* travel_;
    QPushButton *start_, *compute_, *save_;
    QLabel* result_;
    QCustomPlot *pulses_, *displacement_;
    QCPGraph *pulsesGraph_, *displacementGraph_;
    std::optional<CalibrationResult> last_;
};

}  // namespace ui
}  // namespace trilho
