// trilho-cli compile [--dialect classic|standard] [--json] [--lang en|pt_BR|es] [--machine
// PROFILE.json] FILE
#include <QCommandLineParser>
#include <QJsonDocument>

#include "app/cli/cli_output.h"
#include "app/cli/commands.h"
#include "app/cli/program_json.h"
#include "core/compiler.h"
#include "core/diagnostic_text.h"
#include "core/machine_profile.h"
#include "core/source_file.h"
#include "translations/i18n.h"

namespace trilho::cli {

QString formatDiagnosticLine(const QString& file, const Diagnostic& d) {
    QString place = file + QLatin1Char(':') + QString::number(d.line);
    if (d.column) place += QLatin1Char(':') + QString::number(d.column);
    const QString severity =
        d.severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning");
    return QStringLiteral("%1: %2[%3]: %4\n")
        .arg(place, severity,
             QString::fromLatin1(d.code().data(), static_cast<qsizetype>(d.code().size())),
             diagnosticMessage(d));
}

int compileCommand(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Check a .G program and list every diagnostic."));
    QCommandLineOption dialectOpt(QStringLiteral("dialect"),
                                  QStringLiteral("classic or standard (default)."),
                                  QStringLiteral("dialect"), QStringLiteral("standard"));
    QCommandLineOption jsonOpt(QStringLiteral("json"), QStringLiteral("Print one JSON object."));
    QCommandLineOption langOpt(QStringLiteral("lang"),
                               QStringLiteral("Message language: en, pt_BR or es."),
                               QStringLiteral("lang"), QStringLiteral("en"));
    QCommandLineOption machineOpt(
        QStringLiteral("machine"),
        QStringLiteral("Machine profile: axes and soft limits (default: the rail)."),
        QStringLiteral("PROFILE.json"));
    parser.addOptions({dialectOpt, jsonOpt, langOpt, machineOpt});
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("The program to compile."));
    if (auto done = parseArguments(parser, args, "compile")) return *done;
    const auto dialect = parseDialect(parser.value(dialectOpt).toStdString());
    if (!dialect)
        return usageError("compile", QStringLiteral("unknown dialect '%1' (classic or standard)")
                                         .arg(parser.value(dialectOpt)));
    if (!installLanguage(parser.value(langOpt)))
        return usageError(
            "compile",
            QStringLiteral("unknown language '%1' (en, pt_BR or es)").arg(parser.value(langOpt)));
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usageError("compile",
                          QStringLiteral("expected exactly one FILE, got %1").arg(files.size()));
    const QString file = files.front();
    const SourceFile source = readSourceFile(file.toStdString());
    if (!source.ok) return usageError("compile", QString::fromStdString(source.error));
    CompileOptions options;
    options.dialect = *dialect;
    if (parser.isSet(machineOpt)) {
        const ProfileLoad load = loadMachineProfile(parser.value(machineOpt));
        if (!load.profile) return usageError("compile", load.error);
        options.machine = load.profile->limits;
    }
    const Program program = compile(source.bytes, options);

    if (parser.isSet(jsonOpt)) {
        out(QString::fromUtf8(
                QJsonDocument(programToJson(file, program)).toJson(QJsonDocument::Compact)) +
            QLatin1Char('\n'));
    } else {
        QString text;
        for (const Diagnostic& d : program.diagnostics)
            text += formatDiagnosticLine(file, d);
        text += compileSummary(program.errorCount()) + QLatin1Char('\n');
        out(text);
    }
    return program.ok() ? kOk : kCompileErrors;
}

}  // namespace trilho::cli
