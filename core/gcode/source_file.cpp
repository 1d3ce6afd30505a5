#include "core/gcode/source_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace trilho {

SourceFile readSourceFile(const std::string& path) {
    return readRegularFile(path, "'" + path + "'", kMaxSourceBytes, "a program file");
}

SourceFile readRegularFile(const std::string& path, const std::string& label, long long maxBytes,
                           const std::string& limitFor) {
    SourceFile f;
    auto fail = [&](const char* what) {
        f.error = "cannot " + std::string(what) + " " + label + ": " + std::strerror(errno);
        return f;
    };
    auto refuse = [&](int fd, const std::string& why) {
        ::close(fd);
        f.error = "cannot read " + label + ": " + why;
        return f;
    };
    const std::string size = maxBytes >= (1LL << 20) && maxBytes % (1LL << 20) == 0
                                 ? std::to_string(maxBytes >> 20) + " MB"
                                 : std::to_string(maxBytes) + " bytes";
    const std::string tooLarge = "larger than " + size + " (the limit for " + limitFor + ")";
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
    if (st.st_size > maxBytes) return refuse(fd, tooLarge);
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
        if (static_cast<long long>(f.bytes.size()) + got > maxBytes) {
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
