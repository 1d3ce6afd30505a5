#include "app/cli/cli_output.h"

#include <QCommandLineParser>
#include <QFile>
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
        out(parser.helpText());
        return kOk;
    }
    return std::nullopt;
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
