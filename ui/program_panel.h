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

/// Above either bound a program opens read-only in LargeProgramView (issue 30 item 3): no
/// handler may hold the screens' thread, and with it the E-stop key, longer than 20 ms, and the
/// editor takes its whole text at once (its colours with it), on that thread: measured in the
/// rail's window on the 2-core development machine (other builds running), 1,000 lines 10 ms,
/// 2,000 lines 15-19 ms, 9,000 lines 150-230 ms, 49,000 lines 0.4-0.5 s; 2,000 lines of 36
/// characters 14-17 ms. The shipped programs are at most 82 lines; the 1996 ones hundreds.
inline constexpr std::size_t kLargeProgramBytes = 32 * 1024;
inline constexpr int kLargeProgramLines = 1000;
/// A file larger than this is read and indexed on a worker thread, so that the screens (E-stop
/// and Stop among them) keep answering while it loads: every file the editor may not take.
inline constexpr qint64 kAsyncLoadBytes = static_cast<qint64>(kLargeProgramBytes);
/// Diagnostics the screens list (and mark) at most; the rest are counted ("... and 800 more
/// diagnostic(s) not listed") and the summary counts all: listing 1,000 held the screens'
/// thread 30-50 ms, 100 3-5 ms.
inline constexpr int kListedDiagnostics = 100;

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
    /// The compile's diagnostics (at most kListedDiagnostics) and, when omitted is not 0, a last
    /// line saying how many more were found.
    void showDiagnostics(const std::vector<Diagnostic>& diagnostics, const QStringList& messages,
                         std::size_t omitted = 0);
    void setExecutingLine(int line);
    /// Scrolls to the source line (1-based) and puts the cursor there (a timeline mark).
    void showLine(int line) { goToLine(line, 1); }
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
