#pragma once
// The DNC server as the tests set it up over a machine (the rail's VirtualMachine, the XY
// machines', the screens' shared worker): remote access on, the register image in a
// RegisterStore the server owns, and every history line it says collected.
#include <QObject>
#include <QString>
#include <QStringList>
#include <memory>

#include "core/gcode/compiler.h"
#include "core/profile/machine_profile.h"
#include "host/dnc/dnc_server.h"
#include "host/dnc/register_store.h"

namespace trilho::dnc::test {

/// Makes dnc over machine, its programs in programsDir compiled for profile's limits; store is
/// its register image (owned by dnc); each history line is appended to history, which must
/// outlive dnc's history.
inline void serveRemotely(DncMachine& machine, const MachineProfile& profile,
                          const QString& programsDir, std::unique_ptr<DncServer>& dnc,
                          RegisterStore*& store, QStringList& history) {
    CompileOptions options;
    options.machine = profile.limits;
    dnc = std::make_unique<DncServer>(machine, ProgramLibrary(programsDir, options));
    store = new RegisterStore(dnc.get());
    dnc->adopt(store);
    dnc->setRemote(true);
    QObject::connect(dnc.get(), &DncServer::historyLine,
                     [&history](const QString& l) { history << l; });
}

}  // namespace trilho::dnc::test
