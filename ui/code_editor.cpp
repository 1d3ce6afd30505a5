#include "ui/code_editor.h"

#include <QPainter>
#include <QTextBlock>
#include "ui/fixed_font.h"

namespace trilho {
namespace ui {

namespace {
class LineNumberArea : public QWidget {
  public:
    explicit LineNumberArea(CodeEditor* editor) : QWidget(editor), editor_(editor) {}
    QSize sizeHint() const override { return {editor_->lineNumberAreaWidth(), 0}; }

  protected:
    void paintEvent(QPaintEvent* e) override { editor_->paintLineNumbers(e); }

  private:
    CodeEditor* editor_;
};
}  // namespace

CodeEditor::CodeEditor(QWidget* parent)
    : QPlainTextEdit(parent), numbers_(new LineNumberArea(this)) {
    setFont(fixedFont());
    setLineWrapMode(QPlainTextEdit::NoWrap);
    connect(this, &QPlainTextEdit::blockCountChanged, this,
            [this] { setViewportMargins(lineNumberAreaWidth(), 0, 0, 0); });
    connect(this, &QPlainTextEdit::updateRequest, this, [this](const QRect& r, int dy) {
        if (dy)
            numbers_->scroll(0, dy);
        else
            numbers_->update(0, r.y(), numbers_->width(), r.height());
    });
    setViewportMargins(lineNumberAreaWidth(), 0, 0, 0);
}

int CodeEditor::lineNumberAreaWidth() const {
    int digits = 1;
    for (int max = std::max(1, blockCount()); max >= 10; max /= 10)
        ++digits;
    return 8 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(digits, 3);
}

void CodeEditor::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    const QRect cr = contentsRect();
    numbers_->setGeometry(QRect(cr.left(), cr.top(), lineNumberAreaWidth(), cr.height()));
}

void CodeEditor::paintLineNumbers(QPaintEvent* event) {
    QPainter p(numbers_);
    p.fillRect(event->rect(), QColor(235, 235, 235));
    QTextBlock block = firstVisibleBlock();
    int number = block.blockNumber() + 1;
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    int bottom = top + qRound(blockBoundingRect(block).height());
    while (block.isValid() && top <= event->rect().bottom()) {
        if (block.isVisible() && bottom >= event->rect().top()) {
            const bool bad = std::any_of(marked_.begin(), marked_.end(),
                                         [&](auto& m) { return m.first == number; });
            p.setPen(number == executing_ ? QColor(0, 0, 160)
                     : bad                ? QColor(200, 0, 0)
                                          : QColor(120, 120, 120));
            p.drawText(0, top, numbers_->width() - 4, fontMetrics().height(), Qt::AlignRight,
                       QString::number(number));
        }
        block = block.next();
        top = bottom;
        bottom = top + qRound(blockBoundingRect(block).height());
        ++number;
    }
}

void CodeEditor::setExecutingLine(int line) {
    if (line == executing_) return;
    executing_ = line;
    refreshSelections();
    if (line > 0) {
        const QTextBlock b = document()->findBlockByNumber(line - 1);
        if (b.isValid()) {
            QTextCursor c(b);
            setTextCursor(c);
            ensureCursorVisible();
        }
    }
    numbers_->update();
}

void CodeEditor::setDiagnostics(const std::vector<Diagnostic>& diagnostics) {
    marked_.clear();
    for (const auto& d : diagnostics)
        marked_.push_back({static_cast<int>(d.line), static_cast<int>(d.column)});
    refreshSelections();
    numbers_->update();
}

void CodeEditor::goToLine(int line, int column) {
    const QTextBlock b = document()->findBlockByNumber(line - 1);
    if (!b.isValid()) return;
    QTextCursor c(b);
    c.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor,
                   std::max(0, std::min(column - 1, b.length() - 1)));
    setTextCursor(c);
    ensureCursorVisible();
    setFocus();
}

void CodeEditor::refreshSelections() {
    QList<QTextEdit::ExtraSelection> selections;
    for (const auto& [line, column] : marked_) {
        const QTextBlock b = document()->findBlockByNumber(line - 1);
        if (!b.isValid()) continue;
        QTextEdit::ExtraSelection s;
        s.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        s.format.setUnderlineColor(Qt::red);
        s.format.setBackground(QColor(255, 230, 230));
        s.format.setProperty(QTextFormat::FullWidthSelection, true);
        s.cursor = QTextCursor(b);
        selections << s;
    }
    if (executing_ > 0) {
        const QTextBlock b = document()->findBlockByNumber(executing_ - 1);
        if (b.isValid()) {
            QTextEdit::ExtraSelection s;
            s.format.setBackground(QColor(200, 220, 255));
            s.format.setProperty(QTextFormat::FullWidthSelection, true);
            s.cursor = QTextCursor(b);
            selections << s;
        }
    }
    setExtraSelections(selections);
}

}  // namespace ui
}  // namespace trilho
