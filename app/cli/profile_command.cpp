// trilho-cli profile [FILE]: checks a machine profile and prints it with every default filled
// in; with no FILE prints the default profile (the rail of machine.md).
#include <QCommandLineParser>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "core/machine/machine_profile.h"

namespace trilho::cli {

int profileCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Check a machine profile and print it in full."));
    parser.addPositionalArgument(QStringLiteral("FILE"),
                                 QStringLiteral("Profile to check (default: the rail)."),
                                 QStringLiteral("[FILE]"));
    if (auto done = parseArguments(parser, args, "profile")) return *done;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) return usageError("profile", QStringLiteral("expected at most one FILE"));
    MachineProfile profile = MachineProfile::rail();
    if (!files.isEmpty()) {
        ProfileLoad load = loadMachineProfile(files.front());
        if (!load.profile) return usageError("profile", load.error);
        profile = *load.profile;
    }
    out(QString::fromUtf8(machineProfileToJson(profile)));
    return kOk;
}

}  // namespace trilho::cli
