#include "ui/program_library_panel.h"

#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "host/dnc/program_library.h"

namespace trilho {
namespace ui {

namespace {
constexpr int kHeadBytes = 4096;  ///< read of each file for its comment: the first lines only
}

ProgramLibraryPanel::ProgramLibraryPanel(QWidget* parent) : QWidget(parent) {
    folderLabel_ = new QLabel(this);
    folderLabel_->setObjectName(QStringLiteral("libraryFolder"));
    folderLabel_->setWordWrap(true);
    folderLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    list_ = new QTreeWidget(this);
    list_->setObjectName(QStringLiteral("libraryList"));
    list_->setColumnCount(4);
    list_->setRootIsDecorated(false);
    list_->setUniformRowHeights(true);
    list_->setSortingEnabled(false);  // by number, always
    list_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    list_->header()->setStretchLastSection(false);
    list_->header()->setSectionResizeMode(2, QHeaderView::Stretch);
    open_ = new QPushButton(this);
    open_->setObjectName(QStringLiteral("libraryOpen"));
    open_->setEnabled(false);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(open_);
    buttons->addStretch();
    auto* v = new QVBoxLayout(this);
    v->addWidget(folderLabel_);
    v->addWidget(list_, 1);
    v->addLayout(buttons);
    connect(list_, &QTreeWidget::itemDoubleClicked, this, [this] { openCurrent(); });
    connect(list_, &QTreeWidget::currentItemChanged, this,
            [this](QTreeWidgetItem* item) { open_->setEnabled(item != nullptr); });
    connect(open_, &QPushButton::clicked, this, &ProgramLibraryPanel::openCurrent);
    // A download is written by rename (QSaveFile): the folder changes. An edit in place
    // changes the file only: both are watched.
    connect(&watcher_, &QFileSystemWatcher::directoryChanged, this, &ProgramLibraryPanel::refresh);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, &ProgramLibraryPanel::refresh);
    retranslate();
}

void ProgramLibraryPanel::setFolder(const QString& dir) {
    dir_ = QDir::cleanPath(dir);
    refresh();
}

QString ProgramLibraryPanel::firstComment(const QByteArray& head) {
    for (const QByteArray& raw : head.split('\n')) {
        const QString line = QString::fromUtf8(raw).trimmed();
        if (line.isEmpty() || line == QLatin1String("%")) continue;
        const auto paren = line.indexOf(QLatin1Char('('));
        const auto semi = line.indexOf(QLatin1Char(';'));
        if (paren < 0 && semi < 0) continue;
        if (semi >= 0 && (paren < 0 || semi < paren)) return line.mid(semi + 1).trimmed();
        const auto close = line.indexOf(QLatin1Char(')'), paren);
        return line.mid(paren + 1, close < 0 ? -1 : close - paren - 1).trimmed();
    }
    return {};
}

void ProgramLibraryPanel::refresh() {
    if (!watcher_.directories().isEmpty()) watcher_.removePaths(watcher_.directories());
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    const QString current =
        list_->currentItem() ? list_->currentItem()->data(0, Qt::UserRole).toString() : QString();
    list_->clear();
    folderLabel_->setText(dir_.isEmpty() ? QString() : tr("Folder: %1").arg(dir_));
    if (dir_.isEmpty()) return;
    QDir dir(dir_);
    if (!dir.exists()) {
        // Watch the nearest existing parent: the folder shows up with the first download.
        folderLabel_->setText(tr("Folder: %1 (not created yet)").arg(dir_));
        // (QDir::cdUp refuses a parent that does not exist: walk the path's text instead.)
        QString parent = QFileInfo(dir.absolutePath()).path();
        while (!QFileInfo::exists(parent) && parent != QFileInfo(parent).path())
            parent = QFileInfo(parent).path();
        if (QFileInfo::exists(parent)) watcher_.addPath(parent);
        return;
    }
    watcher_.addPath(dir.absolutePath());
    const QLocale locale;
    // The library's own list: an entry it will not serve (a link, a folder, a FIFO...) is shown
    // with the reason, greyed and not openable, so the operator sees why program N does not run.
    const dnc::ProgramLibrary library(dir_, CompileOptions{});
    for (const dnc::LibraryEntry& e : library.list()) {
        const QFileInfo info(e.path);
        QString what;
        if (e.refused.isEmpty()) {
            if (const auto head = library.readHead(e.number, kHeadBytes))
                what = firstComment(*head);
            if (what.isEmpty())
                what = tr("%1 bytes, no comment").arg(locale.toString(qint64(e.sizeBytes)));
        } else {
            what = tr("Not served: %1").arg(e.refused);
        }
        auto* item = new QTreeWidgetItem(list_);
        item->setText(0, QString::number(e.number));
        item->setTextAlignment(0, Qt::AlignRight | Qt::AlignVCenter);
        item->setText(1, info.fileName());
        item->setText(2, what);
        item->setToolTip(2, what);
        if (e.refused.isEmpty()) {
            // To the minute: the comment column keeps the width. (A refused entry has none: a
            // link's would be its target's.)
            item->setText(3, info.lastModified().toString(QStringLiteral("yyyy-MM-dd HH:mm")));
            item->setToolTip(3, info.lastModified().toString(Qt::ISODate));
            item->setData(0, Qt::UserRole, info.absoluteFilePath());
            if (info.absoluteFilePath() == current) list_->setCurrentItem(item);
            watcher_.addPath(info.absoluteFilePath());
        } else {
            item->setFlags(item->flags() & ~(Qt::ItemIsEnabled | Qt::ItemIsSelectable));
        }
    }
    open_->setEnabled(list_->currentItem() != nullptr);
}

void ProgramLibraryPanel::openCurrent() {
    if (QTreeWidgetItem* item = list_->currentItem())
        emit openRequested(item->data(0, Qt::UserRole).toString());
}

void ProgramLibraryPanel::retranslate() {
    list_->setHeaderLabels({tr("No."), tr("File"), tr("Comment or size"), tr("Modified")});
    open_->setText(tr("Open in the editor"));
    refresh();  // the "not created yet" and size texts
}

void ProgramLibraryPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
