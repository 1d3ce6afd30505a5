#pragma once
// The execucao form of 1996 (screens.md 2), control by control and in the same arrangement:
// the Alarmes and Status lists on top; the automatic and manual frames on the left; Dados
// Atuais, Controlador and Malha on the right. It shows a controller snapshot and raises the
// operator's intents as signals; it holds no machine state of its own.
#include <QWidget>

#include "core/rail/rail_controller.h"

class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace trilho {
namespace ui {

class GaugeWidget;

class ExecutionPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ExecutionPanel(QWidget* parent = nullptr);

    void showStatus(const ControllerStatus& s);
    void setAutomaticMode(bool automatic);  ///< greys and enables as the VB did
    void setProgramName(const QString& name);
    void addStatusLine(const QString& line);
    void addAlarmLine(const QString& line);
    void clearAlarms();
    void setAlarmSummary(const QString& text);
    void setLineText(const QString& text);
    void setOnlineStatus(const QString& text);
    void showGains(const LoopGains& g);
    void markGainInvalid(int which, bool invalid);

    // for tests and the main window
    QComboBox* alarms() const { return alarms_; }
    QComboBox* statusList() const { return status_; }
    QLineEdit* programField() const { return program_; }
    QLineEdit* lineField() const { return line_; }
    QLineEdit* onlineStatusField() const { return online_; }
    QPushButton* continueButton() const { return continue_; }
    QPushButton* leftButton() const { return left_; }
    QPushButton* rightButton() const { return right_; }
    QPushButton* stopButton() const { return stop_; }
    QLineEdit* positionField() const { return position_; }
    QLineEdit* speedField() const { return speed_; }
    QLineEdit* accelerationField() const { return acceleration_; }
    QLineEdit* gainField(int which) const {
        return gains_[which];
    }  ///< 0 P, 1 D, 2 I (screen order)
    QLineEdit* setpointField() const { return setpoint_; }
    GaugeWidget* realGauge() const { return real_; }
    GaugeWidget* errorGauge() const { return error_; }
    QGroupBox* automaticFrame() const { return autoFrame_; }
    QGroupBox* manualFrame() const { return manualFrame_; }

  signals:
    void continuePressed();
    void leftPressed();
    void rightPressed();
    void stopPressed();
    /// The operator finished editing a gain: which = 0 P, 1 D, 2 I.
    void gainEdited(int which, double value);

  protected:
    void changeEvent(QEvent* e) override;
    void paintEvent(
        QPaintEvent* e) override;  ///< lets the theme's style sheet paint the background

  private:
    /// Fields and the buttons among them as tall as the text plus 6 px, not the style's h + 8:
    /// the 285-twip (19 px) boxes of the VB form, and the form's height follows the font's line
    /// rather than the style's padding (issue 35: at 10 pt in Nimbus Sans the form needed
    /// 343 px of the 308 a 768-line screen leaves it).
    void fitRows();
    void retranslate();
    QLineEdit* readOnly();
    QComboBox *alarms_, *status_;
    QLabel *alarmsLabel_, *statusLabel_;
    QGroupBox *autoFrame_, *manualFrame_, *dataFrame_, *controllerFrame_, *loopFrame_;
    QLabel *programLabel_, *lineLabel_, *leftLabel_, *rightLabel_;
    QLineEdit *program_, *line_, *online_;
    QPushButton *continue_, *left_, *right_, *stop_;
    QLabel *positionLabel_, *speedLabel_, *accelerationLabel_, *positionUnit_, *speedUnit_,
        *accelerationUnit_;
    QLineEdit *position_, *speed_, *acceleration_;
    QLabel* gainLabels_[3];
    QLineEdit* gains_[3];
    QLabel *setpointLabel_, *setpointUnit_, *realLabel_, *errorLabel_;
    QLineEdit* setpoint_;
    GaugeWidget *real_, *error_;
    double gaugeStart_ = 0.0, gaugeTarget_ = 0.0;
    double shownSpeed_ = 0.0, shownAcceleration_ = 0.0;  ///< display filter state
    bool automatic_ = false;
};

}  // namespace ui
}  // namespace trilho
