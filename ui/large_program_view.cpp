#include "ui/large_program_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

#include <algorithm>
#include <cstring>
#include "ui/fixed_font.h"

namespace trilho {
namespace ui {

LargeProgramView::LargeProgramView(QWidget* parent) : QAbstractScrollArea(parent) {
    setFont(fixedFont());
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setBackgroundRole(QPalette::Base);
    viewport()->setAutoFillBackground(true);
    setText({});
}

IndexedText indexText(std::string bytes) {
    IndexedText t;
    const char* const begin = bytes.data();
    const char* const end = begin + bytes.size();
    // Counted first, then reserved: a growing vector would hold up to twice the offsets (a
    // 64 MB file of empty lines is 67 M offsets, 268 MB).
    std::size_t lines = 1;
    for (const char* at = begin; at < end; ++lines) {
        at = static_cast<const char*>(std::memchr(at, '\n', static_cast<std::size_t>(end - at)));
        if (!at) break;
        ++at;
    }
    t.starts.reserve(lines);
    const char* lineStart = begin;
    while (lineStart < end) {
        const auto* nl = static_cast<const char*>(
            std::memchr(lineStart, '\n', static_cast<std::size_t>(end - lineStart)));
        const char* lineEnd = nl ? nl : end;
        t.longestLine = std::max(
            t.longestLine, static_cast<int>(std::min<std::ptrdiff_t>(lineEnd - lineStart, 4096)));
        if (!nl) break;
        lineStart = nl + 1;
        if (lineStart < end) t.starts.push_back(static_cast<std::uint32_t>(lineStart - begin));
    }
    t.bytes = std::make_shared<const std::string>(std::move(bytes));
    return t;
}

void LargeProgramView::setText(IndexedText text) {
    text_ = std::move(text);
    executing_ = 0;
    current_ = 1;
    marked_.clear();
    verticalScrollBar()->setValue(0);
    horizontalScrollBar()->setValue(0);
    updateScrollBars();
    viewport()->update();
}

QString LargeProgramView::lineText(int line) const {
    if (line < 1 || line > lineCount()) return {};
    const std::string& bytes = *text_.bytes;
    const std::size_t begin = text_.starts[static_cast<std::size_t>(line - 1)];
    std::size_t end = static_cast<std::size_t>(line) < text_.starts.size()
                          ? text_.starts[static_cast<std::size_t>(line)]
                          : bytes.size();
    while (end > begin && (bytes[end - 1] == '\n' || bytes[end - 1] == '\r'))
        --end;
    // A very long line shows its first 4096 characters: a view, not an editor.
    end = std::min(end, begin + 4096);
    return QString::fromUtf8(bytes.data() + begin, static_cast<qsizetype>(end - begin));
}

void LargeProgramView::setExecutingLine(int line) {
    if (line == executing_) return;
    executing_ = line;
    if (line > 0) ensureVisible(line);
    viewport()->update();
}

void LargeProgramView::setDiagnostics(const std::vector<Diagnostic>& diagnostics) {
    marked_.clear();
    for (const Diagnostic& d : diagnostics)
        marked_.push_back(static_cast<int>(d.line));
    std::sort(marked_.begin(), marked_.end());
    marked_.erase(std::unique(marked_.begin(), marked_.end()), marked_.end());
    viewport()->update();
}

void LargeProgramView::goToLine(int line, int /*column*/) {
    current_ = std::clamp(line, 1, std::max(1, lineCount()));
    ensureVisible(current_);
    viewport()->update();
}

int LargeProgramView::firstVisibleLine() const {
    return verticalScrollBar()->value() + 1;
}

int LargeProgramView::visibleRows() const {
    return std::max(1, viewport()->height() / fontMetrics().lineSpacing());
}

int LargeProgramView::gutterWidth() const {
    const auto digits = static_cast<int>(QString::number(std::max(1, lineCount())).size());
    return fontMetrics().horizontalAdvance(QLatin1Char('9')) * (digits + 1) + 8;
}

void LargeProgramView::ensureVisible(int line) {
    const int first = firstVisibleLine();
    const int rows = visibleRows();
    if (line < first)
        verticalScrollBar()->setValue(line - 1);
    else if (line >= first + rows)
        verticalScrollBar()->setValue(line - rows);
}

void LargeProgramView::updateScrollBars() {
    const int rows = visibleRows();
    verticalScrollBar()->setRange(0, std::max(0, lineCount() - rows));
    verticalScrollBar()->setPageStep(rows);
    verticalScrollBar()->setSingleStep(1);
    const int textWidth = fontMetrics().horizontalAdvance(QLatin1Char('M')) * text_.longestLine;
    const int room = viewport()->width() - gutterWidth();
    horizontalScrollBar()->setRange(0, std::max(0, textWidth - room + 8));
    horizontalScrollBar()->setPageStep(std::max(1, room));
}

void LargeProgramView::resizeEvent(QResizeEvent* event) {
    QAbstractScrollArea::resizeEvent(event);
    updateScrollBars();
}

void LargeProgramView::paintEvent(QPaintEvent*) {
    QPainter p(viewport());
    const QFontMetrics fm = fontMetrics();
    const int lineHeight = fm.lineSpacing();
    const int gutter = gutterWidth();
    const int width = viewport()->width();
    const int first = firstVisibleLine();
    const int rows = visibleRows() + 1;
    const int dx = horizontalScrollBar()->value();
    // The same colours as the editor (code_editor.cpp): executing blue, diagnostics red.
    p.fillRect(0, 0, gutter, viewport()->height(), QColor(235, 235, 235));
    for (int row = 0; row < rows; ++row) {
        const int line = first + row;
        if (line > lineCount()) break;
        const int y = row * lineHeight;
        const bool bad = std::binary_search(marked_.begin(), marked_.end(), line);
        QColor background;
        if (line == executing_)
            background = QColor(200, 220, 255);
        else if (bad)
            background = QColor(255, 230, 230);
        else if (line == current_)
            background = palette().color(QPalette::AlternateBase);
        if (background.isValid()) p.fillRect(gutter, y, width - gutter, lineHeight, background);
        p.setClipRect(gutter + 2, y, width - gutter - 2, lineHeight);
        p.setPen(palette().color(QPalette::Text));
        p.drawText(gutter + 4 - dx, y + fm.ascent(), lineText(line));
        if (bad) {
            p.setPen(QPen(Qt::red, 1, Qt::DotLine));
            p.drawLine(gutter + 4, y + lineHeight - 1, width, y + lineHeight - 1);
        }
        p.setClipping(false);
        p.setPen(line == executing_ ? QColor(0, 0, 160)
                 : bad              ? QColor(200, 0, 0)
                                    : QColor(120, 120, 120));
        p.drawText(0, y, gutter - 6, lineHeight, Qt::AlignRight | Qt::AlignVCenter,
                   QString::number(line));
    }
}

void LargeProgramView::mousePressEvent(QMouseEvent* event) {
    const int row = static_cast<int>(event->position().y()) / fontMetrics().lineSpacing();
    goToLine(firstVisibleLine() + row);
}

void LargeProgramView::keyPressEvent(QKeyEvent* event) {
    const int rows = visibleRows();
    const bool ctrl = event->modifiers() & Qt::ControlModifier;
    switch (event->key()) {
        case Qt::Key_Up:
            goToLine(current_ - 1);
            break;
        case Qt::Key_Down:
            goToLine(current_ + 1);
            break;
        case Qt::Key_PageUp:
            goToLine(current_ - rows);
            break;
        case Qt::Key_PageDown:
            goToLine(current_ + rows);
            break;
        case Qt::Key_Home:
            if (!ctrl) return QAbstractScrollArea::keyPressEvent(event);
            goToLine(1);
            break;
        case Qt::Key_End:
            if (!ctrl) return QAbstractScrollArea::keyPressEvent(event);
            goToLine(lineCount());
            break;
        default:
            QAbstractScrollArea::keyPressEvent(event);
            return;
    }
    event->accept();
}

}  // namespace ui
}  // namespace trilho
