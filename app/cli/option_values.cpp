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

std::optional<QString> readLaw(const QCommandLineParser& parser, const QCommandLineOption& opt,
                               bool dcTable, std::optional<LoopLaw>& law,
                               std::optional<DcLaw>& tableLaw) {
    if (!parser.isSet(opt)) return std::nullopt;
    const QString l = parser.value(opt);
    const QString name = opt.names().front();
    if (dcTable) {
        const std::optional<DcLaw> d = dcLawFromName(l.toStdString());
        if (!d)
            return l == QLatin1String("classic")
                       ? QStringLiteral(
                             "--%1 classic is the rail's: the DC table's laws are seed "
                             "(seed 004 as written), seed-signed and engineered")
                             .arg(name)
                       : QStringLiteral(
                             "--%1 on the DC table must be seed, seed-signed or "
                             "engineered (got '%2')")
                             .arg(name, l);
        tableLaw = *d;
        law = *d == DcLaw::Engineered ? LoopLaw::Engineered : LoopLaw::Classic;
        return std::nullopt;
    }
    if (l == QLatin1String("classic")) {
        law = LoopLaw::Classic;
    } else if (l == QLatin1String("engineered")) {
        law = LoopLaw::Engineered;
    } else if (l == QLatin1String("seed") || l == QLatin1String("seed-signed")) {
        return QStringLiteral(
                   "--%1 %2 is the DC table's: the rail's laws are classic and "
                   "engineered")
            .arg(name, l);
    } else {
        return QStringLiteral("--%1 on the rail must be classic or engineered (got '%2')")
            .arg(name, l);
    }
    return std::nullopt;
}

QString lawOptionHelp() {
    return QStringLiteral(
        "The loop's law (default: the profile's): on the rail classic (1996) or engineered; on "
        "the DC table seed (seed 004 as written: |e| with the move's direction bit), "
        "seed-signed (the same gains on the signed error) or engineered.");
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
    return {
        QCommandLineOption(QStringLiteral("kp"), QStringLiteral("Proportional gain."),
                           QStringLiteral("K")),
        QCommandLineOption(QStringLiteral("ki"), QStringLiteral("Integral gain."),
                           QStringLiteral("K")),
        QCommandLineOption(QStringLiteral("kd"), QStringLiteral("Derivative gain (the rail)."),
                           QStringLiteral("K")),
        QCommandLineOption(QStringLiteral("b0"),
                           QStringLiteral("b0 of the DC table's seed laws (seed, seed-signed)."),
                           QStringLiteral("B")),
        QCommandLineOption(QStringLiteral("b1"),
                           QStringLiteral("b1 of the DC table's seed laws (seed, seed-signed)."),
                           QStringLiteral("B"))};
}

}  // namespace trilho::cli
