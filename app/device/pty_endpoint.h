#pragma once
// A pseudo-terminal for a device emulator: the emulator holds the master side, and prints the
// slave's path ("/dev/pts/7") for the host to open as if it were a USB serial port. The slave
// is kept open here too, so that the master reads nothing (instead of an error) while no host
// is connected, and a host may close and re-open it (an unplug and a re-plug).
#include <string>

namespace trilho {

class PtyEndpoint {
  public:
    PtyEndpoint() = default;
    ~PtyEndpoint();
    PtyEndpoint(const PtyEndpoint&) = delete;
    PtyEndpoint& operator=(const PtyEndpoint&) = delete;

    /// Opens the pair in raw mode, master non-blocking. False and errno's text on failure.
    bool open(std::string* error);
    int masterFd() const { return master_; }
    const std::string& slavePath() const { return path_; }

  private:
    int master_ = -1;
    int slave_ = -1;
    std::string path_;
};

}  // namespace trilho
