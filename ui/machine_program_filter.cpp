#include "ui/machine_program_filter.h"

#include <QFile>
#include <QFileInfo>
#include <QFileSystemModel>
#include <algorithm>

namespace trilho {
namespace ui {

MachineProgramFilter::MachineProgramFilter(QFileSystemModel* files, QObject* parent)
    : QSortFilterProxyModel(parent), files_(files) {
    setSourceModel(files);
}

void MachineProgramFilter::setMachine(const std::optional<CompileOptions>& machine) {
    machine_ = machine;
    verdicts_.clear();
    invalidateFilter();
}

bool MachineProgramFilter::isOtherMachines(const QString& path) const {
    if (!machine_) return false;
    const QFileInfo info(path);
    const qint64 modifiedMs = info.lastModified().toMSecsSinceEpoch();
    if (auto it = verdicts_.constFind(path);
        it != verdicts_.constEnd() && it->size == info.size() && it->modifiedMs == modifiedMs)
        return it->other;
    Verdict verdict{info.size(), modifiedMs, false};
    QFile file(path);
    if (info.isFile() && file.open(QIODevice::ReadOnly)) {
        QByteArray head = file.read(kHeadBytes);
        // A head cut mid-line is compiled up to its last whole line.
        if (info.size() > head.size())
            head.truncate(std::max<qsizetype>(0, head.lastIndexOf('\n')));
        CompileOptions options = *machine_;
        options.maxDiagnostics = 64;
        const Program program = compile(std::string_view(head.constData(), head.size()), options);
        verdict.other =
            std::any_of(program.diagnostics.begin(), program.diagnostics.end(),
                        [](const Diagnostic& d) { return d.id == MessageId::UnknownAxis; });
    }
    verdicts_.insert(path, verdict);
    return verdict.other;
}

bool MachineProgramFilter::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const {
    if (!QSortFilterProxyModel::filterAcceptsRow(sourceRow, sourceParent)) return false;
    const QModelIndex index = files_->index(sourceRow, 0, sourceParent);
    if (!index.isValid() || files_->isDir(index)) return true;
    return !isOtherMachines(files_->filePath(index));
}

int MachineProgramFilter::hiddenIn(const QModelIndex& sourceFolder) const {
    if (!machine_) return 0;
    int hidden = 0;
    for (int r = 0; r < files_->rowCount(sourceFolder); ++r) {
        const QModelIndex index = files_->index(r, 0, sourceFolder);
        if (files_->isDir(index)) continue;
        // Files the name pattern leaves out are not counted: they are not programs here.
        if (!mapFromSource(index).isValid() && isOtherMachines(files_->filePath(index))) ++hidden;
    }
    return hidden;
}

}  // namespace ui
}  // namespace trilho
