#pragma once
// The screens' pre-run check (issue 31 item 8): the check of host/check/program_check.h run in
// the screens' background pool (ui/background_pool.h) while the operator looks at the program,
// so the Cycle start question can say its line at once (ui/pre_run_check_text.h) and never
// waits for it. One check at a time, keyed to what it is of (the program's revision) and what
// it runs with (the live law, gains and feed override): a result is given only for the same
// key, never for an edited program or changed settings; a newer start cancels the older check.
//
// Cost (program_check.h): at most kScreenCheckSeconds of machine time, about 0.15 s of one
// core on the rail (1 ms periods) for a program that never ends, at the pool's low priority;
// on the screens' thread only the start (a copy of the editor's text) and the result's arrival.
#include <QObject>
#include <QTimer>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/gcode/compiler.h"
#include "core/gcode/program.h"
#include "core/profile/machine_profile.h"
#include "host/check/program_check.h"

namespace trilho {
namespace ui {

/// The screens' bound, s of machine time from the check's start (homing included): a program
/// that has not ended by then is said as such ("no end within 600 s"). Smaller than the
/// command line's hour, so a program that never ends costs the screens a fraction of a second.
inline constexpr double kScreenCheckSeconds = 600.0;

/// Which program a check is of, as its screen counts them, and what it runs with.
struct PreRunCheckKey {
    std::int64_t program = 0;   ///< the rail: its selection; the XY machines: their load's count
    std::int64_t revision = 0;  ///< the rail: the editor's revision (each edit and load)
    int dialect = 0;            ///< the rail: the G-code dialect it is compiled in
    ProgramCheckOptions options;
    bool operator==(const PreRunCheckKey&) const = default;
};

class PreRunCheck : public QObject {
    Q_OBJECT
  public:
    enum class State : std::uint8_t {
        None,     ///< no check of that key: another's, or none started
        Running,  ///< started, not done yet
        Done,     ///< result() holds it
        Failed,   ///< it could not run (error() says why, in English from the checker)
    };

    explicit PreRunCheck(QObject* parent = nullptr);
    ~PreRunCheck() override;

    /// What the screen would check now (none: no program) and how it starts that check (the
    /// rail compiles its editor's text, the XY machines give their program). Set once.
    void setScreen(std::function<std::optional<PreRunCheckKey>()> currentKey,
                   std::function<void(const PreRunCheckKey&)> startCheck);
    /// After a change (an edit, a load, the law, gains, override or dialect): the check of the
    /// screen's key starts once the changes have rested kRestMs; no program clears it.
    void schedule();
    /// What the screen would check now (none: no program, or no screen set).
    std::optional<PreRunCheckKey> screenKey() const {
        return currentKey_ ? currentKey_() : std::nullopt;
    }
    /// Whether the check of the screen's key is done or failed.
    bool ready() const;
    /// The question is asked now: a key the check is not of is checked from now.
    void startIfOther(const PreRunCheckKey& key);
    /// ms a change rests before it is checked (a held override key starts one check).
    static constexpr int kRestMs = 300;

    /// Checks program (compiled for profile) under key, in the background; the check under way
    /// is cancelled. Nothing when key is the check already under way or done.
    void start(const PreRunCheckKey& key, const MachineProfile& profile,
               std::shared_ptr<const Program> program);
    /// The same from the program's text, compiled with options on the worker first.
    void start(const PreRunCheckKey& key, const MachineProfile& profile,
               std::shared_ptr<const std::string> source, const CompileOptions& options);
    /// No program: the check under way is cancelled and nothing is kept.
    void clear();

    /// The key of the check under way or done; none before the first start or after clear().
    const std::optional<PreRunCheckKey>& key() const { return key_; }
    State stateFor(const PreRunCheckKey& key) const;
    /// The result when the check of key is done; null otherwise.
    const ProgramCheck* resultFor(const PreRunCheckKey& key) const;
    /// Why the check of key could not run (empty unless Failed).
    QString errorFor(const PreRunCheckKey& key) const;

  signals:
    /// The check of key() is done or failed.
    void finished();

  private:
    void launch(const PreRunCheckKey& key, const MachineProfile& profile,
                std::shared_ptr<const Program> program, std::shared_ptr<const std::string> source,
                const CompileOptions& options);

    std::optional<PreRunCheckKey> key_;
    State state_ = State::None;
    std::optional<ProgramCheck> result_;
    QString error_;
    std::function<std::optional<PreRunCheckKey>()> currentKey_;
    std::function<void(const PreRunCheckKey&)> startCheck_;
    QTimer* rest_ = nullptr;                     ///< a change rests this long before a check
    std::optional<PreRunCheckKey> pending_;      ///< waiting for rest_
    std::shared_ptr<std::atomic<bool>> cancel_;  ///< the check under way's
    int generation_ = 0;                         ///< a newer start makes an older result stale
};

}  // namespace ui
}  // namespace trilho
