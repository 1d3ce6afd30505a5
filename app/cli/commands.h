#pragma once
#include <QStringList>

namespace trilho::cli {

/// Each command takes its own arguments (argv[0] is "trilho-cli <command>") and returns the
/// process exit status (cli_output.h).
int compileCommand(const QStringList& args);
int profileCommand(const QStringList& args);
int runCommand(const QStringList& args);
/// The pre-run check (check_command.cpp, host/check/program_check.h).
int checkCommand(const QStringList& args);
int latencyCommand(const QStringList& args);
int serveCommand(const QStringList& args);
/// tune identify | auto (tune_model_command.cpp); tune dispatches to them.
int tuneModelCommand(const QStringList& args, bool autotune);
/// tune relay (tune_relay_command.cpp).
int tuneRelayCommand(const QStringList& args);
/// tune margin (tune_margin_command.cpp): the plotter's speed and acceleration margin.
int tuneMarginCommand(const QStringList& args);
/// tune poles (tune_poles_command.cpp): the closed loop's poles and zeros.
int tunePolesCommand(const QStringList& args);
/// tune disturbance (tune_disturbance_command.cpp): a step of load while holding or moving.
int tuneDisturbanceCommand(const QStringList& args);
/// tune report (tune_report_command.cpp): the lab sheet of saved runs (PDF, PNG).
int tuneReportCommand(const QStringList& args);
int tuneCommand(const QStringList& args);
int calibrateCommand(const QStringList& args);

}  // namespace trilho::cli
