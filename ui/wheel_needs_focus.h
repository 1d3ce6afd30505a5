#pragma once
// A value changes only by deliberate input (issue 19 item 5, issue 33 bug 3): a wheel turned
// over a number box or a drop-down list that does not have the focus changes nothing in it; it
// scrolls the panel the box sits in instead. A click gives the box the focus, and then the
// wheel is the box's.
class QWidget;

namespace trilho {
namespace ui {

/// Guards every number box (QAbstractSpinBox) and drop-down list (QComboBox) under `root` that
/// exists now. They take the focus by click or Tab (Qt::StrongFocus), not by the wheel.
void wheelNeedsFocus(QWidget* root);

}  // namespace ui
}  // namespace trilho
