#pragma once
// The values of trilho-cli's common options, checked the same way in every command: a number
// in its range, a seed, an axis. Each returns the one-line message naming the option and the
// value typed when the value is wrong (the command reports it with usageError), nothing when
// it is right or not given.
#include <QCommandLineOption>
#include <QString>
#include <cstdint>
#include <optional>

#include "core/control/dc_law.h"
#include "core/control/loop_law.h"
#include "core/gcode/dialect.h"

class QCommandLineParser;
class QCommandLineOption;

namespace trilho::cli {

/// A finite number from lo to hi into `into` (unchanged when the option is not given):
/// "--NAME must be a number from LO to HI (got 'TEXT')".
std::optional<QString> readNumber(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                  double lo, double hi, double& into);
/// --seed N (any 64-bit unsigned integer) into `seed`, unchanged when not given.
std::optional<QString> readSeed(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                std::uint64_t& seed);
/// --axis x|y into `axis` ('x' or 'y'), unchanged when not given.
std::optional<QString> readAxis(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                char& axis);

/// --law on the machine's loop (issue 33 item 5): the rail's classic or engineered into `law`;
/// the DC table's seed, seed-signed or engineered into `tableLaw` (and `law`: Classic for the
/// seed's two readings, whose gains are b0, b1). Unchanged when not given. Refused: a law the
/// machine has not, named with the ones it has ("--law classic is the rail's: the DC table's
/// laws are seed, seed-signed and engineered").
std::optional<QString> readLaw(const QCommandLineParser& parser, const QCommandLineOption& opt,
                               bool dcTable, std::optional<LoopLaw>& law,
                               std::optional<DcLaw>& tableLaw);
/// The help text of --law for the commands that take it.
QString lawOptionHelp();

/// The options several commands take, named and explained the same in each one's --help:
/// --dialect (classic or standard), --lang (en, pt_BR, es), --mass-factor F.
QCommandLineOption dialectOption();
QCommandLineOption languageOption();
QCommandLineOption simulatedMassOption();

/// The loop gains the tuning commands take, named and explained the same in each one's --help:
/// --kp, --ki, --kd (the rail), and --b0, --b1 (the DC table's classic law).
struct GainOptions {
    QCommandLineOption kp, ki, kd, b0, b1;
};
GainOptions gainOptions();

/// --dialect classic|standard into `dialect`: "unknown dialect 'TEXT' (classic or standard)".
std::optional<QString> readDialect(const QCommandLineParser& parser, const QCommandLineOption& opt,
                                   Dialect& dialect);
/// --lang en|pt_BR|es, installed for the command's messages: "unknown language 'TEXT' (en,
/// pt_BR or es)".
std::optional<QString> installLanguageOption(const QCommandLineParser& parser,
                                             const QCommandLineOption& opt);

}  // namespace trilho::cli
