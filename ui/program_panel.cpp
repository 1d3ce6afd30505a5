#include "ui/program_panel.h"

#include <cstring>

#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QStackedWidget>
#include <QVBoxLayout>
#include "core/files/atomic_file.h"
#include "core/gcode/diagnostic_text.h"
#include "core/gcode/source_file.h"

#include "ui/background_pool.h"
#include "ui/code_editor.h"
#include "ui/gcode_highlighter.h"
#include "ui/large_program_view.h"

namespace trilho {
namespace ui {

ProgramPanel::ProgramPanel(QWidget* parent) : QWidget(parent) {
    editor_ = new CodeEditor(this);
    new GcodeHighlighter(editor_->document());
    large_ = new LargeProgramView(this);
    views_ = new QStackedWidget(this);
    views_->addWidget(editor_);
    views_->addWidget(large_);
    largeNote_ = new QLabel(this);
    largeNote_->setWordWrap(true);
    largeNote_->hide();
    list_ = new QListWidget(this);
    save_ = new QPushButton(this);
    startHere_ = new QPushButton(this);
    // Two rows: "Iniciar a partir do bloco selecionado" beside Save widened the dock past a
    // 1024-wide screen.
    auto* buttons = new QGridLayout;
    buttons->addWidget(save_, 0, 0);
    buttons->addWidget(startHere_, 1, 0, 1, 2);
    buttons->setColumnStretch(1, 1);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(views_);
    split->addWidget(list_);
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 1);
    // Small minimums: the right docks must not hold the window's middle (and so the Plots
    // dock) at their natural height on a 768-line screen.
    editor_->setMinimumHeight(editor_->fontMetrics().lineSpacing() * 3 + 8);
    large_->setMinimumHeight(editor_->minimumHeight());
    list_->setMinimumHeight(list_->fontMetrics().lineSpacing() * 2 + 6);
    auto* v = new QVBoxLayout(this);
    v->addLayout(buttons);
    v->addWidget(largeNote_);
    v->addWidget(split);
    connect(save_, &QPushButton::clicked, this, [this] {
        QString error;
        if (!save(&error)) QMessageBox::warning(this, tr("Save"), error);
    });
    connect(startHere_, &QPushButton::clicked, this, &ProgramPanel::startFromCursorRequested);
    // A diagnostic's line (the last line, "... and N more", has none).
    auto goToItem = [this](QListWidgetItem* item) {
        if (const int line = item->data(Qt::UserRole).toInt(); line > 0)
            goToLine(line, item->data(Qt::UserRole + 1).toInt());
    };
    connect(list_, &QListWidget::itemActivated, this, goToItem);
    connect(list_, &QListWidget::itemClicked, this, goToItem);
    connect(editor_->document(), &QTextDocument::modificationChanged, this,
            &ProgramPanel::dirtyChanged);
    retranslate();
}

void ProgramPanel::retranslate() {
    save_->setText(tr("Save"));
    startHere_->setText(tr("Start from the selected block"));
    save_->setToolTip(large_mode_ ? tr("A program this large is shown read-only: edit it in a "
                                       "text editor")
                                  : tr("Saves atomically: a crash never leaves half a file"));
    if (large_mode_)
        largeNote_->setText(tr("%1 lines: too large to edit here, shown read-only. Click a line "
                               "to select its block.")
                                .arg(QLocale().toString(large_->lineCount())));
}

void ProgramPanel::goToLine(int line, int column) {
    if (large_mode_)
        large_->goToLine(line, column);
    else
        editor_->goToLine(line, column);
}

void ProgramPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

struct ProgramPanel::Loaded {
    SourceFile source;
    bool large = false;
    IndexedText text;  ///< large programs only
};

ProgramPanel::Loaded ProgramPanel::read(const QString& path) {
    // The compiler's reader: a size limit, and a FIFO or a device is refused, never waited on.
    Loaded l;
    l.source = readSourceFile(QFile::encodeName(path).toStdString());
    if (!l.source.ok) return l;
    // Lines are counted only up to the bound: a large file is not walked twice.
    std::size_t lines = 0;
    for (const char *at = l.source.bytes.data(), *end = at + l.source.bytes.size();
         lines <= static_cast<std::size_t>(kLargeProgramLines);) {
        at = static_cast<const char*>(std::memchr(at, '\n', static_cast<std::size_t>(end - at)));
        if (!at) break;
        ++lines;
        ++at;
    }
    l.large = l.source.bytes.size() > kLargeProgramBytes ||
              lines > static_cast<std::size_t>(kLargeProgramLines);
    if (l.large) l.text = indexText(std::move(l.source.bytes));
    return l;
}

bool ProgramPanel::load(const QString& path, QString* error) {
    const int generation = ++generation_;
    const QFileInfo info(path);
    if (!info.isFile() || info.size() <= kAsyncLoadBytes) {
        Loaded l = read(path);
        if (!l.source.ok) {
            if (error) *error = QString::fromStdString(l.source.error);
            return false;
        }
        path_ = path;
        apply(std::move(l));
        loading_ = false;
        emit loaded();
        return true;
    }
    // Large: read and index on a worker thread; the old program is gone from the screen, so
    // nothing shows a text that is not the one selected.
    loading_ = true;
    path_ = path;
    large_mode_ = false;
    editor_->clear();
    large_->setText({});
    views_->setCurrentWidget(editor_);
    editor_->setReadOnly(true);
    save_->setEnabled(false);
    list_->clear();
    largeNote_->setText(
        tr("Loading %1 (%2 MB)...").arg(info.fileName()).arg(double(info.size()) / 1e6, 0, 'f', 1));
    largeNote_->show();
    auto* watcher = new QFutureWatcher<Loaded>(this);
    connect(watcher, &QFutureWatcher<Loaded>::finished, this, [this, watcher, generation] {
        watcher->deleteLater();
        if (generation != generation_) return;  // another program was selected meanwhile
        loading_ = false;
        editor_->setReadOnly(false);
        Loaded l = watcher->result();
        if (!l.source.ok) {
            path_.clear();
            largeNote_->hide();
            emit loadFailed(QString::fromStdString(l.source.error));
            return;
        }
        apply(std::move(l));
        emit loaded();
    });
    watcher->setFuture(QtConcurrent::run(backgroundPool(), [path] { return read(path); }));
    return true;
}

void ProgramPanel::apply(Loaded l) {
    ++loads_;
    const QFileInfo info(path_);
    loadedModified_ = info.lastModified();
    loadedSize_ = info.size();
    editor_->setReadOnly(false);  // an earlier large load may have set it
    large_mode_ = l.large;
    if (large_mode_) {
        editor_->clear();
        large_->setText(std::move(l.text));
        views_->setCurrentWidget(large_);
    } else {
        large_->setText({});
        editor_->setPlainText(QString::fromUtf8(l.source.bytes.data(),
                                                static_cast<qsizetype>(l.source.bytes.size())));
        views_->setCurrentWidget(editor_);
    }
    editor_->document()->setModified(false);
    largeNote_->setVisible(large_mode_);
    save_->setEnabled(!large_mode_);
    list_->clear();
    editor_->setDiagnostics({});
    retranslate();
}

bool ProgramPanel::save(QString* error) {
    if (path_.isEmpty()) {
        if (error) *error = tr("No program is selected: there is no file to save to.");
        return false;
    }
    if (large_mode_) return true;  // read-only: the file on disk is the program
    // Atomic and checked (issue 30 item 1): a full disk keeps the file as it was and the
    // editor unsaved, so Exit still asks.
    if (QString why; !saveFileAtomically(path_, editor_->toPlainText().toUtf8(), &why)) {
        if (error) *error = why;
        return false;
    }
    editor_->document()->setModified(false);
    return true;
}

QString ProgramPanel::text() const {
    if (large_mode_) return QString::fromStdString(*large_->bytes());
    return editor_->toPlainText();
}
int ProgramPanel::revision() const {
    return loads_ * 1000003 + editor_->document()->revision();
}

bool ProgramPanel::changedOnDisk() const {
    if (!large_mode_ || path_.isEmpty()) return false;
    const QFileInfo info(path_);
    return info.size() != loadedSize_ || info.lastModified() != loadedModified_;
}

std::shared_ptr<const std::string> ProgramPanel::source() const {
    if (large_mode_) return large_->bytes();  // shared, not copied: 16 MB for 1M lines
    return std::make_shared<const std::string>(editor_->toPlainText().toStdString());
}
bool ProgramPanel::dirty() const {
    return !large_mode_ && editor_->document()->isModified();
}
int ProgramPanel::cursorLine() const {
    if (large_mode_) return large_->currentLine();
    return editor_->textCursor().blockNumber() + 1;
}
void ProgramPanel::setExecutingLine(int line) {
    if (large_mode_)
        large_->setExecutingLine(line);
    else
        editor_->setExecutingLine(line);
}

void ProgramPanel::showDiagnostics(const std::vector<Diagnostic>& diagnostics,
                                   const QStringList& messages, std::size_t omitted) {
    list_->clear();
    for (std::size_t i = 0; i < diagnostics.size() && static_cast<qsizetype>(i) < messages.size();
         ++i) {
        const Diagnostic& d = diagnostics[i];
        auto* item = new QListWidgetItem(
            QStringLiteral("%1:%2  [%3]  %4")
                .arg(d.line)
                .arg(d.column)
                .arg(QString::fromLatin1(d.code().data(), static_cast<qsizetype>(d.code().size())),
                     messages[static_cast<qsizetype>(i)]),
            list_);
        item->setData(Qt::UserRole, static_cast<int>(d.line));
        item->setData(Qt::UserRole + 1, static_cast<int>(std::max<std::uint32_t>(1, d.column)));
        item->setForeground(Qt::darkRed);
    }
    if (omitted > 0) {
        auto* more = new QListWidgetItem(omittedDiagnostics(omitted), list_);
        more->setFlags(Qt::ItemIsEnabled);  // no line to go to
    }
    if (large_mode_)
        large_->setDiagnostics(diagnostics);
    else
        editor_->setDiagnostics(diagnostics);
}

}  // namespace ui
}  // namespace trilho
