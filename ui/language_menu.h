#pragma once
// Options > Language, the same on every machine's screen (issue 19, one frame): one checkable
// action per shipped language, named language_<code> so the frame's parity test finds it.
#include <QString>
#include <functional>

class QActionGroup;
class QMenu;

namespace trilho {
namespace ui {

/// Adds the languages to menu; choosing one calls choose with its code (en, pt_BR, es).
QActionGroup* addLanguageActions(QMenu* menu, std::function<void(const QString&)> choose);
/// Checks the action of code in group (after a language was installed).
void checkLanguage(QActionGroup* group, const QString& code);

}  // namespace ui
}  // namespace trilho
