#pragma once
// Small helpers every trilho-cli command shares: exit statuses, UTF-8 output, output of any
// size in constant memory, and file names exactly as they were typed.
#include <QString>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

class QCommandLineParser;

namespace trilho::cli {

/// Exit statuses, the same for every command (issue 2 and 4). Each command's --help lists the
/// ones it can return, with their meaning (exitStatusHelp), and so do its man page and the
/// README; tests/integration/cli_exit_status_test.cpp makes each one happen.
enum Exit : int {
    kOk = 0,
    kCompileErrors = 1,
    kUsage = 2,  ///< usage error, a file that cannot be read, or out of memory
    kAlarm = 3,
    kTimeLimit = 4,
};

/// The "Exit status:" section of a command's --help ("compile", "run", ...; nullptr: the
/// summary for trilho-cli --help), ending with a newline.
QString exitStatusHelp(const char* command);

void out(const QString& text);  ///< stdout, UTF-8, no newline added
void err(const QString& text);  ///< stderr, UTF-8, no newline added

/// Parses a command's arguments; returns the exit status when the command is already done
/// (--help printed: kOk; a parse error reported in one line: kUsage), nothing otherwise.
std::optional<int> parseArguments(QCommandLineParser& parser, const QStringList& args,
                                  const char* command);
/// Reports a usage error in one line ("trilho-cli COMMAND: message") and returns kUsage.
int usageError(const char* command, const QString& message);

/// Keeps argv as the bytes the shell passed (main calls it first): QCoreApplication decodes
/// arguments as UTF-8 and replaces invalid bytes, so a file name that is not valid UTF-8 could
/// not be opened from its QString.
void keepRawArguments(int argc, char** argv);
/// The path to open for a FILE argument: the original bytes of the argument it came from, or
/// its local encoding when it came from nowhere else.
std::string localPath(const QString& argument);

/// Output made piece by piece and handed to a sink every chunk (64 KB), so that output of any
/// size (a million blocks as JSON) takes constant memory and starts at once.
class ChunkedOutput {
  public:
    /// Receives each chunk; returns false when it could not take it (the output is then lost).
    using Sink = std::function<bool(std::string_view)>;
    explicit ChunkedOutput(Sink sink, std::size_t chunkBytes = 64 * 1024);
    ~ChunkedOutput();
    ChunkedOutput(const ChunkedOutput&) = delete;
    ChunkedOutput& operator=(const ChunkedOutput&) = delete;

    void append(std::string_view bytes);
    void append(const char* text) { append(std::string_view(text)); }
    void append(char c);
    void append(const QString& text);  ///< as UTF-8
    /// Hands everything gathered to the sink; false once the sink has failed.
    bool flush();
    bool ok() const { return ok_; }

  private:
    Sink sink_;
    std::string buffer_;
    std::size_t chunk_;
    bool ok_ = true;
};

/// A sink that writes to a stdio stream (stdout); false when a write fails.
ChunkedOutput::Sink streamSink(std::FILE* stream);

}  // namespace trilho::cli
