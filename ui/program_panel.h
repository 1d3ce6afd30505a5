#pragma once
// The program view and editor: line numbers, syntax colours, the executing block highlighted,
// diagnostics marked on their lines and listed (a click jumps there), atomic save. A program
// too large to edit (kLargeProgramBytes or kLargeProgramLines) opens in a read-only view.
#include <QDateTime>
#include <QWidget>

#include <memory>
#include <string>

#include "core/gcode/program.h"

class QLabel;
class QListWidget;
class QPushButton;
class QStackedWidget;

namespace trilho {
namespace ui {

class CodeEditor;
class LargeProgramView;

/// Above either bound a program opens read-only in LargeProgramView: a QPlainTextEdit holding
/// 50,000 lines already takes about 40 MB and half a second; the rail's programs are hundreds
/// of lines.
inline constexpr std::size_t kLargeProgramBytes = 2 * 1024 * 1024;
inline constexpr int kLargeProgramLines = 50000;
/// A file larger than this is read and indexed on a worker thread, so that the screens (E-stop
/// and Stop among them) keep answering while it loads.
inline constexpr qint64 kAsyncLoadBytes = 1024 * 1024;

class ProgramPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ProgramPanel(QWidget* parent = nullptr);
    /// Opens path. A small file is read at once (false and error if it cannot be); a large
    /// one returns true at once and ends with loaded() or loadFailed().
    bool load(const QString& path, QString* error);
    bool loading() const { return loading_; }
    bool save(QString* error);
    QString path() const { return path_; }
    QString text() const;
    /// The program's bytes as the compiler reads them (the editor's text, saved or not).
    std::shared_ptr<const std::string> source() const;
    /// True while the program is shown read-only because it is too large to edit.
    bool readOnlyLarge() const { return large_mode_; }
    /// Counts the editor's edits (and each load): a compile started at one revision is stale
    /// at another.
    int revision() const;
    /// A read-only large program whose file changed (time or size) since it was read.
    bool changedOnDisk() const;
    bool dirty() const;
    void showDiagnostics(const std::vector<Diagnostic>& diagnostics, const QStringList& messages);
    void setExecutingLine(int line);
    /// 1-based line of the cursor (for "start from the selected block").
    int cursorLine() const;
    CodeEditor* editor() const { return editor_; }
    LargeProgramView* largeView() const { return large_; }
    QListWidget* diagnosticsList() const { return list_; }

  signals:
    void startFromCursorRequested();
    void dirtyChanged(bool dirty);
    void loaded();
    void loadFailed(const QString& error);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    struct Loaded;
    static Loaded read(const QString& path);
    void apply(Loaded loaded);
    void goToLine(int line, int column);
    CodeEditor* editor_;
    LargeProgramView* large_;
    QStackedWidget* views_;
    QLabel* largeNote_;
    bool large_mode_ = false;
    bool loading_ = false;
    int loads_ = 0;
    QDateTime loadedModified_;
    qint64 loadedSize_ = -1;
    int generation_ = 0;  ///< a newer load makes an older one's result stale
    QListWidget* list_;
    QPushButton *save_, *startHere_;
    QString path_;
};

}  // namespace ui
}  // namespace trilho
