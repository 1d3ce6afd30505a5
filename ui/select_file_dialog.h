#pragma once
// Selecionar (screens.md 3): drive list over a directory tree, a file list filtered by an
// editable pattern (*.G), and Sair. A double click on a file selects it and closes the dialog;
// Sair closes it keeping the previous selection. Remembers the last folder. Beyond 1996: Enter
// opens the file chosen, arrow keys in the tree change folder, and a path field takes a
// folder or a file typed or pasted.
#include <QDialog>

class QComboBox;
class QFileSystemModel;
class QLabel;
class QLineEdit;
class QListView;
class QPushButton;
class QTreeView;

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
    QListView* fileList() const { return files_; }
    QPushButton* exitButton() const { return exit_; }
    QLineEdit* pathField() const { return path_; }
    QTreeView* folderTree() const { return tree_; }

  private:
    void openFile(const QModelIndex& index);  ///< a file chosen by double click or Enter
    QComboBox* drives_;
    QTreeView* tree_;
    QListView* files_;
    QLabel* filesLabel_;
    QLineEdit *pattern_, *path_;
    QLabel* pathLabel_;
    QPushButton* exit_;
    QFileSystemModel* dirModel_;
    QFileSystemModel* fileModel_;
    QString selected_;
};

}  // namespace ui
}  // namespace trilho
