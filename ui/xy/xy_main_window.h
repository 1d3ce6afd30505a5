#pragma once
// The main screen of an XY machine (xy.md A and B): the work area seen from above with the
// planned and the followed path, the machine's own panel (seed 004's front panel for the DC
// table, seed 001's controls for the plotter), per-axis plots, the position readout, the run
// controls and the history. The rail keeps its own replicated 1996 screen (MainWindow).
#include <QMainWindow>
#include <functional>
#include <memory>

#include "core/gcode/program.h"
#include "ui/xy/xy_link.h"

class QLabel;
class QListWidget;
class QPushButton;
class QAction;
class QSettings;

namespace trilho {
class SerialLinkMotion;
namespace ui {

class WorkAreaView;
class XyPlots;
class DcTablePanel;
class PlotterPanel;
class PlotterCommLog;

class XyMainWindow : public QMainWindow {
    Q_OBJECT
  public:
    XyMainWindow(XyLink& link, QSettings& settings, QWidget* parent = nullptr);

    /// Reads and compiles a .G file for this machine; false (and the reason in the status bar
    /// and the history) when it cannot be read or has errors.
    bool selectProgram(const QString& path);
    /// Automatic (homes first when needed), then runs the program; asks first naming what
    /// moves where unless ask is false (the command line's --run, a deliberate choice).
    void startProgram(bool ask = true);
    /// Who answers the confirmations (tests); by default a Yes/No box that defaults to No.
    void setConfirmer(std::function<bool(const QString&, const QString&)> confirmer) {
        confirmer_ = std::move(confirmer);
    }
    QAction* homeAction() const { return home_; }
    QAction* manualAction() const { return manual_; }
    /// The machine is a board on this serial port (its link's state in the status bar); none:
    /// the simulated machine.
    void setDeviceLink(SerialLinkMotion* link, const QString& port, int baud);
    /// Runs a program made from typed points (seed 001 3.1.4, PolygonDialog): selects it and
    /// starts it as Start does (asking first); false when it cannot be saved or compiled.
    bool plotPolygon(const QString& program);
    QLabel* linkLabel() const { return linkLabel_; }

    WorkAreaView* workArea() const { return view_; }
    XyPlots* plots() const { return plots_; }
    DcTablePanel* tablePanel() const { return table_; }
    PlotterPanel* plotterPanel() const { return plotter_; }
    QListWidget* history() const { return history_; }
    QLabel* stateLabel() const { return state_; }
    QLabel* positionLabel() const { return position_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* estopButton() const { return estop_; }
    QPushButton* stopButton() const { return stop_; }
    const std::shared_ptr<const Program>& program() const { return program_; }

  signals:
    /// Options > Connection chose another backend: port empty for the simulated machine.
    void connectionChosen(const QString& port, int baud);

  protected:
    void changeEvent(QEvent* e) override;
    /// The rail's keys, whatever has the focus: F1 E-stop; Esc and Space a controlled stop when
    /// no menu or dialog is open (Space types a space in a text field).
    bool eventFilter(QObject* watched, QEvent* event) override;
    void closeEvent(QCloseEvent* e) override;

  private:
    bool confirm(const QString& title, const QString& text);
    /// What homing does on this machine, for the questions that lead to it.
    QString homingText() const;
    void requestAutomatic();
    void requestHome();
    std::function<bool(const QString&, const QString&)> confirmer_;
    QAction *home_ = nullptr, *manual_ = nullptr;
    void onUpdate(const std::vector<XyTraceRow>& rows, const std::vector<ControllerEvent>& events,
                  const XyStatus& status);
    void chooseFile();
    void retranslate();
    void addHistory(const QString& line, bool alarm);
    void chooseConnection();
    void showLinkState();

    XyLink& link_;
    QSettings& settings_;
    WorkAreaView* view_;
    XyPlots* plots_;
    DcTablePanel* table_ = nullptr;
    PlotterPanel* plotter_ = nullptr;
    QListWidget* history_;
    QLabel *state_, *position_, *block_, *program_label_;
    QPushButton *open_, *automatic_, *start_, *hold_, *resume_, *stop_, *estop_, *reset_, *ack_;
    std::shared_ptr<const Program> program_;
    QString programPath_;  ///< the file program_ came from
    QString programName_;
    QLabel* linkLabel_;
    SerialLinkMotion* deviceLink_ = nullptr;
    PlotterCommLog* commLog_ = nullptr;  ///< the plotter's communication log (seed 001)
    QString port_;
    int baud_ = 0;
    XyStatus last_;
};

}  // namespace ui
}  // namespace trilho
