#pragma once
// Selecionar (screens.md 3): drive list over a directory tree, a file list filtered by an
// editable pattern (*.G), and Sair. A double click on a file selects it and closes the dialog;
// Sair closes it keeping the previous selection. Remembers the last folder. Beyond 1996: Enter
// opens the file chosen, arrow keys in the tree change folder, and a path field takes a
// folder or a file typed or pasted. Issue 31 item 6: an Open button (the default) beside Sair;
// the drive list is a list of places (the examples, the home folder, each mounted volume) and
// the tree is rooted at the place the folder is in, not at "/"; on a machine, programs that
// name an axis it does not have are left out, and the Files label says how many.
#include <QDialog>
#include <optional>

#include "core/gcode/compiler.h"

class QComboBox;
class QFileSystemModel;
class QLabel;
class QLineEdit;
class QListView;
class QPushButton;
class QTreeView;

namespace trilho::ui {
class MachineProgramFilter;
}

namespace trilho {
namespace ui {

class SelectFileDialog : public QDialog {
    Q_OBJECT
  public:
    explicit SelectFileDialog(const QString& startFolder, QWidget* parent = nullptr);
    QString selectedFile() const { return selected_; }
    QString currentFolder() const;
    void setFolder(const QString& folder);
    void setPattern(const QString& pattern);
    /// Lists only programs for this machine's axes (the rail's window gives its own).
    void showOnlyProgramsFor(const CompileOptions& machine);
    QPushButton* openButton() const { return open_; }
    QLabel* filesLabel() const { return filesLabel_; }
    QComboBox* placeList() const { return drives_; }
    /// The folder the tree is rooted at: the place the current folder is in.
    QString treeRoot() const;
    QListView* fileList() const { return files_; }
    QPushButton* exitButton() const { return exit_; }
    QLineEdit* pathField() const { return path_; }
    QTreeView* folderTree() const { return tree_; }

  private:
    void openFile(const QModelIndex& index);  ///< a file chosen by double click or Enter
    /// The place (an entry of the drive list) that holds `folder`: the deepest one.
    int placeOf(const QString& folder) const;
    void updateFilesLabel();
    void showOnlyThePlace();
    QComboBox* drives_;
    QTreeView* tree_;
    QListView* files_;
    QLabel* filesLabel_;
    QLineEdit *pattern_, *path_;
    QLabel* pathLabel_;
    QPushButton *open_, *exit_;
    QFileSystemModel* dirModel_;
    QFileSystemModel* fileModel_;
    MachineProgramFilter* filter_;
    QString selected_;
    QString placeRoot_;  ///< the place the tree shows, an absolute path
};

}  // namespace ui
}  // namespace trilho
