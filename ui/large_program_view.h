#pragma once
// A read-only view of a program too large for the editor (issue 19: a 1M-line program took
// 11.5 s and 847 MB in a QPlainTextEdit). It keeps the file's bytes and one offset per line,
// and paints only the lines on screen, so opening costs about the file's size plus 4 bytes a
// line and a few tens of milliseconds. It shows what the editor shows: line numbers, the
// executing line, the lines with diagnostics, and a current line that "Start from the selected
// block" uses.
#include <QAbstractScrollArea>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/gcode/diagnostic.h"

namespace trilho {
namespace ui {

/// A program's bytes with the offset of each line, built once (on any thread) and shared with
/// the compiler without a copy.
struct IndexedText {
    std::shared_ptr<const std::string> bytes = std::make_shared<const std::string>();
    std::vector<std::uint32_t> starts{0};  ///< byte offset of each line's first character
    int longestLine = 0;                   ///< characters, capped at 4096
};
/// memchr finds the line ends at memory speed (about 10 ms for 16 MB). A file ends with a line
/// end or without one; either way its last line is a line, as the compiler counts them.
IndexedText indexText(std::string bytes);

class LargeProgramView : public QAbstractScrollArea {
    Q_OBJECT
  public:
    explicit LargeProgramView(QWidget* parent = nullptr);

    void setText(IndexedText text);
    const std::shared_ptr<const std::string>& bytes() const { return text_.bytes; }
    int lineCount() const { return static_cast<int>(text_.starts.size()); }
    /// 1-based line's text without its line end; empty past the end.
    QString lineText(int line) const;

    /// 1-based line being executed, 0 for none.
    void setExecutingLine(int line);
    int executingLine() const { return executing_; }
    void setDiagnostics(const std::vector<Diagnostic>& diagnostics);
    int markedLines() const { return static_cast<int>(marked_.size()); }
    /// Makes line current and scrolls it into view (column is ignored: no caret here).
    void goToLine(int line, int column = 1);
    /// 1-based current line (clicked, or moved to with the keys).
    int currentLine() const { return current_; }
    int firstVisibleLine() const;

  protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

  private:
    void updateScrollBars();
    int visibleRows() const;
    int gutterWidth() const;
    void ensureVisible(int line);

    IndexedText text_;
    int executing_ = 0;
    int current_ = 1;
    std::vector<int> marked_;  ///< sorted 1-based lines with a diagnostic
};

}  // namespace ui
}  // namespace trilho
