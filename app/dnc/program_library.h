#pragma once
// The machine's programs by number (machine.md 3.6: "a program held in the machine's memory,
// chosen by an integer"): programs/0042.G in a folder. Read and compiled when run, written
// atomically (QSaveFile) only once it compiled.
#include <QString>
#include <memory>
#include <optional>

#include "core/gcode/compiler.h"
#include "core/gcode/program.h"

namespace trilho::dnc {

class ProgramLibrary {
  public:
    ProgramLibrary(QString dir, CompileOptions options) : dir_(std::move(dir)), options_(options) {}

    const QString& dir() const { return dir_; }
    /// dir/NNNN.G, four digits.
    QString pathOf(int number) const;
    bool exists(int number) const;
    /// Reads and compiles program `number`; nullopt when there is no such file.
    std::optional<std::shared_ptr<const Program>> load(int number, QString* error) const;
    /// The stored text of program `number`; nullopt when missing, not a regular file or longer
    /// than maxBytes.
    std::optional<QByteArray> read(int number, qint64 maxBytes) const;
    std::shared_ptr<const Program> compileText(const QByteArray& source) const;
    /// Writes the source atomically (the folder is created when missing).
    bool save(int number, const QByteArray& source, QString* error) const;

  private:
    QString dir_;
    CompileOptions options_;
};

}  // namespace trilho::dnc
