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
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return fail("open");
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        ::close(fd);
        return fail("read");
    }
    if (S_ISDIR(st.st_mode)) {
        ::close(fd);
        f.error = "cannot read '" + path + "': it is a directory";
        return f;
    }
    if (st.st_size > kMaxSourceBytes) {
        ::close(fd);
        f.error = "cannot read '" + path + "': larger than " +
                  std::to_string(kMaxSourceBytes >> 20) + " MB";
        return f;
    }
    if (S_ISREG(st.st_mode)) f.bytes.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    while (true) {
        ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0) {
            if (errno == EINTR) continue;
            int saved = errno;
            ::close(fd);
            errno = saved;
            return fail("read");
        }
        if (got == 0) break;
        if (static_cast<long long>(f.bytes.size()) + got > kMaxSourceBytes) {
            ::close(fd);
            f.error = "cannot read '" + path + "': larger than " +
                      std::to_string(kMaxSourceBytes >> 20) + " MB";
            return f;
        }
        f.bytes.append(buffer, static_cast<std::size_t>(got));
    }
    ::close(fd);
    f.ok = true;
    return f;
}

}  // namespace trilho
