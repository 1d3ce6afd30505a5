#pragma once
// The tuning and teaching workbench (issue 21): step and ramp tests without G-code on the
// machine's simulated plant in virtual time, their metrics, an overlay of every run with a
// table of metrics side by side, the P/I/D terms of a run tick by tick with the equation
// substituted and "what if" re-simulation, and on the rail and each DC table axis
// identification, autotune and the Bode plot, and on the rail the relay (Ziegler-Nichols)
// experiment beside the autotune to teach with; on the plotter (no encoder) the speed and
// acceleration margin test against lost steps. Every figure comes from core/tuning and
// host/tuning, the same code `trilho-cli tune` prints, so the screens and the CLI agree to the
// digit.
#include <QMainWindow>
#include <functional>
#include <optional>
#include <vector>

#include "core/profile/machine_profile.h"
#include "host/tuning/step_experiment.h"
#include "ui/workbench/workbench_run.h"

class QAction;
class QCheckBox;
class QMenu;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QListWidget;
class QPushButton;
class QScrollArea;
class QSpinBox;
class QTabWidget;

namespace trilho {
namespace ui {

class LogGainSlider;
class MarginView;
class ModelView;
class PolesView;
class PredictionView;
class TeachingSwitches;
class DisturbanceView;
class RunOverlay;
class TermsView;

class WorkbenchWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit WorkbenchWindow(const MachineProfile& profile, QWidget* parent = nullptr);

    /// The test the form describes now.
    StepTestSpec currentSpec() const;
    /// Runs the form's test (on a worker thread); the run is added when it ends.
    void runStep();
    /// The same move with the 1996 law (at its 10 ms period, its own gains) and with the
    /// engineered law (the profile's period and gains): two runs.
    void compareLaws();
    void identify();
    void autotune();
    /// The relay experiment and its Ziegler-Nichols gains beside the model-based autotune, both
    /// run on the same 10 mm step (host/tuning/relay_comparison.h; `tune relay`'s numbers).
    void relayExperiment();
    /// The plotter's speed and acceleration margin test on the form's axis and seed
    /// (`trilho-cli tune margin`'s numbers).
    void marginTest();
    bool busy() const { return busy_; }
    /// The plotter's workbench has only the margin test (no encoder to measure a step with).
    bool plotter() const { return profile_.kind == MachineKind::Plotter; }
    const std::vector<WorkbenchRunPtr>& runs() const { return runs_; }
    /// Whether run i is drawn in the overlay (its box in the runs' list).
    bool runShown(std::size_t i) const { return i < shown_.size() && shown_[i]; }
    /// Runs > Clear: every run goes.
    void clearRuns();
    /// Writes run index to csvPath and its sidecar on a worker thread (issue 30 item 3: a long
    /// run is hundreds of MB); runSaved says how it ended. False (and error) when there is no
    /// such run.
    bool saveRun(int index, const QString& csvPath, QString* error = nullptr);
    /// Reads, measures and prepares the plot of a run file on a worker thread (issue 30 item 3:
    /// the screens, E-stop among them, never wait for a run); the run is added when it is ready
    /// and runLoaded says how it ended. Returns at once.
    void loadRun(const QString& csvPath);
    /// Runs being read, measured or saved now.
    bool loadingRun() const { return loadingRuns_ > 0; }
    bool savingRun() const { return savingRuns_ > 0; }
    /// Reads a run file (core/tuning's loadRunRecord) on the worker thread; tests replace it to
    /// hold a load.
    using RunReader = std::function<RunLoad(const QString& csvPath)>;
    void setRunReader(RunReader reader) { runReader_ = std::move(reader); }
    /// File > Export...: the lab sheet (host/labsheet) of the runs shown in the overlay, as
    /// `trilho-cli tune report` makes it, to path (.pdf or .png), written atomically. False
    /// with *error when no run is shown, more than fit one sheet, the name is neither, or the
    /// file cannot be written (named, with the reason).
    bool exportLabSheet(const QString& path, QString* error = nullptr);
    QAction* exportAction() const { return exportSheet_; }
    /// The profile with the last autotune's gains, if one passed.
    const std::optional<MachineProfile>& tunedProfile() const { return tuned_; }

    RunOverlay* overlay() const { return overlay_; }
    TermsView* terms() const { return terms_; }
    /// The size the window opens at on a screen with `available` room: 1280x720, no larger than
    /// the room, no smaller than the window's least size.
    static QSize initialSize(const QSize& available, const QSize& least);
    ModelView* model() const { return model_; }
    MarginView* marginView() const { return marginView_; }
    /// The rail's Poles page (the last identified model, the boxes' law, gains and period).
    PolesView* polesView() const { return polesView_; }
    /// The rail's load-disturbance page (null on the other machines).
    DisturbanceView* disturbanceView() const { return disturbanceView_; }
    QTabWidget* tabs() const { return tabs_; }
    /// Issue 33 item 9: the Prediction page, the sliders under Kp, Ki and Kd (Kff on the DC
    /// table; none on the plotter) and the teaching switches.
    PredictionView* predictionView() const { return predictionView_; }
    const std::vector<LogGainSlider*>& gainSliders() const { return gainSliders_; }
    TeachingSwitches* teachingSwitches() const { return switches_; }

  signals:
    void runFinished();
    /// A load asked for with loadRun ended: error is empty when the run was added.
    void runLoaded(const QString& error);
    /// A save asked for with saveRun ended: error is empty when both files were written.
    void runSaved(const QString& csvPath, const QString& error);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void build();
    void retranslate();
    /// The form's column as wide as the form in the current language: never cut.
    void fitForm();
    void lawChanged();
    /// The gain boxes' labels and ranges for the law (the DC table's seed laws: b0, b1).
    void labelGains();
    /// The Poles page follows the boxes: law, gains, period.
    void updatePoles();
    void setBusy(bool busy);
    /// The rail and the DC table have a plant to identify; the plotter (no encoder) has not.
    bool tunable() const { return profile_.kind != MachineKind::Plotter; }
    void identifyTableAxis();
    void autotuneTableAxis();
    /// The middle of an axis' soft limits, mm: where `tune identify|auto` puts the table.
    static double tableMiddle(const AxisTravel& t) { return 0.5 * (t.softMinMm + t.softMaxMm); }
    /// A run made on a worker thread (record, metrics and plot), added with its number, name
    /// and colour; gainChangeMissed as StepTestResult's.
    void addRun(std::shared_ptr<WorkbenchRun> run, const QString& label,
                const QString& gainChangeMissed = {});
    /// loadRun, and when tell, a dialog if it fails (Load run...).
    void startLoad(const QString& csvPath, bool tell);
    /// Runs no longer listed: their memory (hundreds of MB for a long run) is freed on a worker
    /// thread, never on this one.
    void releaseInBackground(std::vector<WorkbenchRunPtr> runs);
    void refreshRuns();
    void selectRun(int index);
    void whatIfRun(const TuningGains& gains);
    void saveSelectedRun();
    void loadRunFromFile();
    void saveTunedProfile();
    /// File > Export...: asks where, then exportLabSheet; a failure in a dialog.
    void exportLabSheetFromDialog();
    QString runLabel(const RunConditions& c) const;
    /// Runs work on a worker thread, then done(result) on this thread.
    template <typename T>
    void inBackground(std::function<T()> work, std::function<void(T)> done);

    MachineProfile profile_;
    bool rail_;
    bool busy_ = false;
    std::vector<WorkbenchRunPtr> runs_;
    std::vector<bool> shown_;  ///< per run: drawn in the overlay
    int selected_ = -1;
    int nextNumber_ = 1;
    std::optional<MachineProfile> tuned_;
    RunReader runReader_ = [](const QString& path) { return loadRunRecord(path); };
    int loadingRuns_ = 0;
    int savingRuns_ = 0;

    QTabWidget* tabs_;
    QScrollArea* formScroll_;
    RunOverlay* overlay_;
    TermsView* terms_;
    ModelView* model_;
    MarginView* marginView_;
    PolesView* polesView_;
    PredictionView* predictionView_;
    std::vector<LogGainSlider*> gainSliders_;
    TeachingSwitches* switches_;
    DisturbanceView* disturbanceView_ = nullptr;
    QGroupBox *testBox_, *tuneBox_, *runsBox_;
    /// The rail's engineered law: new gains part-way through the test (`--change-at`).
    QGroupBox* changeBox_;
    QLabel *changeAtLabel_, *newKpLabel_, *newKiLabel_, *newKdLabel_;
    QDoubleSpinBox *changeAt_, *newKp_, *newKi_, *newKd_;
    QPushButton* margin_;
    QLabel *axisLabel_, *amplitudeLabel_, *speedLabel_, *lawLabel_, *periodLabel_, *kpLabel_,
        *kiLabel_, *kdLabel_, *massLabel_, *seedLabel_;
    QComboBox *axis_, *law_;
    QDoubleSpinBox *amplitude_, *speed_, *period_, *kp_, *ki_, *kd_, *mass_;
    QSpinBox* seed_;
    QPushButton *run_, *compare_, *identify_, *autotune_, *relay_, *saveTuned_;
    QListWidget* runList_;
    QPushButton *saveRun_, *loadRun_, *removeRun_, *clearRuns_;
    QMenu* fileMenu_;
    QAction* exportSheet_;
};

}  // namespace ui
}  // namespace trilho
