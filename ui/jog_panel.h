#pragma once
// Jog and run controls of today, beside the 1996 arrangement: hold-to-jog, jog speed,
// incremental steps, feed override, single block, hold/resume/stop.
#include <QWidget>

class QCheckBox;
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
    QPushButton* holdLeft() const { return holdLeft_; }
    QPushButton* holdRight() const { return holdRight_; }
    QSlider* overrideSlider() const { return override_; }
    QCheckBox* singleBlock() const { return single_; }

  signals:
    void jogStart(int direction);
    void jogStop();
    void jogStep(double mm);
    void feedOverrideChanged(double factor);
    void singleBlockToggled(bool on);
    void holdRequested();
    void resumeRequested();
    void stopRequested();

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    QPushButton *holdLeft_, *holdRight_, *stepMinus_, *stepPlus_, *hold_, *resume_, *stop_;
    QSlider *speed_, *override_;
    QComboBox* increment_;
    QCheckBox* single_;
    QLabel *speedLabel_, *overrideLabel_, *incrementLabel_;
};

}  // namespace ui
}  // namespace trilho
