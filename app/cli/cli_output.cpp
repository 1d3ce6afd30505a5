#include "app/cli/cli_output.h"

#include <QCommandLineParser>
#include <QFile>
#include <string_view>
#include <vector>

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
        out(parser.helpText() + QLatin1Char('\n') + exitStatusHelp(command));
        return kOk;
    }
    return std::nullopt;
}

QString exitStatusHelp(const char* command) {
    const std::string_view c = command ? command : "";
    QString text = QStringLiteral("Exit status:\n");
    // "  N  meaning", wrapped at 79 columns under the meaning (help2man and terminals).
    auto line = [&](int status, const char* meaning) {
        QString row = QStringLiteral("  %1 ").arg(status);
        qsizetype width = row.size();
        for (const QString& word : QString::fromLatin1(meaning).split(QLatin1Char(' '))) {
            if (width + 1 + word.size() > 79) {
                row += QStringLiteral("\n     ");
                width = 5;
            } else {
                row += QLatin1Char(' ');
                ++width;
            }
            row += word;
            width += word.size();
        }
        text += row + QLatin1Char('\n');
    };
    if (c == "run") {
        line(kOk, "finished: m02 reached with the machine on its last target");
        line(kCompileErrors, "compile errors (listed; nothing moved)");
        line(kUsage,
             "usage error, a file or profile that cannot be read, a trace that could not be "
             "written (after the run's own report), or out of memory");
        line(kAlarm,
             "an alarm stopped the run, the program ended off its target (warning 13), a "
             "motionless loop was held (warning 15), a serial link failed (--port), or Ctrl-C / "
             "SIGTERM stopped a real-time run (an E-stop, reported)");
        line(kTimeLimit, "--max-seconds ended the run (default 3600 s in --virtual-time)");
    } else if (c == "check") {
        line(kOk,
             "ok: the simulated program finished on its target, with no alarm, inside the soft "
             "limits");
        line(kCompileErrors, "compile errors (listed; nothing was checked)");
        line(kUsage, "usage error, a file or profile that cannot be read, or out of memory");
        line(kAlarm,
             "not ok: an alarm stopped the simulated program, it ended off its target (warning "
             "13), a motionless loop was held (warning 15), or the machine went outside its soft "
             "limits (each named with its line)");
        line(kTimeLimit,
             "the program did not end within --max-seconds of machine time (default 3600 s): "
             "a loop without end, or a long dwell");
    } else if (c == "compile") {
        line(kOk, "no errors (warnings may be listed)");
        line(kCompileErrors, "compile errors, each listed with its file, line and column");
        line(kUsage, "usage error, a file that cannot be read, or out of memory");
    } else if (c == "serve") {
        line(kOk, "stopped by SIGINT or SIGTERM");
        line(kUsage,
             "usage error, a profile that cannot be read, or a port or device that cannot be "
             "opened");
    } else if (c == "profile") {
        line(kOk, "the profile is valid (printed in full)");
        line(kUsage, "usage error, or a profile that cannot be read or is invalid (named)");
    } else if (c == "tune report") {
        line(kOk, "the lab sheet was written with every run, each a clean record");
        line(kUsage,
             "usage error, a run that cannot be read or has no step (named; the sheet of the "
             "others is still written), or a sheet that cannot be written (named with the "
             "reason; the old file is kept)");
        line(kAlarm,
             "the sheet was written, but a run on it is no clean record (aborted, or cut "
             "short: marked on the sheet)");
    } else if (c == "tune" || c == "tune step" || c == "tune metrics") {
        line(kOk, c == "tune step"      ? "the test ran to its end (measured)"
                  : c == "tune metrics" ? "the trace was measured, a clean record"
                                        : "step: the test ran to its end; metrics: the trace "
                                          "was measured; identify: a model was accepted; auto: "
                                          "tuned and verified in position");
        line(kUsage,
             "usage error, a profile or trace that cannot be read (named with its line and "
             "column) or written, a trace and its sidecar (NAME.run.json) that contradict each "
             "other (another run's period, machine or rows), a test refused (outside the soft "
             "limits), or a trace with no step");
        const char* metricsAlarm =
            "the trace is no clean record: its sidecar (NAME.run.json) says the test was "
            "aborted or the run ended in an alarm, off its target or by --max-seconds, or the "
            "trace was cut short (its last row without an end of line, or fewer rows than its "
            "sidecar counts); what is there is still measured and printed";
        const std::string alarm =
            c == "tune metrics"
                ? std::string(metricsAlarm)
                : std::string(
                      "step: the test was aborted (a servo alarm such as a following error, "
                      "more than 200 ms of continuous saturation, or leaving the test's "
                      "envelope); what ran is still measured and traced") +
                      (c == "tune" ? std::string("; metrics: ") + metricsAlarm +
                                         "; identify, auto, relay: an alarm stopped the "
                                         "experiment, the model fits the held-out run under 90 "
                                         "%, or a verification move did not end in position"
                                   : std::string());
        line(kAlarm, alarm.c_str());
    } else if (c == "calibrate") {
        line(kOk, "calibrated (printed; the profile written with --write-profile)");
        line(kUsage,
             "usage error, a profile that cannot be read or is not a DC table's, a port that "
             "cannot be opened, or a profile that cannot be written");
        line(kAlarm,
             "the board sent no usable stream: no count before --timeout, the line lost, or "
             "counts that measure nothing (named)");
    } else if (c == "latency") {
        line(kOk, "measured (printed)");
        line(kUsage, "usage error");
    } else {
        line(kOk, "success");
        line(kCompileErrors, "compile errors");
        line(kUsage, "usage error, a file that cannot be read, or out of memory");
        line(kAlarm,
             "run: an alarm or a warning ended the run, or it was interrupted; check: the "
             "program is not ok");
        line(kTimeLimit, "run, check: --max-seconds ended the run");
        text += QStringLiteral("  Each command's --help gives its own.\n");
    }
    return text;
}

int usageError(const char* command, const QString& message) {
    err(QStringLiteral("trilho-cli %1: %2\n").arg(QLatin1String(command), message));
    return kUsage;
}

namespace {
std::vector<std::string>& rawArguments() {
    static std::vector<std::string> arguments;
    return arguments;
}
}  // namespace

void keepRawArguments(int argc, char** argv) {
    rawArguments().assign(argv, argv + argc);
}

std::string localPath(const QString& argument) {
    // The same decoding QCoreApplication::arguments() applies: the argument whose decoding is
    // this string is where it came from.
    for (const std::string& raw : rawArguments())
        if (QString::fromLocal8Bit(raw.data(), static_cast<qsizetype>(raw.size())) == argument)
            return raw;
    return QFile::encodeName(argument).toStdString();
}

ChunkedOutput::ChunkedOutput(Sink sink, std::size_t chunkBytes)
    : sink_(std::move(sink)), chunk_(chunkBytes) {
    buffer_.reserve(chunk_ + 256);
}

ChunkedOutput::~ChunkedOutput() {
    flush();
}

void ChunkedOutput::append(std::string_view bytes) {
    buffer_.append(bytes);
    if (buffer_.size() >= chunk_) flush();
}

void ChunkedOutput::append(char c) {
    buffer_.push_back(c);
    if (buffer_.size() >= chunk_) flush();
}

void ChunkedOutput::append(const QString& text) {
    const QByteArray utf8 = text.toUtf8();
    append(std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())));
}

bool ChunkedOutput::flush() {
    if (!buffer_.empty() && ok_) ok_ = sink_(buffer_);
    buffer_.clear();
    return ok_;
}

ChunkedOutput::Sink streamSink(std::FILE* stream) {
    return [stream](std::string_view bytes) {
        return std::fwrite(bytes.data(), 1, bytes.size(), stream) == bytes.size();
    };
}

}  // namespace trilho::cli
