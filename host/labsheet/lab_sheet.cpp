#include "host/labsheet/lab_sheet.h"

#include "host/tuning/reports/metrics_report.h"

namespace trilho {

namespace {

/// A number as a teacher typed it: up to 6 significant digits, no trailing zeros (0.0005, 1.2).
QString plain(double v) {
    return QString::number(v, 'g', 6);
}

QString gainsText(const TuningGains& g, MachineKind kind, LoopLaw law) {
    if (kind == MachineKind::DcTable && law == LoopLaw::Classic)
        return QStringLiteral("b0 %1, b1 %2").arg(plain(g.b0), plain(g.b1));
    if (kind == MachineKind::DcTable)
        return QStringLiteral("Kp %1, Ki %2, Kff %3").arg(plain(g.kp), plain(g.ki), plain(g.kff));
    return QStringLiteral("Kp %1, Ki %2, Kd %3").arg(plain(g.kp), plain(g.ki), plain(g.kd));
}

QString machineText(const RunRecord& r) {
    if (!r.hasConditions) return QStringLiteral("not recorded");
    const RunConditions& c = r.conditions;
    return c.axis ? QStringLiteral("%1 axis %2").arg(c.profile.name, QString(QLatin1Char(c.axis)))
                  : c.profile.name;
}

QString testText(const RunConditions& c) {
    const QString move =
        QStringLiteral("%1 mm from %2 mm").arg(plain(c.amplitudeMm), plain(c.startMm));
    if (c.test == QLatin1String("step")) return QStringLiteral("step, ") + move;
    if (c.test == QLatin1String("ramp"))
        return QStringLiteral("ramp at %1 % of rapid, ").arg(plain(c.speedFraction * 100.0)) + move;
    return c.test;  // a program's trace (`run --trace`): the program's file
}

}  // namespace

QColor labSheetColor(int index) {
    static const QColor colours[] = {
        QColor(31, 119, 180),  QColor(214, 39, 40), QColor(44, 160, 44),   QColor(255, 127, 14),
        QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(23, 190, 207)};
    return colours[static_cast<std::size_t>(index) % std::size(colours)];
}

std::vector<LabSheetRow> labSheetRows(const LabSheet& sheet) {
    std::vector<LabSheetRow> rows;
    auto conditionRow = [&](const char* name, auto cell) {
        LabSheetRow row{QLatin1String(name), {}, false};
        for (const LabSheetRun& run : sheet.runs)
            row.cells.push_back(run.record->hasConditions ? cell(run.record->conditions)
                                                          : QStringLiteral("not recorded"));
        rows.push_back(std::move(row));
    };
    {
        LabSheetRow row{QStringLiteral("machine"), {}, false};
        for (const LabSheetRun& run : sheet.runs)
            row.cells.push_back(machineText(*run.record));
        rows.push_back(std::move(row));
    }
    conditionRow("law", [](const RunConditions& c) { return runLawName(c); });
    conditionRow("period", [](const RunConditions& c) {
        return QStringLiteral("%1 ms").arg(plain(c.periodS * 1e3));
    });
    conditionRow("gains", [](const RunConditions& c) {
        QString g = gainsText(c.gains, c.profile.kind, c.law);
        if (c.gainChange)
            g += QStringLiteral("; %1 s after the step: %2")
                     .arg(plain(c.gainChange->atS),
                          gainsText(c.gainChange->gains, c.profile.kind, c.law));
        return g;
    });
    conditionRow("payload (mass factor)", [](const RunConditions& c) {
        return QStringLiteral("x %1").arg(plain(c.massFactor));
    });
    conditionRow("test", [](const RunConditions& c) { return testText(c); });
    // The teaching switches (issue 33 item 9): a run made with one off is another experiment,
    // and the sheet says which.
    conditionRow("teaching switches", [](const RunConditions& c) {
        QStringList off;
        if (!c.antiWindup) off << QStringLiteral("anti-windup off");
        if (c.encoderNoiseCounts != 0)
            off << QStringLiteral("encoder noise +-%1 counts").arg(c.encoderNoiseCounts);
        if (!c.dacQuantisation) off << QStringLiteral("DAC quantisation off");
        return off.isEmpty() ? QStringLiteral("as the machine") : off.join(QStringLiteral("; "));
    });
    conditionRow("seed", [](const RunConditions& c) { return QString::number(c.seed); });
    conditionRow("ran at", [](const RunConditions& c) {
        return c.date.isEmpty() ? QStringLiteral("not recorded") : c.date;
    });
    {
        LabSheetRow row{QStringLiteral("record"), {}, false};
        for (const LabSheetRun& run : sheet.runs)
            row.cells.push_back(run.flaw.isEmpty()
                                    ? QStringLiteral("clean, %1 ticks").arg(run.metrics.samples)
                                    : run.flaw);
        rows.push_back(std::move(row));
    }
    // The metrics: the rows `tune metrics` prints, in its order, from the same function.
    std::vector<std::vector<StepMetricLine>> lines;
    for (const LabSheetRun& run : sheet.runs)
        lines.push_back(stepMetricLines(run.metrics));
    // A run without a step (a workbench run that never moved) has none: "no step" in its cells.
    const std::vector<StepMetricLine>* names = nullptr;
    for (const auto& l : lines)
        if (!names || l.size() > names->size()) names = &l;
    const std::size_t n = names ? names->size() : 0;
    for (std::size_t k = 0; k < n; ++k) {
        LabSheetRow row{(*names)[k].name, {}, true};
        for (const auto& l : lines)
            row.cells.push_back(k < l.size() ? l[k].value : QStringLiteral("no step"));
        rows.push_back(std::move(row));
    }
    return rows;
}

QString labSheetMachines(const LabSheet& sheet) {
    QStringList names;
    for (const LabSheetRun& run : sheet.runs) {
        const QString m = machineText(*run.record);
        if (!names.contains(m)) names << m;
    }
    return names.join(QStringLiteral(", "));
}

QString labSheetDate(const LabSheet& sheet) {
    return sheet.made.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm")) + QStringLiteral(" UTC");
}

QString labSheetText(const LabSheet& sheet) {
    QString t = QStringLiteral("lab sheet of %1 run%2, made %3\n")
                    .arg(sheet.runs.size())
                    .arg(sheet.runs.size() == 1 ? QString() : QStringLiteral("s"))
                    .arg(labSheetDate(sheet));
    t += QStringLiteral("model: %1\n")
             .arg(sheet.model.isEmpty() ? QStringLiteral("none identified") : sheet.model);
    const std::vector<LabSheetRow> rows = labSheetRows(sheet);
    for (std::size_t r = 0; r < sheet.runs.size(); ++r) {
        t += QStringLiteral("run %1\n").arg(sheet.runs[r].label);
        for (const LabSheetRow& row : rows)
            t += QStringLiteral("  %1 %2\n").arg(row.name, -28).arg(row.cells[r]);
    }
    return t;
}

}  // namespace trilho
