#include "ui/program_panel.h"

#include <QEvent>
#include <QFile>

#include <QGridLayout>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QSplitter>
#include <QVBoxLayout>
#include "core/gcode/source_file.h"

#include "ui/code_editor.h"
#include "ui/gcode_highlighter.h"

namespace trilho {
namespace ui {

ProgramPanel::ProgramPanel(QWidget* parent) : QWidget(parent) {
    editor_ = new CodeEditor(this);
    new GcodeHighlighter(editor_->document());
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
    split->addWidget(editor_);
    split->addWidget(list_);
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 1);
    // Small minimums: the right docks must not hold the window's middle (and so the Plots
    // dock) at their natural height on a 768-line screen.
    editor_->setMinimumHeight(editor_->fontMetrics().lineSpacing() * 3 + 8);
    list_->setMinimumHeight(list_->fontMetrics().lineSpacing() * 2 + 6);
    auto* v = new QVBoxLayout(this);
    v->addLayout(buttons);
    v->addWidget(split);
    connect(save_, &QPushButton::clicked, this, [this] {
        QString error;
        if (!save(&error)) QMessageBox::warning(this, tr("Save"), error);
    });
    connect(startHere_, &QPushButton::clicked, this, &ProgramPanel::startFromCursorRequested);
    connect(list_, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        editor_->goToLine(item->data(Qt::UserRole).toInt(), item->data(Qt::UserRole + 1).toInt());
    });
    connect(list_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        editor_->goToLine(item->data(Qt::UserRole).toInt(), item->data(Qt::UserRole + 1).toInt());
    });
    connect(editor_->document(), &QTextDocument::modificationChanged, this,
            &ProgramPanel::dirtyChanged);
    retranslate();
}

void ProgramPanel::retranslate() {
    save_->setText(tr("Save"));
    startHere_->setText(tr("Start from the selected block"));
    save_->setToolTip(tr("Saves atomically: a crash never leaves half a file"));
}

void ProgramPanel::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

bool ProgramPanel::load(const QString& path, QString* error) {
    // The compiler's reader: a size limit, and a FIFO or a device is refused, never waited on.
    const SourceFile source = readSourceFile(QFile::encodeName(path).toStdString());
    if (!source.ok) {
        if (error) *error = QString::fromStdString(source.error);
        return false;
    }
    editor_->setPlainText(
        QString::fromUtf8(source.bytes.data(), static_cast<qsizetype>(source.bytes.size())));
    editor_->document()->setModified(false);
    path_ = path;
    list_->clear();
    editor_->setDiagnostics({});
    return true;
}

bool ProgramPanel::save(QString* error) {
    if (path_.isEmpty()) {
        if (error) *error = tr("No program is selected: there is no file to save to.");
        return false;
    }
    QSaveFile f(path_);
    if (!f.open(QIODevice::WriteOnly) || f.write(editor_->toPlainText().toUtf8()) < 0 ||
        !f.commit()) {
        if (error) *error = tr("cannot save '%1': %2").arg(path_, f.errorString());
        return false;
    }
    editor_->document()->setModified(false);
    return true;
}

QString ProgramPanel::text() const {
    return editor_->toPlainText();
}
bool ProgramPanel::dirty() const {
    return editor_->document()->isModified();
}
int ProgramPanel::cursorLine() const {
    return editor_->textCursor().blockNumber() + 1;
}
void ProgramPanel::setExecutingLine(int line) {
    editor_->setExecutingLine(line);
}

void ProgramPanel::showDiagnostics(const std::vector<Diagnostic>& diagnostics,
                                   const QStringList& messages) {
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
    editor_->setDiagnostics(diagnostics);
}

}  // namespace ui
}  // namespace trilho
