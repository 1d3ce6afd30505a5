// Issue 20 item 8, the library half: the program library serves and replaces regular files
// inside its folder only. An entry that is a symbolic link (to a file outside, inside, or
// nowhere), a folder, a FIFO, a socket, a device or a file with another name (a hard link) is
// refused with a message naming it; a download never writes through a link, and a failed one
// leaves the old program whole. Ends with a property test over random folders of such entries.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <random>

#include "core/gcode/source_file.h"
#include "host/dnc/folder_entry.h"
#include "host/dnc/program_library.h"
#include "tests/support/full_disk.h"

namespace trilho::dnc {
namespace {

constexpr qint64 kFileRecordBytes = 19998;  // what function 20 asks for (docs/dnc.md)
const QByteArray kProgram = "N10 G01 X10 F20\nN20 M02\n";
const QByteArray kSecret = "secret: not a program\n";

QByteArray contents(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return f.readAll();
}

void put(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate)) << path.toStdString();
    ASSERT_EQ(f.write(bytes), bytes.size());
}

ino_t inodeOf(const QString& path) {
    struct stat s {};
    if (::lstat(QFile::encodeName(path).constData(), &s) != 0) return 0;
    return s.st_ino;
}

/// A unix socket bound at path (kept open while the object lives).
struct Socket {
    int fd = -1;
    explicit Socket(const QString& path) {
        fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un a{};
        a.sun_family = AF_UNIX;
        const QByteArray p = QFile::encodeName(path);
        if (p.size() >= static_cast<qsizetype>(sizeof a.sun_path)) return;
        std::memcpy(a.sun_path, p.constData(), static_cast<std::size_t>(p.size()));
        if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) ::close(fd), fd = -1;
    }
    ~Socket() {
        if (fd >= 0) ::close(fd);
    }
};

struct Library {
    QTemporaryDir root;  ///< the library is root/programs; root/outside.txt is outside it
    QString dir = root.path() + QStringLiteral("/programs");
    QString outside = root.path() + QStringLiteral("/outside.txt");
    ProgramLibrary library{dir, CompileOptions{}};
    Library() {
        QDir().mkpath(dir);
        put(outside, kSecret);
    }
    QString at(int n) const { return library.pathOf(n); }
    std::string readError(int n) const {
        QString e;
        EXPECT_FALSE(library.read(n, kFileRecordBytes, &e).has_value()) << n;
        return e.toStdString();
    }
    std::string loadError(int n) const {
        QString e;
        EXPECT_FALSE(library.load(n, &e).has_value()) << n;
        return e.toStdString();
    }
    std::string saveError(int n) const {
        QString e;
        EXPECT_FALSE(library.save(n, kProgram, &e)) << n;
        return e.toStdString();
    }
};

::testing::AssertionResult says(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << text << "' does not say '" << part << "'";
}

TEST(ProgramLibrary, ARegularFileIsServedLoadedListedAndReplaced) {
    Library l;
    put(l.at(42), kProgram);
    QString e;
    EXPECT_EQ(l.library.read(42, kFileRecordBytes, &e).value_or("?"), kProgram);
    const auto p = l.library.load(42, &e);
    ASSERT_TRUE(p.has_value()) << e.toStdString();
    EXPECT_TRUE((*p)->ok());
    EXPECT_TRUE(l.library.exists(42));
    const auto list = l.library.list();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].number, 42);
    EXPECT_EQ(list[0].path, l.at(42));
    EXPECT_TRUE(list[0].refused.isEmpty());
    const ino_t before = inodeOf(l.at(42));
    ASSERT_TRUE(l.library.save(42, "N10 G01 X20 F20\n", &e)) << e.toStdString();
    EXPECT_EQ(contents(l.at(42)), QByteArray("N10 G01 X20 F20\n"));
    EXPECT_NE(inodeOf(l.at(42)), before);  // a new file renamed over the name: atomic
    // No temporary file is left behind.
    EXPECT_EQ(QDir(l.dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System |
                                    QDir::NoDotAndDotDot),
              QStringList{QStringLiteral("0042.G")});
}

TEST(ProgramLibrary, AReplaceKeepsThePermissions) {
    Library l;
    put(l.at(7), kProgram);
    ASSERT_EQ(::chmod(QFile::encodeName(l.at(7)).constData(), 0640), 0);
    QString e;
    ASSERT_TRUE(l.library.save(7, kProgram, &e)) << e.toStdString();
    struct stat s {};
    ASSERT_EQ(::stat(QFile::encodeName(l.at(7)).constData(), &s), 0);
    EXPECT_EQ(s.st_mode & 0777, 0640u);
}

TEST(ProgramLibrary, ALinkToAFileOutsideIsNotServed) {
    Library l;
    ASSERT_TRUE(QFile::link(l.outside, l.at(42)));
    EXPECT_TRUE(says(l.readError(42), l.at(42).toStdString() + "' is a symbolic link"));
    EXPECT_TRUE(says(l.loadError(42), "is a symbolic link"));
    EXPECT_FALSE(l.library.exists(42));
    const auto list = l.library.list();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_TRUE(says(list[0].refused.toStdString(), "is a symbolic link"));
}

TEST(ProgramLibrary, ALinkToEtcPasswdIsNotServed) {
    Library l;
    ASSERT_TRUE(QFile::link(QStringLiteral("/etc/passwd"), l.at(1)));
    EXPECT_TRUE(says(l.readError(1), "is a symbolic link"));
}

TEST(ProgramLibrary, ALinkToAnotherProgramInsideIsNotFollowedEither) {
    Library l;
    put(l.at(1), kProgram);
    ASSERT_TRUE(QFile::link(QStringLiteral("0001.G"), l.at(2)));
    EXPECT_TRUE(says(l.readError(2), "is a symbolic link"));
    EXPECT_EQ(l.library.read(1, kFileRecordBytes).value_or("?"), kProgram);
}

TEST(ProgramLibrary, ADownloadNeverWritesThroughALink) {
    Library l;
    ASSERT_TRUE(QFile::link(l.outside, l.at(42)));
    EXPECT_TRUE(says(l.saveError(42),
                     "will not replace '" + l.at(42).toStdString() + "': it is a symbolic link"));
    EXPECT_EQ(contents(l.outside), kSecret);
    EXPECT_TRUE(QFileInfo(l.at(42)).isSymLink());
}

TEST(ProgramLibrary, ADanglingLinkIsNeitherServedNorWrittenThrough) {
    Library l;
    const QString target = l.root.path() + QStringLiteral("/created-through-the-link");
    ASSERT_TRUE(QFile::link(target, l.at(9)));
    EXPECT_TRUE(says(l.readError(9), "is a symbolic link"));
    EXPECT_TRUE(says(l.saveError(9), "is a symbolic link"));
    EXPECT_FALSE(QFileInfo::exists(target));
}

TEST(ProgramLibrary, ALinkToAFolderOutsideIsRefused) {
    Library l;
    ASSERT_TRUE(QFile::link(l.root.path(), l.at(3)));
    EXPECT_TRUE(says(l.readError(3), "is a symbolic link"));
    EXPECT_TRUE(says(l.saveError(3), "is a symbolic link"));
}

TEST(ProgramLibrary, AFolderIsRefused) {
    Library l;
    ASSERT_TRUE(QDir().mkpath(l.at(5)));
    EXPECT_TRUE(says(l.readError(5), "is a folder"));
    EXPECT_TRUE(says(l.saveError(5), "is a folder"));
    EXPECT_TRUE(QFileInfo(l.at(5)).isDir());
}

TEST(ProgramLibrary, AFifoIsRefusedAtOnce) {
    Library l;
    ASSERT_EQ(::mkfifo(QFile::encodeName(l.at(6)).constData(), 0600), 0);
    EXPECT_TRUE(says(l.readError(6), "is a FIFO"));  // no writer: would block if opened
    EXPECT_TRUE(says(l.loadError(6), "is a FIFO"));
    EXPECT_TRUE(says(l.saveError(6), "is a FIFO"));
}

TEST(ProgramLibrary, ASocketIsRefused) {
    Library l;
    const Socket s(l.at(8));
    if (s.fd < 0) GTEST_SKIP() << "cannot bind a unix socket in " << l.dir.toStdString();
    EXPECT_TRUE(says(l.readError(8), "is a socket"));
    EXPECT_TRUE(says(l.saveError(8), "is a socket"));
}

TEST(ProgramLibrary, ADeviceIsRefusedNeverOpened) {
    Library l;
    // /dev/zero's numbers (1, 5): read, it would never end. Making one needs CAP_MKNOD.
    if (::mknod(QFile::encodeName(l.at(4)).constData(), S_IFCHR | 0600, makedev(1, 5)) != 0)
        GTEST_SKIP() << "cannot make a device node here (not root)";
    EXPECT_TRUE(says(l.readError(4), "is a device"));
    EXPECT_TRUE(says(l.loadError(4), "is a device"));
    EXPECT_TRUE(says(l.saveError(4), "is a device"));
}

TEST(ProgramLibrary, AHardLinkIsNotServedAndAReplaceLeavesTheOtherName) {
    Library l;
    const QString other = l.root.path() + QStringLiteral("/other-name.G");
    put(other, kSecret);
    ASSERT_EQ(::link(QFile::encodeName(other).constData(), QFile::encodeName(l.at(10)).constData()),
              0);
    EXPECT_TRUE(says(l.readError(10), "has 2 names (a hard link"));
    QString e;
    // Replacing the name is allowed: the other name keeps its content.
    ASSERT_TRUE(l.library.save(10, kProgram, &e)) << e.toStdString();
    EXPECT_EQ(contents(other), kSecret);
    EXPECT_EQ(contents(l.at(10)), kProgram);
    EXPECT_EQ(l.library.read(10, kFileRecordBytes).value_or("?"), kProgram);
}

TEST(ProgramLibrary, HugeFilesAreRefusedWithoutReadingThem) {
    Library l;
    put(l.at(11), QByteArray());
    // Sparse: a terabyte costs nothing on the disk, and is refused from its size alone.
    ASSERT_EQ(::truncate(QFile::encodeName(l.at(11)).constData(), 1LL << 40), 0);
    EXPECT_TRUE(says(l.readError(11), "larger than 19998 bytes"));
    EXPECT_TRUE(says(l.loadError(11), "larger than 64 MB (the limit for a program file)"));
    put(l.at(12), QByteArray(kFileRecordBytes + 1, 'N'));
    EXPECT_TRUE(says(l.readError(12), "larger than 19998 bytes (the limit for file records)"));
    // The screens' list reads only a head.
    EXPECT_EQ(l.library.readHead(11, 16).value_or("?"), QByteArray(16, '\0'));
}

TEST(ProgramLibrary, NumbersOutsideFourDigitsAreRefused) {
    Library l;
    EXPECT_TRUE(says(l.readError(10000), "no program number 10000"));
    EXPECT_TRUE(says(l.readError(-1), "no program number -1"));
    EXPECT_TRUE(says(l.saveError(-1), "no program number -1"));
    EXPECT_EQ(QDir(l.dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
              QStringList{});
}

TEST(ProgramLibrary, AMissingProgramSaysNoSuchFile) {
    Library l;
    EXPECT_TRUE(says(l.readError(77), l.at(77).toStdString()));
    EXPECT_TRUE(says(l.loadError(77), "No such file or directory"));
}

TEST(ProgramLibrary, TheFolderItselfMayBeALinkTheOperatorChose) {
    Library l;
    const QString alias = l.root.path() + QStringLiteral("/alias");
    ASSERT_TRUE(QFile::link(l.dir, alias));
    ProgramLibrary viaLink(alias, CompileOptions{});
    QString e;
    ASSERT_TRUE(viaLink.save(1, kProgram, &e)) << e.toStdString();
    EXPECT_EQ(contents(l.at(1)), kProgram);
    EXPECT_EQ(viaLink.read(1, kFileRecordBytes).value_or("?"), kProgram);
}

TEST(ProgramLibrary, AFolderThatIsAFileOrCannotBeMadeIsNamed) {
    Library l;
    ProgramLibrary onAFile(l.outside, CompileOptions{});
    QString e;
    EXPECT_FALSE(onAFile.save(1, kProgram, &e));
    EXPECT_TRUE(says(e.toStdString(), l.outside.toStdString()));
    EXPECT_FALSE(onAFile.read(1, kFileRecordBytes, &e));
    EXPECT_TRUE(says(e.toStdString(), "cannot open the library folder"));
    EXPECT_TRUE(onAFile.list().empty());
    EXPECT_EQ(contents(l.outside), kSecret);
}

TEST(ProgramLibrary, AFolderNotWritableLeavesTheOldProgram) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes in any folder";
    Library l;
    put(l.at(1), kProgram);
    ASSERT_EQ(::chmod(QFile::encodeName(l.dir).constData(), 0500), 0);
    const std::string e = l.saveError(1);
    ::chmod(QFile::encodeName(l.dir).constData(), 0700);
    EXPECT_TRUE(says(e, "cannot write '" + l.at(1).toStdString() + "': Permission denied"));
    EXPECT_EQ(contents(l.at(1)), kProgram);
}

TEST(ProgramLibrary, AWriteThatFailsHalfWayLeavesTheOldProgramWhole) {
    // A full disk, as the process sees it: a file size limit makes write(2) fail (EFBIG) after
    // 4 KB, deterministic and without a real full disk.
    Library l;
    put(l.at(1), kProgram);
    struct rlimit old {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldHandler = ::signal(SIGXFSZ, SIG_IGN);
    struct rlimit small = old;
    small.rlim_cur = 4096;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    QString e;
    const bool saved = l.library.save(1, QByteArray(8192, 'N'), &e);
    ::setrlimit(RLIMIT_FSIZE, &old);
    ::signal(SIGXFSZ, oldHandler);
    EXPECT_FALSE(saved);
    EXPECT_TRUE(
        says(e.toStdString(), "cannot write '" + l.at(1).toStdString() + "': File too large"));
    EXPECT_EQ(contents(l.at(1)), kProgram);
    EXPECT_EQ(QDir(l.dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System |
                                    QDir::NoDotAndDotDot),
              QStringList{QStringLiteral("0001.G")});
}

// The property: over random folders of every kind of entry, the library serves exactly the
// regular files with one name and at most the limit, byte for byte; it replaces exactly the
// missing entries and the regular files; nothing outside the folder ever changes; the list
// refuses exactly what read refuses.
enum class Kind {
    Missing,
    Regular,
    Empty,
    Huge,
    LinkOut,
    LinkIn,
    Dangling,
    LinkFolder,
    Folder,
    Fifo,
    Socket,
    HardLink,
    Device,
    Count_
};

TEST(ProgramLibraryProperty, ServesAndReplacesOnlyRegularFilesInside) {
    const bool root = ::geteuid() == 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        std::mt19937_64 rng(seed);
        Library l;
        const QString hardOutside = l.root.path() + QStringLiteral("/hard-outside");
        put(hardOutside, kSecret);
        std::vector<std::unique_ptr<Socket>> sockets;
        std::map<int, Kind> made;
        std::map<int, QByteArray> regular;
        for (int n = 1; n <= 24; ++n) {
            auto kind = static_cast<Kind>(rng() % static_cast<unsigned>(Kind::Count_));
            const QString path = l.at(n);
            const QByteArray p = QFile::encodeName(path);
            switch (kind) {
                case Kind::Missing:
                    break;
                case Kind::Regular: {
                    QByteArray text = "N10 G01 X" + QByteArray::number(n) + " F20\n";
                    text.append(QByteArray(static_cast<qsizetype>(rng() % 3000), ' '));
                    put(path, text);
                    regular[n] = text;
                    break;
                }
                case Kind::Empty:
                    put(path, QByteArray());
                    regular[n] = QByteArray();
                    break;
                case Kind::Huge:
                    put(path, QByteArray());
                    ASSERT_EQ(::truncate(p.constData(), kFileRecordBytes + 1 +
                                                            static_cast<off_t>(rng() % (1u << 30))),
                              0);
                    break;
                case Kind::LinkOut:
                    ASSERT_TRUE(QFile::link(l.outside, path));
                    break;
                case Kind::LinkIn:
                    ASSERT_TRUE(QFile::link(QStringLiteral("0001.G"), path));
                    break;
                case Kind::Dangling:
                    ASSERT_TRUE(QFile::link(l.root.path() + QStringLiteral("/nowhere"), path));
                    break;
                case Kind::LinkFolder:
                    ASSERT_TRUE(QFile::link(QStringLiteral(".."), path));
                    break;
                case Kind::Folder:
                    ASSERT_TRUE(QDir().mkpath(path));
                    break;
                case Kind::Fifo:
                    ASSERT_EQ(::mkfifo(p.constData(), 0600), 0);
                    break;
                case Kind::Socket:
                    sockets.push_back(std::make_unique<Socket>(path));
                    if (sockets.back()->fd < 0) kind = Kind::Missing;
                    break;
                case Kind::HardLink:
                    ASSERT_EQ(::link(QFile::encodeName(hardOutside).constData(), p.constData()), 0);
                    break;
                case Kind::Device:
                    if (!root || ::mknod(p.constData(), S_IFCHR | 0600, makedev(1, 5)) != 0)
                        kind = Kind::Missing;
                    break;
                case Kind::Count_:
                    break;
            }
            made[n] = kind;
        }
        const auto listed = l.library.list();
        std::map<int, QString> refusedInList;
        for (const LibraryEntry& e : listed)
            refusedInList[e.number] = e.refused;
        for (const auto& [n, kind] : made) {
            SCOPED_TRACE(testing::Message() << "seed " << seed << " program " << n << " kind "
                                            << static_cast<int>(kind));
            QString error;
            const auto text = l.library.read(n, kFileRecordBytes, &error);
            const bool served = kind == Kind::Regular || kind == Kind::Empty;
            EXPECT_EQ(text.has_value(), served) << error.toStdString();
            if (served) {
                EXPECT_EQ(*text, regular[n]);
            }
            if (!served) {
                EXPECT_TRUE(says(error.toStdString(), l.at(n).toStdString()));
            }
            EXPECT_EQ(l.library.exists(n), served || kind == Kind::Huge);
            if (kind == Kind::Missing) {
                EXPECT_EQ(refusedInList.count(n), 0u);
            } else {
                ASSERT_EQ(refusedInList.count(n), 1u);
                EXPECT_EQ(refusedInList[n].isEmpty(), served || kind == Kind::Huge);
            }
        }
        for (const auto& [n, kind] : made) {
            SCOPED_TRACE(testing::Message() << "seed " << seed << " program " << n << " kind "
                                            << static_cast<int>(kind));
            QString error;
            const QByteArray text = "N10 G01 X" + QByteArray::number(n + 1) + " F20\n";
            const bool replaceable = kind == Kind::Missing || kind == Kind::Regular ||
                                     kind == Kind::Empty || kind == Kind::Huge ||
                                     kind == Kind::HardLink;
            EXPECT_EQ(l.library.save(n, text, &error), replaceable) << error.toStdString();
            if (replaceable) {
                EXPECT_EQ(l.library.read(n, kFileRecordBytes).value_or("?"), text);
            }
        }
        // Nothing outside moved; nothing was created through a link; no temporary left.
        EXPECT_EQ(contents(l.outside), kSecret);
        EXPECT_EQ(contents(hardOutside), kSecret);
        EXPECT_FALSE(QFileInfo::exists(l.root.path() + QStringLiteral("/nowhere")));
        EXPECT_EQ(
            QDir(l.root.path())
                .entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot)
                .size(),
            3);  // programs, outside.txt, hard-outside
        for (const QString& name : QDir(l.dir).entryList(QDir::AllEntries | QDir::Hidden |
                                                         QDir::System | QDir::NoDotAndDotDot))
            EXPECT_FALSE(name.startsWith(QLatin1Char('.'))) << name.toStdString();
    }
}

// Issue 30 item 1: a download onto a full disk keeps the program that was there and says so.
TEST(ProgramLibraryFullDisk, ADownloadOnAFullDiskKeepsTheOldProgram) {
    TRILHO_FULL_DISK(disk);
    const QByteArray good("G00 X10\nM02\n");
    QString error;
    ASSERT_TRUE(replaceFolderEntry(disk.dir(), QStringLiteral("0007.G"), good, &error))
        << error.toStdString();
    ASSERT_TRUE(disk.fill());
    EXPECT_FALSE(replaceFolderEntry(disk.dir(), QStringLiteral("0007.G"),
                                    QByteArray(20000, ';') + "G00 X20\nM02\n", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("No space left on device"))) << error.toStdString();
    EXPECT_EQ(::trilho::test::FullDisk::read(disk.path(QStringLiteral("0007.G"))), good);
    EXPECT_EQ(disk.entries(), QStringList{QStringLiteral("0007.G")});
}

}  // namespace
}  // namespace trilho::dnc
