// Issue 30 item 11: the link answered "applied" to commands that did nothing. A Hold with no
// program running, and a commit by a client that wrote nothing into the download block (its
// writes all refused, or nothing since its last commit), are answered "nothing to do" (result 8),
// never "applied"; another client's download in progress stays busy (4), and the owner of a
// download whose commit failed may commit it again.
#include <gtest/gtest.h>

#include <QDir>
#include <QRegularExpression>

#include "tests/integration/dnc_virtual_rig.h"

namespace trilho::dnc {
namespace {

using test::kClientA;
using test::kClientB;
class DncNothingToDo : public test::VirtualRigTest {};

constexpr auto kApplied = static_cast<std::uint16_t>(CommandResult::Applied);
constexpr auto kBusy = static_cast<std::uint16_t>(CommandResult::Busy);
constexpr auto kSaveFailed = static_cast<std::uint16_t>(CommandResult::SaveFailed);
constexpr auto kNothingToDo = static_cast<std::uint16_t>(CommandResult::NothingToDo);

const QByteArray kProgram = "G1 X10 F50\nM2\n";

/// Function 21: file `file`, records from `record`, two bytes each.
QByteArray fileWrite(std::uint16_t file, std::uint16_t record, const QByteArray& bytes) {
    QByteArray sub;
    sub.append(static_cast<char>(kFileReferenceType));
    test::appendU16(sub, file);
    test::appendU16(sub, record);
    test::appendU16(sub, static_cast<std::uint16_t>(bytes.size() / 2));
    sub.append(bytes);
    return QByteArray(1, static_cast<char>(sub.size())) + sub;
}

TEST_F(DncNothingToDo, AHoldWithNoProgramRunningIsNothingToDoNeverApplied) {
    // Manual, at rest.
    ASSERT_EQ(rig.machine.snapshot().state, ControllerState::Manual);
    EXPECT_EQ(rig.command(Command::Hold, 0, 1), kNothingToDo) << rig.said().toStdString();
    EXPECT_EQ(rig.machine.snapshot().state, ControllerState::Manual);
    // Automatic, homed, idle: still nothing to hold.
    ASSERT_EQ(rig.command(Command::SelectAutomatic, 0, 2), kApplied);
    ASSERT_TRUE(rig.runUntil(
        [](const ControllerStatus& s) { return s.state == ControllerState::AutoIdle && s.homed; },
        60.0));
    EXPECT_EQ(rig.command(Command::Hold, 0, 3), kNothingToDo) << rig.said().toStdString();
    EXPECT_EQ(rig.machine.snapshot().state, ControllerState::AutoIdle);
    // The history says why, naming the client, and never that the hold was taken.
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("command hold (sequence 3) from 127.0.0.1:5020: "
                                         "nothing to do"))
                  .size(),
              1)
        << rig.said().toStdString();
    EXPECT_TRUE(rig.history
                    .filter(QRegularExpression(QStringLiteral("command hold \\(sequence "
                                                              "[13]\\) from [0-9.:]+$")))
                    .isEmpty())
        << rig.said().toStdString();

    // A program running: the hold is taken, and the machine shows it.
    QFile f(rig.dir.filePath(QStringLiteral("0042.G")));
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("G1 X200 F10\nM2\n");
    f.close();
    ASSERT_EQ(rig.command(Command::StartProgram, 42, 4), kApplied) << rig.said().toStdString();
    ASSERT_TRUE(rig.runUntil(
        [](const ControllerStatus& s) { return s.state == ControllerState::Running; }, 10.0));
    EXPECT_EQ(rig.command(Command::Hold, 0, 5), kApplied);
    EXPECT_EQ(rig.machine.snapshot().state, ControllerState::Paused);
    EXPECT_EQ(rig.machine.snapshot().pause, PauseReason::Hold);
    // Held already: a second hold does nothing.
    EXPECT_EQ(rig.command(Command::Hold, 0, 6), kNothingToDo);
    EXPECT_EQ(rig.machine.snapshot().pause, PauseReason::Hold);
}

TEST_F(DncNothingToDo, ACommitByAClientWhoseWritesWereAllRefusedIsNothingToDo) {
    rig.writeDownload(42, kProgram, kClientA);
    ASSERT_EQ(rig.command(Command::CommitDownload, 42, 1, kClientA), kApplied)
        << rig.said().toStdString();
    ASSERT_EQ(rig.programFile(42), kProgram);
    // B's writes into the block are refused (a byte that is not ASCII, by function 16 and by
    // function 21): nothing of B's is in the block, and A's text is still there.
    EXPECT_TRUE(rig.write(hold::kDownloadData, {0xFF00}, kClientB).isException());
    EXPECT_TRUE(rig.request(QModbusPdu::WriteFileRecord, fileWrite(42, 1, "\xff\x01"), kClientB)
                    .isException());
    // B's commit would save A's text again under B's name: nothing to do.
    EXPECT_EQ(rig.command(Command::CommitDownload, 42, 2, kClientB), kNothingToDo)
        << rig.said().toStdString();
    EXPECT_EQ(rig.history.filter(QStringLiteral("program 42 saved")).size(), 1)
        << rig.said().toStdString();
    EXPECT_EQ(rig.history
                  .filter(QStringLiteral("commit download (sequence 2) from "
                                         "127.0.0.1:5021: nothing to do"))
                  .size(),
              1)
        << rig.said().toStdString();
}

TEST_F(DncNothingToDo, ACommitWithNothingWrittenSinceTheLastIsNothingToDo) {
    // Nothing ever written.
    EXPECT_EQ(rig.command(Command::CommitDownload, 7, 1), kNothingToDo);
    rig.writeDownload(42, kProgram);
    ASSERT_EQ(rig.command(Command::CommitDownload, 42, 2), kApplied);
    // The same commit again: the block was committed, nothing new in it.
    EXPECT_EQ(rig.command(Command::CommitDownload, 42, 3), kNothingToDo);
    EXPECT_EQ(rig.history.filter(QStringLiteral("program 42 saved")).size(), 1)
        << rig.said().toStdString();
}

TEST_F(DncNothingToDo, AFileRecordWriteRefusedDoesNotMakeItsClientTheBlocksOwner) {
    rig.writeDownload(42, kProgram, kClientA);
    ASSERT_EQ(rig.command(Command::CommitDownload, 42, 1, kClientA), kApplied);
    // B's only write, refused (not ASCII), then A writes again: the block is A's, not B's.
    EXPECT_TRUE(rig.request(QModbusPdu::WriteFileRecord, fileWrite(42, 1, "\xff\x01"), kClientB)
                    .isException());
    EXPECT_FALSE(rig.write(hold::kDownloadNumber, {43, std::uint16_t(kProgram.size())}, kClientA)
                     .isException());
    EXPECT_EQ(rig.command(Command::CommitDownload, 43, 2, kClientA), kApplied)
        << rig.said().toStdString();
    EXPECT_EQ(rig.programFile(43), kProgram);
}

TEST_F(DncNothingToDo, AnotherClientsDownloadInProgressIsStillBusy) {
    rig.writeDownload(42, kProgram, kClientA);
    EXPECT_EQ(rig.command(Command::CommitDownload, 42, 1, kClientB), kBusy);
    EXPECT_EQ(rig.command(Command::CommitDownload, 42, 2, kClientA), kApplied);
    EXPECT_EQ(rig.programFile(42), kProgram);
}

TEST_F(DncNothingToDo, TheOwnerOfADownloadWhoseSaveFailedCommitsItAgain) {
    // A folder stands at the program's name: the save fails (as on a full disk).
    ASSERT_TRUE(QDir(rig.dir.path()).mkdir(QStringLiteral("0044.G")));
    rig.writeDownload(44, kProgram);
    EXPECT_EQ(rig.command(Command::CommitDownload, 44, 1), kSaveFailed);
    // The operator makes room; the client commits again what it wrote, without rewriting it.
    ASSERT_TRUE(QDir(rig.dir.path()).rmdir(QStringLiteral("0044.G")));
    EXPECT_EQ(rig.command(Command::CommitDownload, 44, 2), kApplied) << rig.said().toStdString();
    EXPECT_EQ(rig.programFile(44), kProgram);
}

}  // namespace
}  // namespace trilho::dnc
