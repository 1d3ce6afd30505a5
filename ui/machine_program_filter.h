#pragma once
// The Select dialog's file list for one machine (issue 31 item 6): a program that names an
// axis the machine does not have (the XY examples' y, on the rail) is another machine's, and
// is left out of the list; the dialog says how many were. Folders always pass.
#include <QHash>
#include <QSortFilterProxyModel>
#include <optional>

#include "core/gcode/compiler.h"

class QFileSystemModel;

namespace trilho {
namespace ui {

class MachineProgramFilter : public QSortFilterProxyModel {
    Q_OBJECT
  public:
    /// The first bytes of a file read to tell whose it is: a program names its axes in its first
    /// moves, and a folder of large files is listed without reading them whole (16 KiB, about
    /// 600 lines; compiling them takes well under a millisecond).
    static constexpr qint64 kHeadBytes = 16 * 1024;

    explicit MachineProgramFilter(QFileSystemModel* files, QObject* parent = nullptr);
    /// Lists only the programs for this machine's axes; without it (nullopt) every file.
    void setMachine(const std::optional<CompileOptions>& machine);
    /// Files of the folder at `sourceFolder` (a source index) left out as other machines'.
    int hiddenIn(const QModelIndex& sourceFolder) const;
    /// The file at `path` names an axis the machine lacks (false without a machine, or when it
    /// cannot be read: a file the operator cannot tell about stays in view).
    bool isOtherMachines(const QString& path) const;

  protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

  private:
    struct Verdict {
        qint64 size = -1;
        qint64 modifiedMs = 0;
        bool other = false;
    };
    QFileSystemModel* files_;
    std::optional<CompileOptions> machine_;
    mutable QHash<QString, Verdict> verdicts_;  ///< by path, kept while size and time hold
};

}  // namespace ui
}  // namespace trilho
