#include "host/dnc/program_library.h"

#include <QDir>
#include <QRegularExpression>
#include <algorithm>

#include "core/gcode/source_file.h"
#include "host/dnc/folder_entry.h"

namespace trilho::dnc {

QString ProgramLibrary::nameOf(int number) const {
    return QStringLiteral("%1.G").arg(number, 4, 10, QLatin1Char('0'));
}

QString ProgramLibrary::pathOf(int number) const {
    return QDir(dir_).filePath(nameOf(number));
}

QString ProgramLibrary::badNumber(int number) const {
    if (number >= 0 && number <= kMaxNumber) return {};
    return QStringLiteral("no program number %1 (programs are 0 to %2)")
        .arg(number)
        .arg(kMaxNumber);
}

bool ProgramLibrary::exists(int number) const {
    if (!badNumber(number).isEmpty()) return false;
    const EntryStat st = statFolderEntry(dir_, nameOf(number));
    return st.kind == EntryKind::Regular && refusalOf(st).isEmpty();
}

std::shared_ptr<const Program> ProgramLibrary::compileText(const QByteArray& source) const {
    return std::make_shared<const Program>(compile(
        std::string_view(source.constData(), static_cast<std::size_t>(source.size())), options_));
}

std::optional<QByteArray> ProgramLibrary::read(int number, qint64 maxBytes, QString* error) const {
    if (QString bad = badNumber(number); !bad.isEmpty()) {
        if (error) *error = bad;
        return std::nullopt;
    }
    EntryRead r = readFolderEntry(dir_, nameOf(number), maxBytes, Overlong::Refuse,
                                  QStringLiteral("file records"));
    if (!r.ok) {
        if (error) *error = r.error;
        return std::nullopt;
    }
    return std::move(r.bytes);
}

std::optional<QByteArray> ProgramLibrary::readHead(int number, qint64 maxBytes,
                                                   QString* error) const {
    if (QString bad = badNumber(number); !bad.isEmpty()) {
        if (error) *error = bad;
        return std::nullopt;
    }
    EntryRead r = readFolderEntry(dir_, nameOf(number), maxBytes, Overlong::Truncate, QString());
    if (!r.ok) {
        if (error) *error = r.error;
        return std::nullopt;
    }
    return std::move(r.bytes);
}

std::optional<std::shared_ptr<const Program>> ProgramLibrary::load(int number,
                                                                   QString* error) const {
    // At most kMaxSourceBytes, as any program run (a huge file must not exhaust the server).
    if (QString bad = badNumber(number); !bad.isEmpty()) {
        if (error) *error = bad;
        return std::nullopt;
    }
    const EntryRead r = readFolderEntry(dir_, nameOf(number), kMaxSourceBytes, Overlong::Refuse,
                                        QStringLiteral("a program file"));
    if (!r.ok) {
        if (error) *error = r.error;
        return std::nullopt;
    }
    return compileText(r.bytes);
}

bool ProgramLibrary::save(int number, const QByteArray& source, QString* error) const {
    if (QString bad = badNumber(number); !bad.isEmpty()) {
        if (error) *error = bad;
        return false;
    }
    if (!QDir().mkpath(dir_)) {
        if (error) *error = QStringLiteral("cannot create the library folder '%1'").arg(dir_);
        return false;
    }
    return replaceFolderEntry(dir_, nameOf(number), source, error);
}

std::vector<LibraryEntry> ProgramLibrary::list() const {
    std::vector<LibraryEntry> entries;
    static const QRegularExpression kName(QStringLiteral("^(\\d{4})\\.G$"));
    // System: links (dangling ones too), FIFOs, sockets and devices are listed, with why they
    // are not served, so the operator sees why program N does not run.
    const QStringList names = QDir(dir_).entryList(
        {QStringLiteral("*.G")},
        QDir::AllEntries | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
    for (const QString& name : names) {
        const auto m = kName.match(name);
        if (!m.hasMatch()) continue;  // only programs by number: what the link can run
        LibraryEntry e;
        e.number = m.captured(1).toInt();
        e.path = pathOf(e.number);
        const EntryStat st = statFolderEntry(dir_, name);
        e.sizeBytes = st.sizeBytes;
        e.refused = refusalOf(st);
        entries.push_back(std::move(e));
    }
    std::sort(entries.begin(), entries.end(),
              [](const LibraryEntry& a, const LibraryEntry& b) { return a.number < b.number; });
    return entries;
}

}  // namespace trilho::dnc
