#include "host/tuning/reports/report_fields.h"

#include <cmath>

namespace trilho {

QJsonValue numberOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

QString fixedOrNotReached(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("not reached");
}

QJsonObject tuneConditionsJson(const TuneConditions& c) {
    QJsonObject o;
    o[QStringLiteral("machine")] = c.machine;
    o[QStringLiteral("axis")] = c.axis;
    o[QStringLiteral("mass_factor")] = c.massFactor;
    o[QStringLiteral("seed")] = QString::number(c.seed);
    o[QStringLiteral("sample_period_s")] = c.samplePeriodS;
    return o;
}

}  // namespace trilho
