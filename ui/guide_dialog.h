#pragma once
// Help > Operator's guide and Teaching guide: the installed Markdown guide (docsDir()) in a
// window beside the screens, with its screenshots; not modal, so the machine's keys and E-stop
// keep answering while it is open.
#include <QDialog>
#include <QString>

class QTextBrowser;

namespace trilho::ui {

class GuideDialog : public QDialog {
    Q_OBJECT
  public:
    /// fileName: a guide in docsDir(), e.g. "operator.md". A missing file is said in the
    /// window, with its path.
    GuideDialog(const QString& fileName, const QString& title, QWidget* parent);
    QTextBrowser* browser() const { return browser_; }
    /// Whether the guide was read.
    bool loaded() const { return loaded_; }

  private:
    QTextBrowser* browser_;
    bool loaded_ = false;
};

}  // namespace trilho::ui
