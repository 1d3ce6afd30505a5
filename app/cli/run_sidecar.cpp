#include "app/cli/run_sidecar.h"

#include <QDateTime>
#include <QFileInfo>
#include <QJsonObject>
#include <numbers>

#include "core/files/atomic_file.h"
#include "core/files/replace_target.h"
#include "core/timeline/events_file.h"
#include "core/tuning/run_record.h"
#include "host/tuning/step_experiment.h"

namespace trilho::cli {

QString runAbortReason(Outcome outcome, const Report& report, const RunOptions& options) {
    // The last alarm (or warning) the run raised is what ended it: "Alarm 3: Following error..."
    // as the history says it.
    QString last;
    if (!report.alarms.isEmpty()) {
        const QJsonObject a = report.alarms.last().toObject();
        last = QStringLiteral("%1 %2: %3")
                   .arg(a.value(QStringLiteral("severity")).toString() == QLatin1String("warning")
                            ? QStringLiteral("Warning")
                            : QStringLiteral("Alarm"))
                   .arg(a.value(QStringLiteral("code")).toInt())
                   .arg(a.value(QStringLiteral("text")).toString());
    }
    switch (outcome) {
        case Outcome::Finished:
            return report.offTarget
                       ? QStringLiteral("the program ended away from its last target: %1").arg(last)
                       : QString();
        case Outcome::Alarm:
            return last.isEmpty() ? QStringLiteral("the run was stopped (E-stop or interrupted)")
                                  : QStringLiteral("the run ended in an alarm: %1").arg(last);
        case Outcome::TimeLimit:
            return QStringLiteral("stopped by --max-seconds %1 before the program's end")
                .arg(options.maxSeconds);
    }
    return {};
}

namespace {

QString writeRunSidecar(const QString& tracePath, const MachineProfile& profile, double periodS,
                        const RunOptions& options, const QString& program, long long rows,
                        const QString& abortReason) {
    RunConditions c;
    c.profile = profile;
    c.massFactor = options.massFactor;
    c.seed = options.seed;
    c.test = program;
    c.date = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    c.periodS = periodS;
    c.rows = rows;
    c.abortReason = abortReason;
    // Late periods lengthen the trace's steps: recorded, so that they are not read as another
    // period (runSidecarContradiction).
    c.tickJitterMs = options.tickJitterMs;
    c.jitterRate = options.tickJitterMs > 0.0 ? options.jitterRate : 0.0;
    switch (profile.kind) {
        case MachineKind::Rail:
            c.law = profile.loop.law;
            c.countsPerMm = profile.plant.countsPerMm;
            break;
        case MachineKind::DcTable: {
            // The X axis' count here; `tune metrics --axis y` takes Y's from the profile.
            c.law = tableStepLaw(profile.dcTable.law);
            const DcAxisParams& a = profile.dcTable.x;
            c.countsPerMm = 2.0 * std::numbers::pi / (a.mmPerTurn * a.radPerCount);
            break;
        }
        case MachineKind::Plotter:
            c.countsPerMm = profile.plant.countsPerMm;
            break;
    }
    c.gains = profileGains(profile, profile.kind == MachineKind::DcTable ? 'x' : 0, c.law);
    const QString path = runSidecarPath(tracePath);
    if (const QString refused = refuseToReplace(path); !refused.isEmpty())
        return QStringLiteral("cannot write %1").arg(refused);
    QString error;
    if (!saveFileAtomically(path, runConditionsToJson(c, nullptr), &error)) return error;
    return {};
}

}  // namespace

QString finishTrace(TraceFile& trace, const RunOptions& options, double periodS, Outcome outcome,
                    const Report& report) {
    if (!trace.active()) return {};
    const QString path = trace.path();
    const long long rows = trace.rows();
    if (!trace.close()) return trace.error();
    // Beside a regular file only: a device or a FIFO has no "beside".
    if (!QFileInfo(path).isFile()) return {};
    const QString sidecarFailure =
        writeRunSidecar(path, options.recordedProfile, periodS, options, options.programFile, rows,
                        runAbortReason(outcome, report, options));
    if (!sidecarFailure.isEmpty()) return sidecarFailure;
    // The run's marks on the trace's time axis (events_file.h), written whole or not at all.
    QString error;
    if (!writeEventsFile(eventsPathFor(path), report.timeline.timeline(), &error)) return error;
    return {};
}

}  // namespace trilho::cli
