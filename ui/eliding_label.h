#pragma once
// A one-line label that never asks for the width of its text: what does not fit ends in "…",
// and the whole text is its tooltip. For what the screens show in an emergency (the latched
// E-stop's banner): it must not widen the window (issue 31 item 1) nor grow in height and push
// the 1996 form into scrolling, so it keeps one line whatever the language and the screen.
#include <QLabel>
#include <QString>

namespace trilho::ui {

class ElidingLabel : public QLabel {
    Q_OBJECT
  public:
    explicit ElidingLabel(QWidget* parent = nullptr);
    /// The text to show whole when it fits; text() is what is shown.
    void setFullText(const QString& text);
    QString fullText() const { return full_; }
    /// One line high, and no wider than "…": the layout never grows for the text.
    QSize minimumSizeHint() const override;

  protected:
    void resizeEvent(QResizeEvent* e) override;
    void changeEvent(QEvent* e) override;

  private:
    void elide();
    QString full_;
};

}  // namespace trilho::ui
