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
#include <QVBoxLayout>

#include "host/common/data_paths.h"
#include "ui/machine_program_filter.h"

namespace trilho {
namespace ui {

SelectFileDialog::SelectFileDialog(const QString& startFolder, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Select"));
    // 5670 x 3555 twips was 378 x 237 px: at 1.5x, the names fit (x.G and x.classic.G looked
    // the same truncated) and a path field below has its line.
    resize(567, 380);
    // The places: the examples, the home folder, then each mounted volume (the VB's drives).
    drives_ = new QComboBox(this);
    drives_->setObjectName(QStringLiteral("places"));
    const auto addPlace = [this](const QString& label, const QString& path) {
        const QString clean = QDir(path).absolutePath();
        if (!QFileInfo(clean).isDir() || drives_->findData(clean) >= 0) return;
        drives_->addItem(label.isEmpty() ? clean : QStringLiteral("%1 (%2)").arg(label, clean),
                         clean);
        drives_->setItemData(drives_->count() - 1, clean, Qt::ToolTipRole);
    };
    addPlace(tr("Examples"), examplesDir());
    addPlace(tr("Home folder"), QDir::homePath());
    addPlace(QString(), QDir::rootPath());
    for (const QStorageInfo& s : QStorageInfo::mountedVolumes())
        if (s.isValid() && s.isReady()) addPlace(QString(), s.rootPath());

    dirModel_ = new QFileSystemModel(this);
    dirModel_->setFilter(QDir::AllDirs | QDir::NoDotAndDotDot);
    tree_ = new QTreeView(this);
    tree_->setModel(dirModel_);
    for (int c = 1; c < dirModel_->columnCount(); ++c)
        tree_->hideColumn(c);
    tree_->header()->hide();

    fileModel_ = new QFileSystemModel(this);
    fileModel_->setFilter(QDir::Files);
    fileModel_->setNameFilterDisables(false);
    filter_ = new MachineProgramFilter(fileModel_, this);
    files_ = new QListView(this);
    files_->setModel(filter_);
    files_->setTextElideMode(Qt::ElideNone);  // a whole name, scrolled if needed, never "x…G"
    files_->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    path_ = new QLineEdit(this);
    path_->setObjectName(QStringLiteral("path"));
    pathLabel_ = new QLabel(tr("Path"), this);
    filesLabel_ = new QLabel(tr("Files"), this);
    filesLabel_->setWordWrap(true);  // "Files (8 for other machines not shown)" in its column
    pattern_ = new QLineEdit(QStringLiteral("*.G"), this);
    open_ = new QPushButton(tr("&Open"), this);
    open_->setObjectName(QStringLiteral("open"));
    open_->setEnabled(false);  // until a file is chosen in the list
    open_->setDefault(true);
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
    auto* buttons = new QVBoxLayout;
    buttons->addWidget(open_);
    buttons->addWidget(exit_);
    grid->addLayout(buttons, 2, 2, 2, 1);
    grid->addWidget(pathLabel_, 4, 0, 1, 3);
    grid->addWidget(path_, 5, 0, 1, 3);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);

    connect(drives_, &QComboBox::activated, this,
            [this](int i) { setFolder(drives_->itemData(i).toString()); });
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
    connect(open_, &QPushButton::clicked, this, [this] { openFile(files_->currentIndex()); });
    connect(files_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& i) { open_->setEnabled(i.isValid()); });
    // The count of other machines' programs follows the listing as it loads and changes.
    for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
        connect(filter_, signal, this, &SelectFileDialog::updateFilesLabel);
    connect(filter_, &QAbstractItemModel::modelReset, this, &SelectFileDialog::updateFilesLabel);
    connect(filter_, &QAbstractItemModel::layoutChanged, this, &SelectFileDialog::updateFilesLabel);
    connect(fileModel_, &QFileSystemModel::directoryLoaded, this,
            &SelectFileDialog::updateFilesLabel);
    // Folders the tree's model finds later beside the place stay out of view.
    connect(dirModel_, &QAbstractItemModel::rowsInserted, this, [this](const QModelIndex& under) {
        if (under == tree_->rootIndex()) showOnlyThePlace();
    });
    setPattern(pattern_->text());
    setFolder(QDir(startFolder).exists() ? startFolder : QDir::homePath());
}

void SelectFileDialog::openFile(const QModelIndex& index) {
    if (!index.isValid()) return;
    selected_ = fileModel_->filePath(filter_->mapToSource(index));
    accept();
}

void SelectFileDialog::showOnlyProgramsFor(const CompileOptions& machine) {
    filter_->setMachine(machine);
    setFolder(currentFolder());
}

int SelectFileDialog::placeOf(const QString& folder) const {
    int best = -1;
    qsizetype bestLength = -1;
    for (int i = 0; i < drives_->count(); ++i) {
        const QString place = drives_->itemData(i).toString();
        const bool inside =
            folder == place ||
            folder.startsWith(place.endsWith(QLatin1Char('/')) ? place : place + QLatin1Char('/'));
        if (inside && place.size() > bestLength) best = i, bestLength = place.size();
    }
    return best;
}

QString SelectFileDialog::treeRoot() const {
    return placeRoot_;
}

void SelectFileDialog::showOnlyThePlace() {
    // The tree is rooted at the place's parent with the place its one visible node, so the place
    // itself shows (and opens) at the top as the VB's directory list showed its drive.
    const QModelIndex place = dirModel_->index(placeRoot_);
    const QModelIndex parent = place.parent();
    if (tree_->rootIndex() != parent) tree_->setRootIndex(parent);
    for (int r = 0; r < dirModel_->rowCount(parent); ++r)
        tree_->setRowHidden(r, parent, dirModel_->index(r, 0, parent) != place);
    tree_->expand(place);
}

void SelectFileDialog::updateFilesLabel() {
    const int hidden = filter_->hiddenIn(fileModel_->index(currentFolder()));
    filesLabel_->setText(hidden == 0 ? tr("Files")
                                     : tr("Files (%1 for other machines not shown)").arg(hidden));
}

QString SelectFileDialog::currentFolder() const {
    return fileModel_->rootPath();
}

void SelectFileDialog::setFolder(const QString& folder) {
    const QString path = QDir(folder).absolutePath();
    // The tree shows the place the folder is in, from that place down.
    const int place = placeOf(path);
    const QString root = place < 0 ? QDir::rootPath() : drives_->itemData(place).toString();
    if (place >= 0) drives_->setCurrentIndex(place);
    if (placeRoot_ != root) {
        placeRoot_ = root;
        dirModel_->setRootPath(root);
        showOnlyThePlace();
    }
    files_->setRootIndex(filter_->mapFromSource(fileModel_->setRootPath(path)));
    open_->setEnabled(false);
    updateFilesLabel();
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
