#pragma once
// Jogging of today, beside the 1996 arrangement: hold-to-jog, jog speed (in mm/s) and
// incremental steps. The run controls live on the main screen (run_controls).
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;

namespace trilho {
namespace ui {

class JogPanel : public QWidget {
    Q_OBJECT
  public:
    explicit JogPanel(QWidget* parent = nullptr);
    double jogFraction() const;  ///< of the rapid speed, within the manual cap
    double incrementMm() const;
    void setManual(bool manual);
    /// The rapid speed and the manual cap (fraction of it), to say the jog speed in mm/s.
    void setSpeeds(double rapidMmS, double maxFraction);
    QPushButton* holdLeft() const { return holdLeft_; }
    QPushButton* holdRight() const { return holdRight_; }
    QLabel* speedLabel() const { return speedLabel_; }

  signals:
    void jogStart(int direction);
    void jogStop();
    void jogStep(double mm);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QPushButton *holdLeft_, *holdRight_, *stepMinus_, *stepPlus_;
    QSlider* speed_;
    QComboBox* increment_;
    QLabel *speedLabel_, *incrementLabel_, *holdLabel_;
    double rapidMmS_ = 0.0, maxFraction_ = 0.5;
};

}  // namespace ui
}  // namespace trilho
