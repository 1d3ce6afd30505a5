#pragma once
// The DNC program library at the screens (issue 13): the NNNN.G files of the programs folder
// by number, with their first comment line (or size) and modification time, refreshed when
// the folder changes (a download, a copy). A double click or Open loads one in the editor.
#include <QFileSystemWatcher>
#include <QWidget>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace trilho {
namespace ui {

class ProgramLibraryPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ProgramLibraryPanel(QWidget* parent = nullptr);

    /// Lists and watches dir (it need not exist yet: its parent is watched until it does).
    void setFolder(const QString& dir);
    const QString& folder() const { return dir_; }
    void refresh();
    QTreeWidget* list() const { return list_; }
    QPushButton* openButton() const { return open_; }
    /// The first comment of a G-code text ("( ... )" or "; ..."), empty when none in its first
    /// lines: what a program says it is.
    static QString firstComment(const QByteArray& head);

  signals:
    /// The operator asked for this program in the editor.
    void openRequested(const QString& path);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    void openCurrent();
    QString dir_;
    QLabel* folderLabel_;
    QTreeWidget* list_;
    QPushButton* open_;
    QFileSystemWatcher watcher_;
};

}  // namespace ui
}  // namespace trilho
