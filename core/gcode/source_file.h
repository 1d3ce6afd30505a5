#pragma once
// Reads a whole program file (or any small input file, e.g. a machine profile), with a one-line
// reason when it cannot (missing, a directory, not a regular file, unreadable, too large). Plain
// POSIX, so the message carries the system's own wording.
#include <string>

namespace trilho {

struct SourceFile {
    bool ok = false;
    std::string bytes;  ///< the file's content, byte for byte
    std::string error;  ///< e.g. "cannot open 'x.G': No such file or directory"
};

/// Files larger than this are refused: the biggest real program is far smaller (a million
/// lines is about 25 MB), and the compiler keeps the whole text and its blocks in memory.
inline constexpr long long kMaxSourceBytes = 64LL * 1024 * 1024;

/// Reads path (bytes as given to open(2), any encoding). Only regular files are read: a FIFO or
/// a device is refused at once instead of blocking (it is opened non-blocking, then checked).
SourceFile readSourceFile(const std::string& path);

/// The same for any input file: at most maxBytes, regular files only. label names the file in
/// the messages ("cannot open <label>: ...", e.g. "machine profile 'rail.json'"); limitFor says
/// whose limit a too-large file passed ("larger than 1 MB (the limit for <limitFor>)").
SourceFile readRegularFile(const std::string& path, const std::string& label, long long maxBytes,
                           const std::string& limitFor);

}  // namespace trilho
