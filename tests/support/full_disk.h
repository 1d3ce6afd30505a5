#pragma once
// A small file system that can be filled (issue 30 item 1): a tmpfs of kBytes mounted on a new
// folder, so a test can put a good file there, fill the disk to the last byte and check that a
// writer keeps the good file and says it failed. Mounting needs root (CI and the fresh-machine
// check run as root); anywhere else the test is skipped with the reason.
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>

#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace trilho::test {

class FullDisk {
  public:
    static constexpr int kKiB = 512;  ///< the file system's size: enough for any test's good file

    FullDisk() {
        char tmpl[] = "/tmp/trilho-full-disk-XXXXXX";
        if (!::mkdtemp(tmpl)) {
            why_ = std::string("mkdtemp: ") + std::strerror(errno);
            return;
        }
        dir_ = tmpl;
        const std::string options = "size=" + std::to_string(kKiB) + "k,mode=0777";
        if (::mount("tmpfs", dir_.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) != 0) {
            why_ = std::string("cannot mount a tmpfs (needs root): ") + std::strerror(errno);
            ::rmdir(dir_.c_str());
            dir_.clear();
            return;
        }
        mounted_ = true;
    }
    ~FullDisk() {
        if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
        if (!dir_.empty()) ::rmdir(dir_.c_str());
    }
    FullDisk(const FullDisk&) = delete;
    FullDisk& operator=(const FullDisk&) = delete;

    bool ready() const { return mounted_; }
    /// Why the disk could not be made (for GTEST_SKIP).
    const std::string& why() const { return why_; }
    QString dir() const { return QString::fromStdString(dir_); }
    QString path(const QString& name) const { return QDir(dir()).filePath(name); }

    /// Fills the file system to its last byte (a filler file written until ENOSPC); every write
    /// after this fails for lack of space while new (empty) files can still be created.
    /// False when the filler could not be written for another reason.
    [[nodiscard]] bool fill() {
        const std::string filler = dir_ + "/.filler";
        const int fd = ::open(filler.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
        if (fd < 0) return false;
        static const std::string block(4096, 'x');
        bool ok = true;
        for (std::size_t chunk = block.size(); chunk > 0 && ok;) {
            const ssize_t n = ::write(fd, block.data(), chunk);
            if (n < 0 && errno == ENOSPC)
                chunk /= 2;  // the last pages: down to a byte
            else if (n < 0 && errno != EINTR)
                ok = false;
        }
        ::close(fd);
        return ok;
    }
    /// Frees the disk again (the filler removed).
    void drain() { ::unlink((dir_ + "/.filler").c_str()); }

    /// The content of a file there (empty when missing).
    static QByteArray read(const QString& file) {
        QFile f(file);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
    /// Names in the folder other than the filler (a temporary file left behind shows here).
    QStringList entries() const {
        QStringList names = QDir(dir()).entryList(QDir::Files | QDir::Hidden | QDir::System);
        names.removeAll(QStringLiteral(".filler"));
        return names;
    }

  private:
    std::string dir_;
    std::string why_;
    bool mounted_ = false;
};

}  // namespace trilho::test

/// Declares `disk`, a FullDisk, or skips the test with the reason: GoogleTest ...
#define TRILHO_FULL_DISK(disk)     \
    ::trilho::test::FullDisk disk; \
    if (!disk.ready()) GTEST_SKIP() << disk.why();
/// ... and QtTest.
#define TRILHO_FULL_DISK_QT(disk)  \
    ::trilho::test::FullDisk disk; \
    if (!disk.ready()) QSKIP(disk.why().c_str());
