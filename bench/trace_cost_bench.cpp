// trilho-bench-trace: what --trace costs a virtual-time run of the rail (issue 21 item 3: "a
// trace must slow a run by at most 1.5x to a file or a pipe, in a benchmark").
//
// Each mode runs the same program with the loop of `trilho-cli run --virtual-time`
// (runRailVirtual, app/cli/rail_virtual_run.cpp: the same code, not a copy):
//   none     no --trace;
//   file     --trace to a regular file (QSaveFile, renamed into place at the end);
//   pipe     --trace to a FIFO that a reader thread drains (as `| cat > /dev/null` would).
// For comparison, the writer this replaced: each row formatted and written on the run's own
// thread (the same CsvRow rows and 64 KB blocks, no writer thread), to a file and to a pipe:
//   inline-file, inline-pipe.
// Runs are interleaved (mode after mode, then again) so a busy machine weighs on each alike;
// the figures are the median, fastest and slowest wall time per mode, and the ratio of each
// median to the median of `none`.
//
// --long: one run of more than 10 minutes of machine time traced to a pipe, checking that the
// reader got one row per tick (no drop), with its wall time.
//
// Usage: trilho-bench-trace [--runs N (default 9)] [--long]
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/rail_trace.h"
#include "app/cli/rail_virtual_run.h"
#include "app/cli/run_supervisor.h"
#include "core/gcode/compiler.h"
#include "host/session/sim_session.h"

using namespace trilho;
using namespace trilho::cli;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// A FIFO and a thread that reads it to the end, counting the lines (rows + header).
class PipeReader {
  public:
    explicit PipeReader(const QString& path) : path_(path) {
        ::mkfifo(QFile::encodeName(path).constData(), 0600);
        // Opened without blocking (no writer yet), then made blocking: the writer's open then
        // finds a reader, as `trilho-cli run --trace FIFO` requires.
        fd_ = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK);
        ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    }
    /// After the writer opened the FIFO: before, a read would see its end at once.
    void start() {
        thread_ = std::thread([this] {
            std::vector<char> buf(1 << 16);
            while (true) {
                const ssize_t n = ::read(fd_, buf.data(), buf.size());
                if (n <= 0) break;  // 0: the writer closed it
                lines_ += static_cast<std::uint64_t>(std::count(buf.data(), buf.data() + n, '\n'));
            }
        });
    }
    std::uint64_t join() {
        if (thread_.joinable()) thread_.join();
        return lines_;
    }
    ~PipeReader() {
        join();
        ::close(fd_);
        ::unlink(QFile::encodeName(path_).constData());
    }

  private:
    QString path_;
    int fd_ = -1;
    std::thread thread_;
    std::uint64_t lines_ = 0;
};

enum class Mode { None, File, Pipe, InlineFile, InlinePipe };
const char* const kModeNames[] = {"none", "file", "pipe", "inline-file", "inline-pipe"};

/// The former loop: runRailVirtual's, with each row formatted and written on this thread.
Outcome runInline(const MachineProfile& profile, std::shared_ptr<const Program> program,
                  const RunOptions& options, Report& report, TraceFile& trace) {
    SimSession session(profile, options.seed);
    RailController& c = session.controller();
    c.selectAutomatic();
    c.loadProgram(std::move(program));
    c.start(0);
    Supervisor sup{options};
    Outcome outcome = Outcome::Finished;
    CsvRow row;
    while (true) {
        session.step();
        c.drainEvents([&](const ControllerEvent& e) { report.add(e); });
        const ControllerStatus& s = c.status();
        formatRailTraceRow({s.timeS, s.blockN, s.servo.setpointMm, s.servo.positionMm,
                            s.servo.errorMm, s.servo.velocityMmS, s.servo.loop.code},
                           row);
        trace.line(row.data(), static_cast<qint64>(row.size()));
        bool press = false;
        if (sup.check(s, s.timeS, outcome, press)) break;
        if (press) c.pressContinue();
    }
    return outcome;
}

struct RunFigures {
    double wallMs = 0.0;
    double machineS = 0.0;
    std::uint64_t rowsRead = 0;  ///< pipe: lines the reader got, header included
    bool ok = false;
};

RunFigures runOnce(Mode mode, const std::shared_ptr<const Program>& program, QTemporaryDir& dir) {
    RunOptions options;
    options.virtualTime = true;
    Report report;
    const bool pipe = mode == Mode::Pipe || mode == Mode::InlinePipe;
    std::unique_ptr<PipeReader> reader;
    QString path;
    if (pipe) {
        path = dir.filePath(QStringLiteral("trace.fifo"));
        reader = std::make_unique<PipeReader>(path);
    } else if (mode != Mode::None) {
        path = dir.filePath(QStringLiteral("trace.csv"));
    }
    RunFigures f;
    QElapsedTimer clock;
    clock.start();
    TraceFile trace;
    QString error;
    if (!trace.open(path, kRailTraceHeader, &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return f;
    }
    if (reader) reader->start();
    ControllerStatus last;
    double plantMm = 0.0;
    const Outcome outcome = mode == Mode::InlineFile || mode == Mode::InlinePipe
                                ? runInline(MachineProfile::rail(), program, options, report, trace)
                                : runRailVirtual(MachineProfile::rail(), program, options, report,
                                                 trace, last, plantMm);
    const bool traceOk = trace.close();
    if (reader) f.rowsRead = reader->join();
    f.wallMs = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
    f.machineS = last.timeS;
    f.ok = outcome == Outcome::Finished && traceOk;
    if (!traceOk) std::fprintf(stderr, "%s\n", qPrintable(trace.error()));
    return f;
}

std::shared_ptr<const Program> compileOrDie(const char* text) {
    auto program = std::make_shared<Program>(compile(text, CompileOptions{}));
    if (!program->ok()) {
        std::fprintf(stderr, "the benchmark's program does not compile\n");
        std::exit(1);
    }
    return program;
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int runs = 9;
    bool longRun = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (std::strcmp(argv[i], "--long") == 0) {
            longRun = true;
        } else {
            std::fprintf(stderr, "usage: trilho-bench-trace [--runs N] [--long]\n");
            return 2;
        }
    }
    QTemporaryDir dir;
    // About 30 s of machine time (30,000 rows at 1 kHz, 1.6 MB of CSV): the fixed costs
    // (opening, the rename at the end) are small beside the rows.
    const auto program = compileOrDie(
        "N10 G1 X600 F20\nN20 G1 X-600 F20\nN30 G1 X600 F20\nN40 G1 X-600 F20\n"
        "N50 G1 X600 F20\nN60 G1 X-600 F20\nN70 G1 X600 F20\nN80 G1 X-600 F20\n"
        "N90 G0 X0\nN100 M2\n");
    const Mode modes[] = {Mode::None, Mode::File, Mode::Pipe, Mode::InlineFile, Mode::InlinePipe};
    std::vector<std::vector<double>> wall(std::size(modes));
    double machineS = 0.0;
    runOnce(Mode::File, program, dir);  // warm-up: the page cache, the allocator
    for (int r = 0; r < runs; ++r) {
        for (std::size_t m = 0; m < std::size(modes); ++m) {
            const RunFigures f = runOnce(modes[m], program, dir);
            if (!f.ok) {
                std::fprintf(stderr, "%s: the run did not finish cleanly\n", kModeNames[m]);
                return 1;
            }
            wall[m].push_back(f.wallMs);
            if (modes[m] == Mode::None) machineS = f.machineS;
        }
    }
    const double base = median(wall[0]);
    std::printf(
        "trace cost, rail, virtual time: %.1f s of machine time (%.0f ticks), %d runs "
        "per mode\n",
        machineS, machineS * 1000.0, runs);
    std::printf("%-12s %10s %10s %10s %10s %8s\n", "mode", "median ms", "min ms", "max ms",
                "ns/tick", "ratio");
    for (std::size_t m = 0; m < std::size(modes); ++m) {
        const double med = median(wall[m]);
        std::printf("%-12s %10.1f %10.1f %10.1f %10.0f %7.2fx\n", kModeNames[m], med,
                    *std::min_element(wall[m].begin(), wall[m].end()),
                    *std::max_element(wall[m].begin(), wall[m].end()),
                    med * 1e6 / (machineS * 1000.0), med / base);
    }
    if (longRun) {
        // 12 passes of 1200 mm at F20: over 10 minutes of machine time.
        std::string text;
        int n = 10;
        for (int k = 0; k < 24; ++k, n += 10)
            text += "N" + std::to_string(n) + (k % 2 ? " G1 X-600 F20\n" : " G1 X600 F20\n");
        text += "N" + std::to_string(n) + " G0 X0\nN" + std::to_string(n + 10) + " M2\n";
        const auto longProgram = compileOrDie(text.c_str());
        const RunFigures f = runOnce(Mode::Pipe, longProgram, dir);
        const double ticks = std::round(f.machineS * 1000.0);
        std::printf(
            "long run to a pipe: %.1f s of machine time, %.0f ticks, %llu rows read "
            "(header excluded), %s, %.0f ms wall\n",
            f.machineS, ticks, static_cast<unsigned long long>(f.rowsRead - 1),
            static_cast<double>(f.rowsRead - 1) == ticks ? "no drop" : "ROWS MISSING", f.wallMs);
        if (!f.ok || static_cast<double>(f.rowsRead - 1) != ticks) return 1;
    }
    return 0;
}
