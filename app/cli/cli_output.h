#pragma once
// Small helpers every trilho-cli command shares: exit statuses and UTF-8 output.
#include <QString>
#include <optional>

class QCommandLineParser;

namespace trilho::cli {

/// Exit statuses, the same for every command (issue 2 and 4).
enum Exit : int {
    kOk = 0,
    kCompileErrors = 1,
    kUsage = 2,  ///< usage error, or a file that cannot be read
    kAlarm = 3,
    kTimeLimit = 4,
};

void out(const QString& text);  ///< stdout, UTF-8, no newline added
void err(const QString& text);  ///< stderr, UTF-8, no newline added

/// Parses a command's arguments; returns the exit status when the command is already done
/// (--help printed: kOk; a parse error reported in one line: kUsage), nothing otherwise.
std::optional<int> parseArguments(QCommandLineParser& parser, const QStringList& args,
                                  const char* command);
/// Reports a usage error in one line ("trilho-cli COMMAND: message") and returns kUsage.
int usageError(const char* command, const QString& message);

}  // namespace trilho::cli
