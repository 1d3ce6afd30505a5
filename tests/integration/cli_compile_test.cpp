// trilho-cli compile as an operator or a script uses it: exit statuses, text and JSON output.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "tests/integration/cli_process.h"

#ifndef TRILHO_TEST_DATA
#define TRILHO_TEST_DATA TRILHO_PROGRAMS_DIR "/../../tests/data"
#endif

namespace {

using Result = trilho::test::CliResult;
Result run(const QStringList& args) {
    return trilho::test::runCli(args);
}

class CliCompile : public ::testing::Test {
  protected:
    QTemporaryDir dir;
    QString write(const QString& name, const QByteArray& content) {
        QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(content);
        return path;
    }
};

TEST_F(CliCompile, CleanProgramExitsZero) {
    Result r =
        run({QStringLiteral("compile"), write(QStringLiteral("ok.G"), "G1 X10 F20\nX20\nM2\n")});
    EXPECT_EQ(r.exit, 0);
    EXPECT_EQ(r.out, QStringLiteral("Compilation completed successfully\n"));
}

TEST_F(CliCompile, ErrorsListedWithPlaceAndCodeExitOne) {
    QString file = write(QStringLiteral("bad.G"), "n0010 g07\nn0020 x0010\n");
    Result r = run(
        {QStringLiteral("compile"), QStringLiteral("--dialect"), QStringLiteral("classic"), file});
    EXPECT_EQ(r.exit, 1);
    QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 4);
    EXPECT_EQ(lines[0], file + QStringLiteral(
                                   ":1:7: error[invalid-g]: invalid g command in line n=10 (g07)"));
    EXPECT_EQ(
        lines[1],
        file + QStringLiteral(":2:7: error[no-motion-mode]: g01 or g00 not defined in line n=20"));
    EXPECT_EQ(
        lines[2],
        file + QStringLiteral(":2: error[missing-m02]: program requires m02 (END) at the end"));
    EXPECT_EQ(lines[3], QStringLiteral("3 compile error(s)"));
}

// Seed 000, Compilar_click: the classic dialect in Portuguese says what the VB said, "na linha
// N" with N the block number, and the faults after a g00's x and under a modal g00 with the
// VB's own text and kind (issue 22 item 3).
TEST_F(CliCompile, Seed000_CompilarClick_TheNineFaultsAsTheVbListedThem) {
    Result r = run({QStringLiteral("compile"), QStringLiteral("--lang"), QStringLiteral("pt_BR"),
                    QStringLiteral("--dialect"), QStringLiteral("classic"),
                    QStringLiteral(TRILHO_TEST_DATA "/com_erros.classic.G")});
    EXPECT_EQ(r.exit, 1);
    const QStringList want = {
        QStringLiteral("error[feed-undefined]: Erro: g01 precisa de f definido na linha 10"),
        QStringLiteral("error[n-order]: Erro: Seqüência n errada na linha 5"),
        QStringLiteral(
            "error[trailing-words]: Erro: Não pode haver mais comandos após g00 na linha 5"),
        QStringLiteral("error[invalid-g]: Erro: Comando g inválido na linha 30"),
        QStringLiteral("error[g00-feed]: Erro: Caracter inválido ou g00 não requer f na linha 40"),
        QStringLiteral("error[invalid-m]: Erro: Comando m inválido na linha 50"),
        QStringLiteral("error[n-alone]: Erro: Seqüência n sozinha na linha 60"),
        QStringLiteral("error[negative-value]: Erro: Caracter inválido após g04 na linha 70"),
        QStringLiteral("error[missing-m02]: Erro: Programa requer m02 (END) no final"),
        QStringLiteral("Há 9 erro(s) de compilação !"),
    };
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), want.size()) << r.out.toStdString();
    for (qsizetype i = 0; i < want.size(); ++i)
        EXPECT_TRUE(lines[i].endsWith(want[i])) << lines[i].toStdString();
    // The standard dialect keeps its clearer places.
    Result std = run({QStringLiteral("compile"), QStringLiteral("--lang"), QStringLiteral("pt_BR"),
                      write(QStringLiteral("s.G"), "N30 G7\nM2\n")});
    EXPECT_TRUE(std.out.contains(QStringLiteral("Erro: Comando g inválido no bloco n=30")))
        << std.out.toStdString();
}

TEST_F(CliCompile, PortugueseSummary) {
    QString file = write(QStringLiteral("bad.G"), "n0010 g90\n");
    Result r = run({QStringLiteral("compile"), QStringLiteral("--lang"), QStringLiteral("pt_BR"),
                    QStringLiteral("--dialect"), QStringLiteral("classic"), file});
    EXPECT_EQ(r.exit, 1);
    EXPECT_TRUE(r.out.endsWith(QStringLiteral("Há 1 erro(s) de compilação !\n")))
        << r.out.toStdString();
}

TEST_F(CliCompile, JsonShape) {
    QString file = write(QStringLiteral("p.G"),
                         "N10 G92 X100\nN20 G1 X10 F20\nN30 G4 X1.5\nN40 M3 X20\nN50 Q1\nM2\n");
    Result r = run({QStringLiteral("compile"), QStringLiteral("--json"), file});
    EXPECT_EQ(r.exit, 1);
    QJsonParseError error{};
    QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &error);
    ASSERT_EQ(error.error, QJsonParseError::NoError) << r.out.toStdString();
    QJsonObject o = doc.object();
    EXPECT_EQ(o[QStringLiteral("file")].toString(), file);
    EXPECT_EQ(o[QStringLiteral("dialect")].toString(), QStringLiteral("standard"));
    EXPECT_FALSE(o[QStringLiteral("ok")].toBool(true));
    QJsonArray diags = o[QStringLiteral("diagnostics")].toArray();
    ASSERT_EQ(diags.size(), 1);
    QJsonObject d = diags[0].toObject();
    EXPECT_EQ(d[QStringLiteral("severity")].toString(), QStringLiteral("error"));
    EXPECT_EQ(d[QStringLiteral("code")].toString(), QStringLiteral("invalid-char"));
    EXPECT_EQ(d[QStringLiteral("line")].toInt(), 5);
    EXPECT_EQ(d[QStringLiteral("column")].toInt(), 5);
    EXPECT_EQ(d[QStringLiteral("n")].toInt(), 50);
    EXPECT_FALSE(d[QStringLiteral("message")].toString().isEmpty());
    QJsonArray blocks = o[QStringLiteral("blocks")].toArray();
    ASSERT_EQ(blocks.size(), 5);
    QJsonObject zero = blocks[0].toObject(), lin = blocks[1].toObject(),
                dwell = blocks[2].toObject(), go = blocks[3].toObject(), end = blocks[4].toObject();
    EXPECT_EQ(zero[QStringLiteral("op")].toString(), QStringLiteral("set_zero"));
    EXPECT_EQ(zero[QStringLiteral("zero")].toDouble(), 100.0);
    EXPECT_FALSE(zero.contains(QStringLiteral("x")));
    EXPECT_EQ(lin[QStringLiteral("op")].toString(), QStringLiteral("linear"));
    EXPECT_EQ(lin[QStringLiteral("x")].toDouble(), 110.0);
    EXPECT_EQ(lin[QStringLiteral("feed")].toDouble(), 20.0);
    EXPECT_FALSE(lin.contains(QStringLiteral("y")));
    EXPECT_EQ(dwell[QStringLiteral("seconds")].toDouble(), 1.5);
    EXPECT_EQ(go[QStringLiteral("target_n")].toInt(), 20);
    EXPECT_EQ(go[QStringLiteral("target_index")].toInt(), 1);
    EXPECT_EQ(end[QStringLiteral("op")].toString(), QStringLiteral("end"));
    EXPECT_TRUE(end[QStringLiteral("n")].isNull());
    EXPECT_EQ(end[QStringLiteral("line")].toInt(), 6);
}

TEST_F(CliCompile, UsageAndFileErrorsExitTwoWithOneLine) {
    const QString ok = write(QStringLiteral("ok.G"), "M2\n");
    for (const QStringList& args :
         {QStringList{QStringLiteral("compile")},
          QStringList{QStringLiteral("compile"), dir.filePath(QStringLiteral("missing.G"))},
          QStringList{QStringLiteral("compile"), dir.path()},
          QStringList{QStringLiteral("compile"), QStringLiteral("--dialect"),
                      QStringLiteral("basic"), ok},
          QStringList{QStringLiteral("compile"), QStringLiteral("--lang"), QStringLiteral("fr"),
                      ok},
          QStringList{QStringLiteral("compile"), QStringLiteral("--bogus"), ok},
          QStringList{QStringLiteral("frobnicate")}, QStringList{}}) {
        Result r = run(args);
        EXPECT_EQ(r.exit, 2) << args.join(QLatin1Char(' ')).toStdString();
        EXPECT_TRUE(r.out.isEmpty());
        EXPECT_FALSE(r.err.isEmpty());
        if (!args.isEmpty() && args[0] == QLatin1String("compile")) {
            EXPECT_EQ(r.err.count(QLatin1Char('\n')), 1) << r.err.toStdString();
        }
    }
}

TEST_F(CliCompile, UnreadableFileExitsTwo) {
    if (geteuid() == 0) GTEST_SKIP() << "root reads every file";
    QString file = write(QStringLiteral("secret.G"), "M2\n");
    QFile::setPermissions(file, QFileDevice::WriteOwner);
    EXPECT_EQ(run({QStringLiteral("compile"), file}).exit, 2);
}

TEST_F(CliCompile, BinaryFileGetsDiagnosticsNotACrash) {
    QByteArray bytes;
    for (int i = 0; i < 100000; ++i)
        bytes.append(static_cast<char>((i * 7919) & 0xFF));
    Result r = run({QStringLiteral("compile"), write(QStringLiteral("bin.G"), bytes)});
    EXPECT_EQ(r.exit, 1);
    EXPECT_TRUE(r.out.contains(QStringLiteral("error[invalid-char]")));
}

TEST_F(CliCompile, ExamplePrograms) {
    QDir programs(QStringLiteral(TRILHO_PROGRAMS_DIR));
    const QStringList files = programs.entryList({QStringLiteral("*.G")}, QDir::Files);
    ASSERT_GE(files.size(), 5);
    for (const QString& name : files) {
        QStringList args{QStringLiteral("compile"), programs.filePath(name)};
        if (name.endsWith(QLatin1String(".classic.G")))
            args << QStringLiteral("--dialect") << QStringLiteral("classic");
        // The plotter's programs (the objects of seed 001) are for its profile: X and Y.
        if (name.startsWith(QLatin1String("plotter_")))
            args << QStringLiteral("--machine")
                 << programs.filePath(QStringLiteral("../machines/xy_plotter.json"));
        // The DC XY table's programs (mesa_xy_*) are for its profile.
        if (name.startsWith(QLatin1String("mesa_xy_")))
            args << QStringLiteral("--machine")
                 << QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json");
        Result r = run(args);
        EXPECT_EQ(r.exit, 0) << name.toStdString() << "\n" << r.out.toStdString();
    }
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

namespace {

TEST(CliCompileMachine, TheProfileSetsAxesAndTravel) {
    QTemporaryDir dir;
    const QString program = dir.filePath(QStringLiteral("xy.G"));
    QFile f(program);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("G0 X100 Y50\nG1 Y350 F50\nM2\n");
    f.close();
    const QString xy = QStringLiteral(TRILHO_PROGRAMS_DIR "/../machines/xy_dc_table.json");
    // On the rail (default) y does not exist; on the XY table it does, within 0..300 mm.
    auto rail =
        trilho::test::runCli({QStringLiteral("compile"), QStringLiteral("--json"), program});
    auto table = trilho::test::runCli({QStringLiteral("compile"), QStringLiteral("--json"),
                                       QStringLiteral("--machine"), xy, program});
    const auto codes = [](const QString& json) {
        QStringList c;
        for (const auto& d : QJsonDocument::fromJson(json.toUtf8())
                                 .object()[QStringLiteral("diagnostics")]
                                 .toArray())
            c << d.toObject()[QStringLiteral("code")].toString();
        return c;
    };
    EXPECT_EQ(codes(rail.out),
              (QStringList{QStringLiteral("unknown-axis"), QStringLiteral("unknown-axis")}));
    EXPECT_EQ(codes(table.out), QStringList{QStringLiteral("soft-limit")});
    const QJsonArray blocks =
        QJsonDocument::fromJson(table.out.toUtf8()).object()[QStringLiteral("blocks")].toArray();
    ASSERT_EQ(blocks.size(), 2);
    EXPECT_EQ(blocks[0].toObject()[QStringLiteral("y")].toDouble(), 50.0);
    auto missing = trilho::test::runCli({QStringLiteral("compile"), QStringLiteral("--machine"),
                                         dir.filePath(QStringLiteral("none.json")), program});
    EXPECT_EQ(missing.exit, 2);
}

}  // namespace
