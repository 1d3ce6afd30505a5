#pragma once
// Installs the translator for a UI language ("en", "pt_BR", "es") from the .qm files in
// translationsDir() (host/common/data_paths.h).
#include <QString>
#include <QStringList>

class QTranslator;

namespace trilho {

/// Languages the program ships, the source language (en) first.
QStringList availableLanguages();

/// Replaces the application's trilho translator with the one for lang. Returns false (and
/// leaves English) for an unknown language. Needs a QCoreApplication.
bool installLanguage(const QString& lang);

}  // namespace trilho
