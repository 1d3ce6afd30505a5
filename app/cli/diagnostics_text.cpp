#include "app/cli/diagnostics_text.h"

#include "core/gcode/diagnostic_text.h"

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

void writeDiagnosticsText(ChunkedOutput& out, const QString& file, const Program& program) {
    for (const Diagnostic& d : program.diagnostics)
        out.append(formatDiagnosticLine(file, d));
    if (program.diagnosticsOmitted)
        out.append(omittedDiagnostics(program.diagnosticsOmitted) + QLatin1Char('\n'));
    out.append(compileSummary(program.errorCount()) + QLatin1Char('\n'));
}

}  // namespace trilho::cli
