#include "ui/wheel_needs_focus.h"

#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QScrollBar>
#include <QWidget>

namespace trilho {
namespace ui {

namespace {
/// One filter per guarded root, a child of it (it goes when the root goes).
class WheelGuard : public QObject {
  public:
    using QObject::QObject;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() != QEvent::Wheel) return false;
        auto* box = qobject_cast<QWidget*>(watched);
        if (!box || box->hasFocus()) return false;
        // Scroll the panel the box is in, if it scrolls; the box itself takes nothing.
        for (QWidget* p = box->parentWidget(); p; p = p->parentWidget())
            if (auto* area = qobject_cast<QAbstractScrollArea*>(p)) {
                if (area->verticalScrollBar()->isVisible())
                    QApplication::sendEvent(area->verticalScrollBar(), event);
                break;
            }
        return true;
    }
};
}  // namespace

void wheelNeedsFocus(QWidget* root) {
    auto* guard = new WheelGuard(root);
    const auto guardOne = [guard](QWidget* w) {
        w->setFocusPolicy(Qt::StrongFocus);
        w->installEventFilter(guard);
    };
    for (QAbstractSpinBox* box : root->findChildren<QAbstractSpinBox*>())
        guardOne(box);
    for (QComboBox* box : root->findChildren<QComboBox*>())
        guardOne(box);
}

}  // namespace ui
}  // namespace trilho
