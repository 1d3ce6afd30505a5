// Where the programs find their data when run from the build tree (the installed layout is
// checked on the unpacked package by scripts/test-package).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFileInfo>

#include "host/common/data_paths.h"

namespace trilho {
namespace {

QCoreApplication& app() {
    // One application for the whole test binary (translation_test needs one too).
    static int argc = 1;
    static char name[] = "data_paths_test";
    static char* argv[] = {name, nullptr};
    if (!QCoreApplication::instance()) new QCoreApplication(argc, argv);
    return *QCoreApplication::instance();
}

TEST(DataPaths, TheBuildTreeUsesTheSourceTreeAndTheBuiltTranslations) {
    app();
    EXPECT_FALSE(runningInstalled());
    EXPECT_EQ(QFileInfo(examplesDir()).canonicalFilePath(),
              QFileInfo(QStringLiteral(TRILHO_RESOURCES_DIR "/programs")).canonicalFilePath());
    EXPECT_TRUE(QFileInfo::exists(examplesDir() + QStringLiteral("/exemplo_documento.G")));
    EXPECT_TRUE(QFileInfo::exists(machinesDir() + QStringLiteral("/rail.json")));
    EXPECT_TRUE(QFileInfo::exists(translationsDir() + QStringLiteral("/trilho_pt_BR.qm")));
    EXPECT_TRUE(QFileInfo::exists(translationsDir() + QStringLiteral("/trilho_es.qm")));
}

TEST(DataPaths, AProfileIsNamedByFileOrByShippedName) {
    app();
    EXPECT_EQ(machineProfilePath(QString()), machinesDir() + QStringLiteral("/rail.json"));
    EXPECT_EQ(machineProfilePath(QStringLiteral("xy_dc_table")),
              machinesDir() + QStringLiteral("/xy_dc_table.json"));
    EXPECT_EQ(machineProfilePath(QStringLiteral("xy_dc_table.json")),
              machinesDir() + QStringLiteral("/xy_dc_table.json"));
    // A path is taken as given, even when missing (the load error names it).
    EXPECT_EQ(machineProfilePath(QStringLiteral("/nowhere/rail.json")),
              QStringLiteral("/nowhere/rail.json"));
    EXPECT_EQ(machineProfilePath(QStringLiteral("no_such_machine")),
              QStringLiteral("no_such_machine"));

    const ProfileLoad rail = loadNamedMachineProfile(QString());
    ASSERT_TRUE(rail.profile.has_value()) << rail.error.toStdString();
    EXPECT_TRUE(rail.error.isEmpty()) << rail.error.toStdString();  // the file, not the built-in
    EXPECT_EQ(machineProfileToJson(*rail.profile), machineProfileToJson(MachineProfile::rail()));
    const ProfileLoad xy = loadNamedMachineProfile(QStringLiteral("xy_dc_table"));
    ASSERT_TRUE(xy.profile.has_value()) << xy.error.toStdString();
    EXPECT_FALSE(loadNamedMachineProfile(QStringLiteral("no_such_machine")).profile.has_value());
}

}  // namespace
}  // namespace trilho
