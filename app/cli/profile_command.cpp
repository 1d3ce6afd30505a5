// trilho-cli profile [FILE]: checks a machine profile and prints it with every default filled
// in; with no FILE prints the default profile (rail.json of the data folder, the rail of
// machine.md).
#include <QCommandLineParser>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "core/profile/machine_profile.h"
#include "host/common/data_paths.h"

namespace trilho::cli {

int profileCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Check a machine profile and print it in full."));
    parser.addPositionalArgument(
        QStringLiteral("FILE"),
        QStringLiteral("Profile to check: a file, or the name of a shipped one "
                       "(default: rail)."),
        QStringLiteral("[FILE]"));
    if (auto done = parseArguments(parser, args, "profile")) return *done;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) return usageError("profile", QStringLiteral("expected at most one FILE"));
    const ProfileLoad load = loadNamedMachineProfile(files.isEmpty() ? QString() : files.front());
    if (!load.profile) return usageError("profile", load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli profile: %1\n").arg(load.error));
    out(QString::fromUtf8(machineProfileToJson(*load.profile)));
    return kOk;
}

}  // namespace trilho::cli
