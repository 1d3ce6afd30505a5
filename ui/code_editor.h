#pragma once
// A plain-text G-code editor with line numbers, the executing line highlighted and compile
// diagnostics underlined on their lines.
#include <QPlainTextEdit>

#include "core/gcode/diagnostic.h"

namespace trilho {
namespace ui {

class CodeEditor : public QPlainTextEdit {
    Q_OBJECT
  public:
    explicit CodeEditor(QWidget* parent = nullptr);
    int lineNumberAreaWidth() const;
    void paintLineNumbers(QPaintEvent* event);
    /// 1-based line being executed, 0 for none.
    void setExecutingLine(int line);
    void setDiagnostics(const std::vector<Diagnostic>& diagnostics);
    void goToLine(int line, int column = 1);
    int executingLine() const { return executing_; }
    int markedLines() const { return static_cast<int>(marked_.size()); }

  protected:
    void resizeEvent(QResizeEvent* event) override;

  private:
    void refreshSelections();
    QWidget* numbers_;
    int executing_ = 0;
    std::vector<std::pair<int, int>> marked_;  ///< line, column
};

}  // namespace ui
}  // namespace trilho
