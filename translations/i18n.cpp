#include "translations/i18n.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

#include "host/common/data_paths.h"

namespace trilho {
namespace {
QTranslator*& current() {
    static QTranslator* translator = nullptr;
    return translator;
}
/// Qt's own texts (the Yes/No/Cancel buttons, the file dialogs) in the same language.
QTranslator*& currentQt() {
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
    if (currentQt()) {
        QCoreApplication::removeTranslator(currentQt());
        delete currentQt();
        currentQt() = nullptr;
    }
    if (lang == QLatin1String("en")) return true;
    // Optional: without the qt6-translations-l10n package Qt's buttons stay English.
    auto* qt = new QTranslator(QCoreApplication::instance());
    if (qt->load(QStringLiteral("qtbase_%1").arg(lang),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
        currentQt() = qt;
    } else {
        delete qt;
    }
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
