#include "ui/language_menu.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <utility>

namespace trilho {
namespace ui {

QActionGroup* addLanguageActions(QMenu* menu, std::function<void(const QString&)> choose) {
    auto* group = new QActionGroup(menu);
    // Each language in its own name: an operator who cannot read the current one finds theirs.
    for (const auto& [code, name] :
         {std::pair{QStringLiteral("en"), QStringLiteral("English")},
          std::pair{QStringLiteral("pt_BR"), QStringLiteral("Português (Brasil)")},
          std::pair{QStringLiteral("es"), QStringLiteral("Español")}}) {
        QAction* a = menu->addAction(name);
        a->setObjectName(QStringLiteral("language_") + code);
        a->setCheckable(true);
        a->setData(code);
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, menu, [choose, c = code] { choose(c); });
    }
    return group;
}

void checkLanguage(QActionGroup* group, const QString& code) {
    for (QAction* a : group->actions())
        a->setChecked(a->data().toString() == code);
}

}  // namespace ui
}  // namespace trilho
