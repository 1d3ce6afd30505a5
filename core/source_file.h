#pragma once
// Reads a whole program file, with a one-line reason when it cannot (missing, a directory,
// unreadable, too large). Plain POSIX, so the message carries the system's own wording.
#include <string>

namespace trilho {

struct SourceFile {
    bool ok = false;
    std::string bytes;  ///< the file's content, byte for byte
    std::string error;  ///< e.g. "cannot open 'x.G': No such file or directory"
};

/// Files larger than this are refused: the biggest real program is far smaller, and the
/// compiler keeps the whole text in memory.
inline constexpr long long kMaxSourceBytes = 512LL * 1024 * 1024;

SourceFile readSourceFile(const std::string& path);

}  // namespace trilho
