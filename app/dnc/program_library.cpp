#include "app/dnc/program_library.h"

#include <QDir>
#include <QFile>
#include <QSaveFile>

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
    QFile f(pathOf(number));
    if (!f.open(QIODevice::ReadOnly)) return std::nullopt;
    return f.read(maxBytes);
}

std::optional<std::shared_ptr<const Program>> ProgramLibrary::load(int number,
                                                                   QString* error) const {
    QFile f(pathOf(number));
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) *error = f.errorString();
        return std::nullopt;
    }
    return compileText(f.readAll());
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
