#include "ui/workbench/workbench_lab_sheet.h"

namespace trilho {
namespace ui {

QString labSheetModelText(const RailModel& m, bool rail) {
    auto g = [](double v) { return QString::number(v, 'g', 4); };
    if (!rail)
        return QStringLiteral("identified in the workbench: K = %1 mm/s per PWM %, tau = %2 s")
            .arg(g(m.speedGainMmSPerCode), g(m.timeConstantS));
    return QStringLiteral(
               "identified in the workbench: K = %1 mm/s per DAC code, tau = %2 s, A = %3 "
               "mm/s2, c = %4 mm/s2")
        .arg(g(m.speedGainMmSPerCode), g(m.timeConstantS), g(m.accelerationLimitMmS2),
             g(m.coulombMmS2));
}

LabSheet workbenchLabSheet(const std::vector<WorkbenchRunPtr>& runs, const std::vector<bool>& shown,
                           const std::optional<RailModel>& model, bool rail) {
    LabSheet sheet;
    sheet.made = QDateTime::currentDateTimeUtc();
    if (model) sheet.model = labSheetModelText(*model, rail);
    for (std::size_t k = 0; k < runs.size(); ++k) {
        if (k < shown.size() && !shown[k]) continue;
        const WorkbenchRunPtr& run = runs[k];
        LabSheetRun s;
        s.label = run->name;
        s.color = run->color;
        // The run's own record, shared: the sheet copies none of its ticks.
        s.record = std::shared_ptr<const RunRecord>(run, &run->record);
        s.metrics = run->metrics;
        if (!run->abortReason.isEmpty()) s.flaw = QStringLiteral("ABORTED: ") + run->abortReason;
        sheet.runs.push_back(std::move(s));
    }
    return sheet;
}

}  // namespace ui
}  // namespace trilho
