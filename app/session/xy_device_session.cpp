#include "app/session/xy_device_session.h"

#include "core/machine/plotter_link_motion.h"

namespace trilho {

XyDeviceSession makeXyDeviceSession(const MachineProfile& profile, SerialSettings settings) {
    XyDeviceSession made;
    if (profile.kind != MachineKind::Plotter) {
        made.error = profile.kind == MachineKind::DcTable
                         ? QStringLiteral("the DC table's serial backend is not built yet")
                         : QStringLiteral("the rail has no serial backend");
        return made;
    }
    if (settings.baud <= 0) settings.baud = 57600;  // seed 001
    made.line = std::make_unique<SerialLine>();
    QString error;
    if (!made.line->open(settings, &error)) {
        made.error = error;
        made.line.reset();
        return made;
    }
    SerialLine* line = made.line.get();
    auto motion = std::make_unique<PlotterLinkMotion>(
        profile, [line](const std::vector<std::uint8_t>& bytes) { line->write(bytes); });
    PlotterLinkMotion* m = motion.get();
    QObject::connect(line, &SerialLine::received, line, [m](const QByteArray& bytes) {
        m->onBytes(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                   static_cast<std::size_t>(bytes.size()));
    });
    QObject::connect(line, &SerialLine::lost, line,
                     [m](const QString& reason) { m->linkLost(reason.toStdString()); });
    auto controller = std::make_unique<XyController>(profile, std::move(motion));
    // 1 ms: the protocol's own deadlines are seconds; the period only bounds the latency.
    made.session = std::make_unique<XySession>(nullptr, std::move(controller), 0.001);
    made.plotter = m;
    return made;
}

}  // namespace trilho
