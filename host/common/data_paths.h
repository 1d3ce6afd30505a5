#pragma once
// Where trilho's data is. Installed (the executable in <prefix>/bin): <prefix>/share/trilho/
// programs, machines, translations and docs. Run from the build tree: the source tree's
// resources/programs and resources/machines, and the .qm files the build made. An installed
// program never looks in the source tree. Needs a QCoreApplication.
#include <QString>

#include "core/profile/machine_profile.h"

namespace trilho {

/// The example programs (the Select dialog starts here).
QString examplesDir();
/// The machine profiles (rail.json, xy_dc_table.json, ...).
QString machinesDir();
/// The compiled translations (trilho_pt_BR.qm, trilho_es.qm).
QString translationsDir();
/// The guides (operator.md, teaching.md, ... and their screenshots) Help opens.
QString docsDir();
/// The boards' firmware images (seed004.elf, seed004-calibration.elf: firmware/, issue 32).
QString firmwareDir();
/// True when the running executable is the installed one (not in the build tree).
bool runningInstalled();

/// The profile a --machine argument names: an existing file as given, else a profile of
/// machinesDir() by name ("xy_dc_table" or "xy_dc_table.json"); empty names the default,
/// machinesDir()/rail.json.
QString machineProfilePath(const QString& nameOrPath);
/// Loads that profile. With an empty name and no rail.json installed, the built-in rail
/// profile (identical to the shipped file) is returned and error says the file is missing.
ProfileLoad loadNamedMachineProfile(const QString& nameOrPath);

}  // namespace trilho
