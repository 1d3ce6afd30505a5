#include "host/tuning/reports/margin_report.h"

#include <QJsonArray>

namespace trilho {

namespace {

QJsonArray trialsJson(const std::vector<MarginTrial>& trials) {
    QJsonArray a;
    for (const MarginTrial& t : trials)
        a.append(QJsonObject{
            {QStringLiteral("speed_mm_s"), t.speedMmS},
            {QStringLiteral("acceleration_mm_s2"), t.accelerationMmS2},
            {QStringLiteral("move_mm"), t.moveMm},
            {QStringLiteral("reached_speed"), t.reachedSpeed},
            {QStringLiteral("lost_steps"), static_cast<double>(t.lostSteps)},
            {QStringLiteral("return_error_steps"), static_cast<double>(t.returnErrorSteps)},
            {QStringLiteral("ok"), t.ok()}});
    return a;
}

QString limitText(const char* what, double max, bool found, double configured, double margin,
                  const char* unit) {
    return found ? QStringLiteral(
                       "%1: no lost step up to %2 %3; the profile's %4 %3 has a margin "
                       "of %5 (%6 %)\n")
                       .arg(QString::fromLatin1(what))
                       .arg(max, 0, 'f', 0)
                       .arg(QString::fromLatin1(unit))
                       .arg(configured, 0, 'f', 0)
                       .arg(margin, 0, 'f', 2)
                       .arg((margin - 1.0) * 100.0, 0, 'f', 0)
                 : QStringLiteral(
                       "%1: no lost step in the whole sweep (or as far as the travel lets "
                       "a move reach its speed), up to %2 %3 (margin at least %4)\n")
                       .arg(QString::fromLatin1(what))
                       .arg(max, 0, 'f', 0)
                       .arg(QString::fromLatin1(unit))
                       .arg(margin, 0, 'f', 2);
}

QString axisName(const MarginTestSpec& spec) {
    return QString(QChar::fromLatin1(spec.axis));
}

}  // namespace

QJsonObject marginReportJson(const MarginTestSpec& spec, const MarginResult& r) {
    return QJsonObject{
        {QStringLiteral("machine"), spec.profile.name},
        {QStringLiteral("axis"), axisName(spec)},
        {QStringLiteral("seed"), QString::number(spec.seed)},
        {QStringLiteral("simulation_only"), true},
        {QStringLiteral("min_move_mm"), spec.moveMm},
        {QStringLiteral("configured_speed_mm_s"), r.configuredSpeedMmS},
        {QStringLiteral("configured_acceleration_mm_s2"), r.configuredAccelerationMmS2},
        {QStringLiteral("max_speed_mm_s"), r.maxSpeedMmS},
        {QStringLiteral("max_acceleration_mm_s2"), r.maxAccelerationMmS2},
        {QStringLiteral("speed_limit_found"), r.speedLimitFound},
        {QStringLiteral("acceleration_limit_found"), r.accelerationLimitFound},
        {QStringLiteral("speed_margin"), r.speedMargin},
        {QStringLiteral("acceleration_margin"), r.accelerationMargin},
        {QStringLiteral("machine_time_s"), r.machineTimeS},
        {QStringLiteral("speed_sweep"), trialsJson(r.speedSweep)},
        {QStringLiteral("acceleration_sweep"), trialsJson(r.accelerationSweep)}};
}

QString marginReportText(const MarginTestSpec& spec, const MarginResult& r) {
    QString text = QStringLiteral(
                       "%1, axis %2: %3 trials of at least %4 mm out and back, %5 s of "
                       "machine time (simulation only)\n")
                       .arg(spec.profile.name, axisName(spec))
                       .arg(r.speedSweep.size() + r.accelerationSweep.size())
                       .arg(spec.moveMm, 0, 'f', 0)
                       .arg(r.machineTimeS, 0, 'f', 1);
    text += limitText("speed at the profile's acceleration", r.maxSpeedMmS, r.speedLimitFound,
                      r.configuredSpeedMmS, r.speedMargin, "mm/s");
    text += limitText("acceleration at the profile's speed", r.maxAccelerationMmS2,
                      r.accelerationLimitFound, r.configuredAccelerationMmS2, r.accelerationMargin,
                      "mm/s2");
    return text;
}

}  // namespace trilho
