#include "host/session/xy_device_session.h"

#include "core/xy/plotter_link_motion.h"
#include "core/xy/seed004_link_motion.h"
#include "core/xy/table_link_motion.h"

namespace trilho {

XyDeviceSession makeXyDeviceSession(const MachineProfile& profile, SerialSettings settings) {
    XyDeviceSession made;
    if (profile.kind == MachineKind::Rail) {
        made.error = QStringLiteral("the rail has no serial backend");
        return made;
    }
    const bool plotter = profile.kind == MachineKind::Plotter;
    if (settings.baud <= 0) settings.baud = plotter ? 57600 : 9600;  // seeds 001 and 004
    made.line = std::make_unique<SerialLine>();
    QString error;
    if (!made.line->open(settings, &error)) {
        made.error = error;
        made.line.reset();
        return made;
    }
    SerialLine* line = made.line.get();
    auto send = [line](const std::vector<std::uint8_t>& bytes) { line->write(bytes); };
    std::unique_ptr<SerialLinkMotion> motion;
    if (plotter)
        motion = std::make_unique<PlotterLinkMotion>(profile, send);
    else if (profile.dcTable.law == DcLaw::Seed)
        motion = std::make_unique<Seed004LinkMotion>(profile, send);  // the seed's own board
    else
        motion = std::make_unique<TableLinkMotion>(profile, send);
    SerialLinkMotion* m = motion.get();
    QObject::connect(line, &SerialLine::received, line, [m](const QByteArray& bytes) {
        m->onBytes(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                   static_cast<std::size_t>(bytes.size()));
    });
    QObject::connect(line, &SerialLine::lost, line,
                     [m](const QString& reason) { m->linkLost(reason.toStdString()); });
    m->setReopen([line, settings](std::string* why) {
        QString reason;
        const bool ok = line->open(settings, &reason);
        if (!ok && why) *why = reason.toStdString();
        return ok;
    });
    auto controller = std::make_unique<XyController>(profile, std::move(motion));
    // 1 ms: the protocols' own deadlines are seconds; the period only bounds the latency.
    made.session = std::make_unique<XySession>(nullptr, std::move(controller), 0.001);
    made.link = m;
    return made;
}

}  // namespace trilho
