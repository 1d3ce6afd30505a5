#include "app/dnc/program_library.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>

#include "core/gcode/source_file.h"

namespace trilho::dnc {

QString ProgramLibrary::pathOf(int number) const {
    return QDir(dir_).filePath(QStringLiteral("%1.G").arg(number, 4, 10, QLatin1Char('0')));
}

bool ProgramLibrary::exists(int number) const {
    return QFile::exists(pathOf(number));
}

std::shared_ptr<const Program> ProgramLibrary::compileText(const QByteArray& source) const {
    return std::make_shared<const Program>(compile(
        std::string_view(source.constData(), static_cast<std::size_t>(source.size())), options_));
}

std::optional<QByteArray> ProgramLibrary::read(int number, qint64 maxBytes) const {
    const SourceFile f = readRegularFile(QFile::encodeName(pathOf(number)).toStdString(), "program",
                                         maxBytes, "file records");
    if (!f.ok) return std::nullopt;
    return QByteArray(f.bytes.data(), static_cast<qsizetype>(f.bytes.size()));
}

std::optional<std::shared_ptr<const Program>> ProgramLibrary::load(int number,
                                                                   QString* error) const {
    // Regular files only, at most kMaxSourceBytes: a FIFO dropped in the folder must not block
    // the server, nor a huge file exhaust it.
    const SourceFile f = readSourceFile(QFile::encodeName(pathOf(number)).toStdString());
    if (!f.ok) {
        if (error) *error = QString::fromStdString(f.error);
        return std::nullopt;
    }
    return compileText(QByteArray(f.bytes.data(), static_cast<qsizetype>(f.bytes.size())));
}

bool ProgramLibrary::save(int number, const QByteArray& source, QString* error) const {
    if (!QDir().mkpath(dir_)) {
        if (error) *error = QStringLiteral("cannot create %1").arg(dir_);
        return false;
    }
    QSaveFile f(pathOf(number));
    if (!f.open(QIODevice::WriteOnly) || f.write(source) != source.size() || !f.commit()) {
        if (error) *error = f.errorString();
        return false;
    }
    return true;
}

}  // namespace trilho::dnc
