#include "app/cli/cli_output.h"

#include <QCommandLineParser>
#include <cstdio>

namespace trilho::cli {

void out(const QString& text) {
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stdout);
}

void err(const QString& text) {
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stderr);
}

std::optional<int> parseArguments(QCommandLineParser& parser, const QStringList& args,
                                  const char* command) {
    parser.addHelpOption();
    if (!parser.parse(args)) return usageError(command, parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        out(parser.helpText());
        return kOk;
    }
    return std::nullopt;
}

int usageError(const char* command, const QString& message) {
    err(QStringLiteral("trilho-cli %1: %2\n").arg(QLatin1String(command), message));
    return kUsage;
}

}  // namespace trilho::cli
