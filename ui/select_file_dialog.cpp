#include "ui/select_file_dialog.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFileSystemModel>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QPushButton>
#include <QStorageInfo>
#include <QTreeView>

namespace trilho {
namespace ui {

SelectFileDialog::SelectFileDialog(const QString& startFolder, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Select"));
    // 5670 x 3555 twips was 378 x 237 px: at 1.5x, the names fit (x.G and x.classic.G looked
    // the same truncated) and a path field below has its line.
    resize(567, 380);
    drives_ = new QComboBox(this);
    for (const QStorageInfo& s : QStorageInfo::mountedVolumes())
        if (s.isValid() && s.isReady()) drives_->addItem(s.rootPath());
    if (drives_->findText(QDir::rootPath()) < 0) drives_->insertItem(0, QDir::rootPath());

    dirModel_ = new QFileSystemModel(this);
    dirModel_->setFilter(QDir::AllDirs | QDir::NoDotAndDotDot);
    dirModel_->setRootPath(QDir::rootPath());
    tree_ = new QTreeView(this);
    tree_->setModel(dirModel_);
    for (int c = 1; c < dirModel_->columnCount(); ++c)
        tree_->hideColumn(c);
    tree_->header()->hide();

    fileModel_ = new QFileSystemModel(this);
    fileModel_->setFilter(QDir::Files);
    fileModel_->setNameFilterDisables(false);
    files_ = new QListView(this);
    files_->setModel(fileModel_);
    files_->setTextElideMode(Qt::ElideNone);  // a whole name, scrolled if needed, never "x…G"
    files_->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    path_ = new QLineEdit(this);
    path_->setObjectName(QStringLiteral("path"));
    pathLabel_ = new QLabel(tr("Path"), this);
    filesLabel_ = new QLabel(tr("Files"), this);
    pattern_ = new QLineEdit(QStringLiteral("*.G"), this);
    exit_ = new QPushButton(tr("E&xit"), this);
    // Sair is never the default: Enter opens the file (or folder) chosen, as the operator means.
    exit_->setAutoDefault(false);
    exit_->setDefault(false);

    auto* grid = new QGridLayout(this);
    grid->addWidget(drives_, 0, 0);
    grid->addWidget(tree_, 1, 0, 3, 1);
    grid->addWidget(files_, 0, 1, 2, 2);
    grid->addWidget(filesLabel_, 2, 1);
    grid->addWidget(pattern_, 3, 1);
    grid->addWidget(exit_, 2, 2, 2, 1);
    grid->addWidget(pathLabel_, 4, 0, 1, 3);
    grid->addWidget(path_, 5, 0, 1, 3);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);

    connect(drives_, &QComboBox::textActivated, this, &SelectFileDialog::setFolder);
    connect(tree_, &QTreeView::clicked, this,
            [this](const QModelIndex& i) { setFolder(dirModel_->filePath(i)); });
    connect(pattern_, &QLineEdit::textChanged, this, &SelectFileDialog::setPattern);
    connect(files_, &QListView::doubleClicked, this, &SelectFileDialog::openFile);
    connect(files_, &QListView::activated, this, &SelectFileDialog::openFile);  // Enter
    // Arrow keys in the tree change the folder, as a click does.
    connect(tree_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& i) {
                if (i.isValid() && dirModel_->filePath(i) != currentFolder())
                    setFolder(dirModel_->filePath(i));
            });
    connect(path_, &QLineEdit::returnPressed, this, [this] {
        const QFileInfo info(path_->text());
        if (info.isDir()) {
            setFolder(info.absoluteFilePath());
        } else if (info.isFile()) {
            selected_ = info.absoluteFilePath();
            accept();
        }
    });
    connect(exit_, &QPushButton::clicked, this, &QDialog::reject);
    setPattern(pattern_->text());
    setFolder(QDir(startFolder).exists() ? startFolder : QDir::homePath());
}

void SelectFileDialog::openFile(const QModelIndex& index) {
    if (!index.isValid()) return;
    selected_ = fileModel_->filePath(index);
    accept();
}

QString SelectFileDialog::currentFolder() const {
    return fileModel_->rootPath();
}

void SelectFileDialog::setFolder(const QString& folder) {
    const QString path = QDir(folder).absolutePath();
    files_->setRootIndex(fileModel_->setRootPath(path));
    if (path_->text() != path) path_->setText(path);
    const QModelIndex dir = dirModel_->index(path);
    tree_->setCurrentIndex(dir);
    tree_->scrollTo(dir);
    tree_->expand(dir);
}

void SelectFileDialog::setPattern(const QString& pattern) {
    if (pattern_->text() != pattern) pattern_->setText(pattern);
    QStringList filters;
    for (const QString& p : pattern.split(QLatin1Char(';'), Qt::SkipEmptyParts))
        filters << p.trimmed();
    fileModel_->setNameFilters(filters.isEmpty() ? QStringList{QStringLiteral("*")} : filters);
}

}  // namespace ui
}  // namespace trilho
