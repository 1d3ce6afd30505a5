// trilho-cli --version names the project version (CMake's project(VERSION)), for scripts,
// help2man and bug reports.
#include <gtest/gtest.h>

#include "tests/integration/cli_process.h"

namespace {

TEST(CliVersion, PrintsTheProjectVersionAndExitsZero) {
    const trilho::test::CliResult r = trilho::test::runCli({QStringLiteral("--version")});
    EXPECT_EQ(r.exit, 0);
    EXPECT_EQ(r.out, QStringLiteral("trilho-cli " TRILHO_EXPECTED_VERSION "\n"));
    EXPECT_TRUE(r.err.isEmpty()) << r.err.toStdString();
}

TEST(CliVersion, HelpNamesEveryCommand) {
    const trilho::test::CliResult r = trilho::test::runCli({QStringLiteral("--help")});
    EXPECT_EQ(r.exit, 0);
    for (const char* command : {"compile", "run", "latency", "profile"})
        EXPECT_TRUE(r.out.contains(QLatin1String(command))) << command;
}

}  // namespace
