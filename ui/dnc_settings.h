#pragma once
// Options > DNC as remembered in QSettings ("dnc/..."): where the Modbus server listens and
// where the program library is. Remote (the operator's consent) is deliberately not here: it
// is off at every start and never remembered.
#include <QSettings>
#include <QString>

namespace trilho {
namespace ui {

struct DncSettings {
    bool enabled = false;                        ///< serve at start (and after Apply)
    QString host = QStringLiteral("127.0.0.1");  ///< Modbus TCP address (numeric or localhost)
    quint16 port = 1502;                         ///< Modbus TCP port (502 needs root)
    bool rtu = false;                            ///< also Modbus RTU on a serial line
    QString rtuDevice;                           ///< e.g. /dev/ttyUSB0
    int baud = 19200;                            ///< RTU bit rate, bit/s (8N1)
    int unit = 1;                                ///< RTU unit id, 1-247
    QString programsDir;                         ///< the library (NNNN.G); empty: default

    /// The app's data location + "/programs" (next to history.log), e.g.
    /// ~/.local/share/trilho/trilho/programs on Linux.
    static QString defaultProgramsDir();
    /// programsDir, or the default when it is empty.
    QString programs() const;

    static DncSettings load(QSettings& settings);
    void save(QSettings& settings) const;

    /// True for 127.0.0.0/8, ::1 and "localhost": only this computer can connect.
    static bool isLocal(const QString& host);
    /// The address to bind: "localhost" is 127.0.0.1; others as written.
    static QString bindAddress(const QString& host);
};

}  // namespace ui
}  // namespace trilho
