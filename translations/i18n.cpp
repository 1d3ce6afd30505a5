#include "translations/i18n.h"

#include <QCoreApplication>
#include <QTranslator>

#include "app/common/data_paths.h"

namespace trilho {
namespace {
QTranslator*& current() {
    static QTranslator* translator = nullptr;
    return translator;
}
}  // namespace

QStringList availableLanguages() {
    return {QStringLiteral("en"), QStringLiteral("pt_BR"), QStringLiteral("es")};
}

bool installLanguage(const QString& lang) {
    if (!availableLanguages().contains(lang)) return false;
    if (current()) {
        QCoreApplication::removeTranslator(current());
        delete current();
        current() = nullptr;
    }
    if (lang == QLatin1String("en")) return true;
    auto* translator = new QTranslator(QCoreApplication::instance());
    if (!translator->load(QStringLiteral("trilho_%1").arg(lang), translationsDir())) {
        delete translator;
        return false;
    }
    QCoreApplication::installTranslator(translator);
    current() = translator;
    return true;
}

}  // namespace trilho
