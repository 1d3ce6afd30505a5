#pragma once
// The program view and editor: line numbers, syntax colours, the executing block highlighted,
// diagnostics marked on their lines and listed (a click jumps there), atomic save.
#include <QWidget>

#include "core/gcode/program.h"

class QListWidget;
class QPushButton;

namespace trilho {
namespace ui {

class CodeEditor;

class ProgramPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ProgramPanel(QWidget* parent = nullptr);
    bool load(const QString& path, QString* error);
    bool save(QString* error);
    QString path() const { return path_; }
    QString text() const;
    bool dirty() const;
    void showDiagnostics(const std::vector<Diagnostic>& diagnostics, const QStringList& messages);
    void setExecutingLine(int line);
    /// 1-based line of the cursor (for "start from the selected block").
    int cursorLine() const;
    CodeEditor* editor() const { return editor_; }
    QListWidget* diagnosticsList() const { return list_; }

  signals:
    void startFromCursorRequested();
    void dirtyChanged(bool dirty);

  protected:
    void changeEvent(QEvent* e) override;

  private:
    void retranslate();
    CodeEditor* editor_;
    QListWidget* list_;
    QPushButton *save_, *startHere_;
    QString path_;
};

}  // namespace ui
}  // namespace trilho
