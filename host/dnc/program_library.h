#pragma once
// The machine's programs by number (machine.md 3.6: "a program held in the machine's memory,
// chosen by an integer"): programs/0042.G in a folder. Read and compiled when run, written
// atomically only once it compiled. Only regular files inside the folder are served and
// replaced (issue 20 item 8): an entry that is a link, a folder, a FIFO, a socket or a device
// is refused with a message naming it, and a download never writes through a link
// (host/dnc/folder_entry.h).
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/gcode/program.h"

namespace trilho::dnc {

/// One NNNN.G entry of the folder, as list() sees it.
struct LibraryEntry {
    int number = 0;
    QString path;  ///< dir/NNNN.G
    std::int64_t sizeBytes = 0;
    QString refused;  ///< why it is not served ("is a symbolic link: ..."); empty when it is
};

class ProgramLibrary {
  public:
    /// Program numbers are four digits: 0000.G to 9999.G.
    static constexpr int kMaxNumber = 9999;

    ProgramLibrary(QString dir, CompileOptions options) : dir_(std::move(dir)), options_(options) {}

    const QString& dir() const { return dir_; }
    /// dir/NNNN.G, four digits.
    QString pathOf(int number) const;
    /// Program `number` is a regular file in the folder (a link to one is not).
    bool exists(int number) const;
    /// Reads and compiles program `number` (a regular file of at most kMaxSourceBytes); nullopt
    /// with the reason, naming the entry, when it is missing or refused.
    std::optional<std::shared_ptr<const Program>> load(int number, QString* error) const;
    /// The stored text of program `number`; nullopt (with the reason when error is given) when
    /// missing, refused or longer than maxBytes.
    std::optional<QByteArray> read(int number, qint64 maxBytes, QString* error = nullptr) const;
    /// The first maxBytes of program `number` at most (the screens' list shows its comment).
    std::optional<QByteArray> readHead(int number, qint64 maxBytes, QString* error = nullptr) const;
    std::shared_ptr<const Program> compileText(const QByteArray& source) const;
    /// Writes the source atomically (the folder is created when missing). Refused, with the
    /// entry named, when the entry is there and not a regular file.
    bool save(int number, const QByteArray& source, QString* error) const;
    /// Every NNNN.G entry of the folder by number, those refused with their reason (empty when
    /// the folder is missing).
    std::vector<LibraryEntry> list() const;

  private:
    QString nameOf(int number) const;
    QString badNumber(int number) const;
    QString dir_;
    CompileOptions options_;
};

}  // namespace trilho::dnc
