#include "app/cli/option_values.h"

#include <QCommandLineParser>
#include <cmath>

#include "translations/i18n.h"

namespace trilho::cli {

std::optional<QString> readNumber(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                  double lo, double hi, double& into) {
    if (!parser.isSet(opt)) return std::nullopt;
    bool ok = false;
    const double v = parser.value(opt).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < lo || v > hi)
        return QStringLiteral("--%1 must be a number from %2 to %3 (got '%4')")
            .arg(opt.names().front())
            .arg(lo)
            .arg(hi)
            .arg(parser.value(opt));
    into = v;
    return std::nullopt;
}

std::optional<QString> readSeed(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                std::uint64_t& seed) {
    if (!parser.isSet(opt)) return std::nullopt;
    bool ok = false;
    const std::uint64_t v = parser.value(opt).toULongLong(&ok);
    if (!ok)
        return QStringLiteral(
                   "--%1 must be a whole number from 0 to 18446744073709551615 (got "
                   "'%2')")
            .arg(opt.names().front(), parser.value(opt));
    seed = v;
    return std::nullopt;
}

std::optional<QString> readAxis(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                char& axis) {
    if (!parser.isSet(opt)) return std::nullopt;
    const QString a = parser.value(opt);
    if (a != QLatin1String("x") && a != QLatin1String("y"))
        return QStringLiteral("--%1 must be x or y (got '%2')").arg(opt.names().front(), a);
    axis = a.at(0).toLatin1();
    return std::nullopt;
}

QCommandLineOption dialectOption() {
    return {QStringLiteral("dialect"), QStringLiteral("classic or standard (default)."),
            QStringLiteral("dialect"), QStringLiteral("standard")};
}

QCommandLineOption languageOption() {
    return {QStringLiteral("lang"), QStringLiteral("Message language: en, pt_BR or es."),
            QStringLiteral("lang"), QStringLiteral("en")};
}

QCommandLineOption simulatedMassOption() {
    return {QStringLiteral("mass-factor"),
            QStringLiteral("Multiply the simulated moving mass, on the rail and the DC table (the "
                           "controller is not told; refused on the plotter)."),
            QStringLiteral("F"), QStringLiteral("1")};
}

std::optional<QString> readDialect(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                   Dialect& dialect) {
    const auto parsed = parseDialect(parser.value(opt).toStdString());
    if (!parsed)
        return QStringLiteral("unknown dialect '%1' (classic or standard)").arg(parser.value(opt));
    dialect = *parsed;
    return std::nullopt;
}

std::optional<QString> installLanguageOption(const QCommandLineParser& parser,
                                             const QCommandLineOption& opt) {
    if (installLanguage(parser.value(opt))) return std::nullopt;
    return QStringLiteral("unknown language '%1' (en, pt_BR or es)").arg(parser.value(opt));
}

GainOptions gainOptions() {
    return {QCommandLineOption(QStringLiteral("kp"), QStringLiteral("Proportional gain."),
                               QStringLiteral("K")),
            QCommandLineOption(QStringLiteral("ki"), QStringLiteral("Integral gain."),
                               QStringLiteral("K")),
            QCommandLineOption(QStringLiteral("kd"), QStringLiteral("Derivative gain (the rail)."),
                               QStringLiteral("K")),
            QCommandLineOption(QStringLiteral("b0"),
                               QStringLiteral("b0 of the DC table's classic law."),
                               QStringLiteral("B")),
            QCommandLineOption(QStringLiteral("b1"),
                               QStringLiteral("b1 of the DC table's classic law."),
                               QStringLiteral("B"))};
}

}  // namespace trilho::cli
