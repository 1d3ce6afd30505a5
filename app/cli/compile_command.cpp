// trilho-cli compile [--dialect classic|standard] [--json] [--lang en|pt_BR|es] [--machine
// PROFILE] FILE
#include <QCommandLineParser>
#include <cerrno>
#include <cstring>
#include <new>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/diagnostics_text.h"
#include "app/cli/option_values.h"
#include "app/cli/program_json.h"
#include "core/gcode/compiler.h"
#include "core/gcode/diagnostic_text.h"
#include "core/gcode/source_file.h"
#include "core/profile/machine_profile.h"
#include "host/common/data_paths.h"
#include "translations/i18n.h"

namespace trilho::cli {

namespace {

int compileFile(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Check a .G program and list every diagnostic."));
    const QCommandLineOption dialectOpt = dialectOption();
    QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print one JSON object."));
    const QCommandLineOption langOpt = languageOption();
    QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: axes and soft limits; a file, or the name of a shipped "
                       "one (rail, xy_dc_table, ...; default: rail)."),
        QStringLiteral("PROFILE"));
    parser.addOptions({dialectOpt, jsonOpt, langOpt, machineOpt});
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("The program to compile."));
    if (auto done = parseArguments(parser, args, "compile")) return *done;
    Dialect dialect = Dialect::Standard;
    if (auto m = readDialect(parser, dialectOpt, dialect)) return usageError("compile", *m);
    if (auto m = installLanguageOption(parser, langOpt)) return usageError("compile", *m);
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usageError("compile",
                          QStringLiteral("expected exactly one FILE, got %1").arg(files.size()));
    const QString file = files.front();
    SourceFile source = readSourceFile(localPath(file));
    if (!source.ok) return usageError("compile", QString::fromStdString(source.error));
    CompileOptions options;
    options.dialect = dialect;
    const ProfileLoad load = loadNamedMachineProfile(parser.value(machineOpt));
    if (!load.profile) return usageError("compile", load.error);
    if (!load.error.isEmpty()) err(QStringLiteral("trilho-cli compile: %1\n").arg(load.error));
    options.machine = load.profile->limits;
    options.maxDiagnostics = kMaxListedDiagnostics;
    const Program program = compile(source.bytes, options);
    source = {};  // the text is no longer needed: free it before the output is made

    // Streamed: each chunk goes to stdout as soon as it is made.
    ChunkedOutput output(streamSink(stdout));
    if (parser.isSet(jsonOpt)) {
        writeProgramJson(output, file, program);
        output.append('\n');
    } else {
        writeDiagnosticsText(output, file, program);
    }
    if (!output.flush() || std::fflush(stdout) != 0)
        return usageError("compile", QStringLiteral("cannot write the output: %1")
                                         .arg(QString::fromLocal8Bit(std::strerror(errno))));
    return program.ok() ? kOk : kCompileErrors;
}

}  // namespace

int compileCommand(const QStringList& args) {
    try {
        return compileFile(args);
    } catch (const std::bad_alloc&) {
        // Whatever the program needed has been released by now; the report itself is small.
        std::fflush(stdout);
        return usageError("compile", QStringLiteral("out of memory (the program is too large "
                                                    "to compile on this computer)"));
    }
}

}  // namespace trilho::cli
