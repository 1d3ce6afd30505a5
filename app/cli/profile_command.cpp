// trilho-cli profile [FILE]: checks a machine profile and prints it with every default filled
// in; with no FILE prints the default profile (the rail of machine.md).
#include <QCommandLineParser>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "core/machine_profile.h"

namespace trilho::cli {

int profileCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Check a machine profile and print it in full."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("FILE"),
                                 QStringLiteral("Profile to check (default: the rail)."),
                                 QStringLiteral("[FILE]"));
    if (!parser.parse(args)) {
        err(QStringLiteral("trilho-cli profile: %1\n").arg(parser.errorText()));
        return kUsage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText());
        return kOk;
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) {
        err(QStringLiteral("trilho-cli profile: expected at most one FILE\n"));
        return kUsage;
    }
    MachineProfile profile = MachineProfile::rail();
    if (!files.isEmpty()) {
        ProfileLoad load = loadMachineProfile(files.front());
        if (!load.profile) {
            err(QStringLiteral("trilho-cli profile: %1\n").arg(load.error));
            return kUsage;
        }
        profile = *load.profile;
    }
    out(QString::fromUtf8(machineProfileToJson(profile)));
    return kOk;
}

}  // namespace trilho::cli
