#pragma once
// What the Cycle start question says of the pre-run check (issue 31 item 8): one line in the
// question ("Pre-run check: cycle 42.3 s, worst following error 0.8 mm at line 40.") and the
// details a click away (the question's "Show Details..."), in the UI language. A check not done
// for the program and settings the question is about is said as still running, never with
// another's figures; a result that is not ok says why plainly (an alarm and its line, the soft
// limits left, no end within the bound). The operator still decides.
#include <QCoreApplication>
#include <QString>

#include "core/profile/machine_profile.h"
#include "ui/pre_run_check.h"

namespace trilho {
namespace ui {

struct PreRunCheckSaid {
    QString line;     ///< one line for the question's text
    QString details;  ///< the question's details; empty while the check runs
};

class PreRunCheckText {
    Q_DECLARE_TR_FUNCTIONS(PreRunCheckText)
  public:
    /// The line and details for the question about key on profile's machine (file: the
    /// program's file name, for the details' first line).
    static PreRunCheckSaid say(const PreRunCheck& check, const PreRunCheckKey& key,
                               const MachineProfile& profile, const QString& file);
    /// At the question: the screen's program as it is now, checked from now when the check is
    /// of another (a change that has not rested yet); its line, or that it still runs; nothing
    /// with no program.
    static PreRunCheckSaid sayAtQuestion(PreRunCheck& check, const MachineProfile& profile,
                                         const QString& file);
    /// Only the line of a done check, run at feedOverride (0 to 1.5).
    static QString line(const ProgramCheck& check, const MachineProfile& profile,
                        double feedOverride = 1.0);
    /// An alarm's text cut to its name: the words before its first ':' or '!' ("Following
    /// error"), the whole text when it has neither.
    static QString alarmName(const QString& text);
};

}  // namespace ui
}  // namespace trilho
