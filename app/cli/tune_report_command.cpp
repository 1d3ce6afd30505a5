// trilho-cli tune report RUN.csv [RUN2.csv ...] [--pdf OUT.pdf] [--png OUT.png]
// Issue 33 item 8: the lab sheet of runs saved by `tune step --trace`, `run --trace` or the
// workbench: their responses overlaid, their conditions and metrics side by side, on one A4
// page (host/labsheet). Each run is read and measured as `tune metrics` reads and measures it
// (loadRunRecord, measureRun against the commanded target, the same rows of text), so the sheet
// and `tune metrics` agree to the digit. A run that cannot be read, or has no step, is named and
// left out; the sheet of the others is still made.
#include <QCommandLineParser>
#include <QFileInfo>
#include <numbers>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "core/tuning/run_record.h"
#include "host/common/data_paths.h"
#include "host/labsheet/lab_sheet.h"
#include "host/labsheet/lab_sheet_file.h"
#include "host/labsheet/lab_sheet_painter.h"
#include "host/tuning/reports/metrics_report.h"
#include "host/tuning/reports/trace_report.h"

namespace trilho::cli {

int tuneReportCommand(const QStringList& args) {
    const char* name = "tune report";
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Make the lab sheet of saved runs (tune step --trace, run --trace, the workbench's Save "
        "run): one A4 page with their responses and drives overlaid, their machine, law, period, "
        "gains, payload and test, and their metrics side by side as 'tune metrics' prints them, "
        "the model when one was identified and the date. Written as a PDF, a PNG of the same page "
        "(1240 x 1754 px, 150 dpi), or both; each atomically. The sheet's text is printed."));
    const QCommandLineOption pdfOpt(QStringLiteral("pdf"),
                                    QStringLiteral("Write the sheet as a one-page PDF here."),
                                    QStringLiteral("OUT.pdf"));
    const QCommandLineOption pngOpt(
        QStringLiteral("png"), QStringLiteral("Write the sheet as a PNG (A4 at 150 dpi) here."),
        QStringLiteral("OUT.png"));
    const QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("For a trace without its JSON sidecar: the profile whose encoder sets the "
                       "count (default rail, 22.8 counts/mm)."),
        QStringLiteral("PROFILE"));
    parser.addOptions({pdfOpt, pngOpt, machineOpt});
    parser.addPositionalArgument(
        QStringLiteral("RUN"),
        QStringLiteral("Runs (CSV, with their NAME.run.json beside them), at most %1.")
            .arg(kMaxLabSheetRuns),
        QStringLiteral("RUN.csv [RUN2.csv ...]"));
    if (auto done = parseArguments(parser, args, name)) return *done;
    auto usage = [&](const QString& m) { return usageError(name, m); };
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) return usage(QStringLiteral("expected one or more RUN.csv"));
    if (static_cast<std::size_t>(files.size()) > kMaxLabSheetRuns)
        return usage(QStringLiteral("%1 runs: at most %2 fit one sheet")
                         .arg(files.size())
                         .arg(kMaxLabSheetRuns));
    const QString pdfPath = parser.value(pdfOpt), pngPath = parser.value(pngOpt);
    if (pdfPath.isEmpty() && pngPath.isEmpty())
        return usage(QStringLiteral("expected --pdf OUT.pdf, --png OUT.png or both"));
    if (!pdfPath.isEmpty() && !pngPath.isEmpty() &&
        QFileInfo(pdfPath).absoluteFilePath() == QFileInfo(pngPath).absoluteFilePath())
        return usage(QStringLiteral("--pdf and --png name the same file '%1'").arg(pdfPath));
    // A bare trace (no sidecar) is counted with this profile's encoder, as `tune metrics` does.
    std::optional<double> bareCountsPerMm;
    auto countsForBare = [&]() -> std::optional<double> {
        if (bareCountsPerMm) return bareCountsPerMm;
        const ProfileLoad p = loadNamedMachineProfile(parser.value(machineOpt));
        if (!p.profile) {
            err(QStringLiteral("trilho-cli tune report: %1\n").arg(p.error));
            return std::nullopt;
        }
        // As `tune metrics` counts a bare trace: a DC table's by its X axis' encoder.
        const DcAxisParams& x = p.profile->dcTable.x;
        bareCountsPerMm = p.profile->kind == MachineKind::DcTable
                              ? 2.0 * std::numbers::pi / (x.mmPerTurn * x.radPerCount)
                              : p.profile->plant.countsPerMm;
        return bareCountsPerMm;
    };

    LabSheet sheet;
    sheet.made = QDateTime::currentDateTimeUtc();
    int leftOut = 0;
    bool flawed = false;
    for (const QString& file : files) {
        auto leave = [&](const QString& why) {
            err(QStringLiteral("trilho-cli tune report: %1 (left out of the sheet)\n").arg(why));
            ++leftOut;
        };
        RunLoad load = loadRunRecord(QString::fromLocal8Bit(localPath(file)));
        if (!load.record) {
            leave(load.error);
            continue;
        }
        auto record = std::make_shared<RunRecord>(std::move(*load.record));
        std::optional<double> countsPerMm;
        if (record->hasConditions)
            countsPerMm = record->conditions.countsPerMm;
        else
            countsPerMm = countsForBare();
        if (!countsPerMm) {
            leave(QStringLiteral("%1: not measured").arg(file));
            continue;
        }
        const StepMetrics m = measureRun(record->channels, *countsPerMm, commandedTarget(*record));
        if (!m.ok) {
            leave(QStringLiteral("%1: no step to measure: %2")
                      .arg(file, QString::fromStdString(m.problem)));
            continue;
        }
        const TraceFlaws flaws = traceFlaws(*record);
        LabSheetRun run;
        // "1: c10.csv (classic, 10 ms)": the legend tells the curves apart by what changed.
        run.label =
            QStringLiteral("%1: %2").arg(sheet.runs.size() + 1).arg(QFileInfo(file).fileName());
        if (record->hasConditions)
            run.label += QStringLiteral(" (%1, %2 ms)")
                             .arg(runLawName(record->conditions))
                             .arg(QString::number(record->conditions.periodS * 1e3, 'g', 6));
        run.color = labSheetColor(static_cast<int>(sheet.runs.size()));
        run.metrics = m;
        if (flaws.aborted) run.flaw = QStringLiteral("ABORTED: ") + flaws.abortReason;
        if (flaws.truncated())
            run.flaw += (run.flaw.isEmpty() ? QString() : QStringLiteral("; ")) +
                        QStringLiteral("TRUNCATED: ") + flaws.truncation;
        flawed = flawed || !run.flaw.isEmpty();
        run.record = std::move(record);
        sheet.runs.push_back(std::move(run));
    }
    if (sheet.runs.empty()) {
        err(
            QStringLiteral("trilho-cli tune report: no run to put on the sheet; nothing "
                           "written\n"));
        return kUsage;
    }

    out(labSheetText(sheet));
    bool writeFailed = false;
    auto write = [&](const QString& path, LabSheetFormat format, const QString& what) {
        if (path.isEmpty()) return;
        QString error;
        if (writeLabSheet(sheet, format, QString::fromLocal8Bit(localPath(path)), &error)) {
            out(QStringLiteral("lab sheet written: %1 (%2)\n").arg(path, what));
        } else {
            err(QStringLiteral("trilho-cli tune report: %1\n").arg(error));
            writeFailed = true;
        }
    };
    write(pdfPath, LabSheetFormat::Pdf, QStringLiteral("PDF, one A4 page"));
    write(pngPath, LabSheetFormat::Png,
          QStringLiteral("PNG, %1 x %2 px at %3 dpi")
              .arg(kLabSheetWidthPx)
              .arg(kLabSheetHeightPx)
              .arg(kLabSheetDpi));
    if (leftOut)
        err(QStringLiteral("trilho-cli tune report: %1 of %2 runs left out of the sheet\n")
                .arg(leftOut)
                .arg(files.size()));
    if (writeFailed || leftOut) return kUsage;
    // Drawn either way; a run that is no clean record is no success (as `tune metrics`).
    return flawed ? kAlarm : kOk;
}

}  // namespace trilho::cli
