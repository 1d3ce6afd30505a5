#pragma once
// Options > DNC: where the DNC link (Modbus) listens, the programs folder, and whether it is
// on; Apply remembers the settings (QSettings) and starts or stops the server. The server's
// state is shown live; a non-local address shows a warning (Modbus has no authentication).
#include <QDialog>
#include <QSettings>
#include <optional>

#include "ui/dnc_settings.h"

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace trilho {
namespace ui {

class DncLink;

class DncDialog : public QDialog {
    Q_OBJECT
  public:
    DncDialog(DncLink& link, QSettings& settings, QWidget* parent = nullptr);

    /// Checks the fields, remembers them, starts (or stops) the server. False with the reason
    /// shown in the dialog (a bad port or address, a taken port).
    bool apply();
    /// The fields as settings, or nullopt with the reason for the operator.
    std::optional<DncSettings> fields(QString* error) const;

    QCheckBox* enabledBox() const { return enabled_; }
    QLineEdit* hostEdit() const { return host_; }
    QLineEdit* portEdit() const { return port_; }
    QGroupBox* rtuGroup() const { return rtu_; }
    QLineEdit* rtuDeviceEdit() const { return device_; }
    QLineEdit* programsEdit() const { return programs_; }
    QLabel* warningLabel() const { return warning_; }
    QLabel* messageLabel() const { return message_; }
    QLabel* stateLabel() const { return state_; }
    QPushButton* applyButton() const { return apply_; }

  signals:
    /// Applied: the programs folder may have changed.
    void applied(const trilho::ui::DncSettings& settings);

  protected:
    void changeEvent(QEvent* e) override;
    /// Opened again: the remembered settings, not what was typed and closed without Apply.
    void showEvent(QShowEvent* e) override;

  private:
    void retranslate();
    void showSettings(const DncSettings& s);
    void updateWarning();
    void updateState();

    DncLink& link_;
    QSettings& settings_;
    QCheckBox* enabled_;
    QGroupBox *tcp_, *rtu_, *library_;
    QLabel *hostLabel_, *portLabel_, *deviceLabel_, *baudLabel_, *unitLabel_, *programsLabel_;
    QLineEdit *host_, *port_, *device_, *programs_;
    QComboBox* baud_;
    QSpinBox* unit_;
    QPushButton *browse_, *apply_, *close_;
    QLabel *warning_, *message_, *state_, *remoteNote_;
};

}  // namespace ui
}  // namespace trilho
