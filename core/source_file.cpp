#include "core/source_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace trilho {

SourceFile readSourceFile(const std::string& path) {
    SourceFile f;
    auto fail = [&](const char* what) {
        f.error = "cannot " + std::string(what) + " '" + path + "': " + std::strerror(errno);
        return f;
    };
    auto refuse = [&](int fd, const std::string& why) {
        ::close(fd);
        f.error = "cannot read '" + path + "': " + why;
        return f;
    };
    const std::string tooLarge = "larger than " + std::to_string(kMaxSourceBytes >> 20) +
                                 " MB (the limit for a program file)";
    // O_NONBLOCK: opening a FIFO with no writer would otherwise wait forever; for a regular
    // file the flag changes nothing.
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return fail("open");
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int saved = errno;
        ::close(fd);
        errno = saved;
        return fail("read");
    }
    if (S_ISDIR(st.st_mode)) return refuse(fd, "it is a directory");
    if (!S_ISREG(st.st_mode)) return refuse(fd, "not a regular file");
    if (st.st_size > kMaxSourceBytes) return refuse(fd, tooLarge);
    f.bytes.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    while (true) {
        ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0) {
            if (errno == EINTR) continue;
            const int saved = errno;
            ::close(fd);
            errno = saved;
            return fail("read");
        }
        if (got == 0) break;
        // The file may grow while it is read: the limit holds for what is read, too.
        if (static_cast<long long>(f.bytes.size()) + got > kMaxSourceBytes) {
            f.bytes.clear();
            f.bytes.shrink_to_fit();
            return refuse(fd, tooLarge);
        }
        f.bytes.append(buffer, static_cast<std::size_t>(got));
    }
    ::close(fd);
    f.ok = true;
    return f;
}

}  // namespace trilho
