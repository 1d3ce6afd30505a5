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
// the figures are the median, fastest and slowest wall time per mode and the ratio of each
// median to the median of `none`, then the median CPU time of the run's own thread and of the
// whole process with their ratios (where the time went), and the load average.
//
// --long: one run of more than 10 minutes of machine time traced to a pipe, checking that the
// reader got one row per tick (no drop), with its wall time.
//
// Usage: trilho-bench-trace [--runs N (default 9)] [--long] [--only MODE (for a profiler)]
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

/// CPU time, ms: of this thread (the run's), or of the whole process (the run, the writer
/// thread and, for a pipe, the reader thread), user and system.
double cpuMs(int who) {
    rusage u{};
    ::getrusage(who, &u);
    return (static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 +
            static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3);
}

struct RunFigures {
    double wallMs = 0.0;
    double runCpuMs = 0.0;      ///< the run's own thread
    double processCpuMs = 0.0;  ///< every thread of the process
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
    // A new file each run, as a first trace is: replacing the last run's 6 MB would also free
    // its page cache, a cost of the file system's, not of the trace.
    if (mode == Mode::File || mode == Mode::InlineFile) QFile::remove(path);
    RunFigures f;
    const double thread0 = cpuMs(RUSAGE_THREAD), process0 = cpuMs(RUSAGE_SELF);
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
    f.runCpuMs = cpuMs(RUSAGE_THREAD) - thread0;
    f.processCpuMs = cpuMs(RUSAGE_SELF) - process0;
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

/// A program of `count` passes of 1200 mm at F20 (3.75 s each), back to 0, then m02.
std::string passes(int count) {
    std::string text;
    int n = 10;
    for (int k = 0; k < count; ++k, n += 10)
        text += "N" + std::to_string(n) + (k % 2 ? " G1 X-600 F20\n" : " G1 X600 F20\n");
    text += "N" + std::to_string(n) + " G0 X0\nN" + std::to_string(n + 10) + " M2\n";
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int runs = 9;
    bool longRun = false;
    int only = -1;  ///< --only MODE: that mode alone, for a profiler
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else if (std::strcmp(argv[i], "--long") == 0) {
            longRun = true;
        } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
            ++i;
            for (int m = 0; m < 5; ++m)
                if (std::strcmp(argv[i], kModeNames[m]) == 0) only = m;
            if (only < 0) {
                std::fprintf(stderr, "--only: none, file, pipe, inline-file or inline-pipe\n");
                return 2;
            }
        } else {
            std::fprintf(stderr, "usage: trilho-bench-trace [--runs N] [--long] [--only MODE]\n");
            return 2;
        }
    }
    QTemporaryDir dir;
    // About 120 s of machine time (120,000 rows at 1 kHz, 6.5 MB of CSV): the fixed costs
    // (opening, the writer thread's start, the rename at the end) are small beside the rows.
    const auto program = compileOrDie(passes(32).c_str());
    const Mode modes[] = {Mode::None, Mode::File, Mode::Pipe, Mode::InlineFile, Mode::InlinePipe};
    std::vector<std::vector<double>> wall(std::size(modes)), runCpu(std::size(modes)),
        processCpu(std::size(modes));
    double machineS = 0.0;
    runOnce(Mode::File, program, dir);  // warm-up: the page cache, the allocator
    for (int r = 0; r < runs; ++r) {
        for (std::size_t m = 0; m < std::size(modes); ++m) {
            if (only >= 0 && static_cast<int>(m) != only) continue;
            const RunFigures f = runOnce(modes[m], program, dir);
            if (!f.ok) {
                std::fprintf(stderr, "%s: the run did not finish cleanly\n", kModeNames[m]);
                return 1;
            }
            wall[m].push_back(f.wallMs);
            runCpu[m].push_back(f.runCpuMs);
            processCpu[m].push_back(f.processCpuMs);
            if (modes[m] == Mode::None) machineS = f.machineS;
        }
    }
    if (only >= 0) {
        std::printf("%s: median %.1f ms wall, %.1f ms CPU of the run's thread\n", kModeNames[only],
                    median(wall[static_cast<std::size_t>(only)]),
                    median(runCpu[static_cast<std::size_t>(only)]));
        return 0;
    }
    const double base = median(wall[0]);
    std::printf(
        "trace cost, rail, virtual time: %.1f s of machine time (%.0f ticks), %d runs "
        "per mode\n",
        machineS, machineS * 1000.0, runs);
    // Wall time is what the issue bounds; the CPU times say where it went: the run's own thread
    // (what tracing adds to the loop itself) and the whole process (the writer and the pipe's
    // reader too). On a machine with no core free, wall time follows the process's CPU time.
    std::printf("%-12s %10s %8s %8s %8s %8s | %9s %6s | %9s %6s\n", "mode", "wall ms", "min", "max",
                "ns/tick", "ratio", "run cpu", "ratio", "all cpu", "ratio");
    const double baseRun = median(runCpu[0]), baseAll = median(processCpu[0]);
    for (std::size_t m = 0; m < std::size(modes); ++m) {
        const double med = median(wall[m]);
        std::printf("%-12s %10.1f %8.1f %8.1f %8.0f %7.2fx | %9.1f %5.2fx | %9.1f %5.2fx\n",
                    kModeNames[m], med, *std::min_element(wall[m].begin(), wall[m].end()),
                    *std::max_element(wall[m].begin(), wall[m].end()),
                    med * 1e6 / (machineS * 1000.0), med / base, median(runCpu[m]),
                    median(runCpu[m]) / baseRun, median(processCpu[m]),
                    median(processCpu[m]) / baseAll);
    }
    double load[3] = {0, 0, 0};
    if (::getloadavg(load, 3) == 3)
        std::printf(
            "load average now %.2f %.2f %.2f on %u cores: a busy machine leaves the "
            "writer thread no core of its own\n",
            load[0], load[1], load[2], std::thread::hardware_concurrency());
    // What the writer thread spends per row on formatting alone (no I/O): the rows of the
    // run's own shape, 1,000,000 of them, median of the runs.
    {
        std::vector<double> ns;
        CsvRow row;
        std::size_t bytes = 0;
        for (int r = 0; r < runs; ++r) {
            const double cpu0 = cpuMs(RUSAGE_THREAD);
            for (std::size_t k = 0; k < 1'000'000; ++k) {
                const double t = 0.001 * static_cast<double>(k + 1);
                const double x = 600.0 * std::sin(0.37 * t);
                formatRailTraceRow(
                    {t, static_cast<std::int32_t>(k / 1000) * 10, x + 0.0123456, x, 0.0123456,
                     25.0 * std::cos(0.37 * t), static_cast<std::uint8_t>(k % 256)},
                    row);
                bytes += row.size();
            }
            ns.push_back(cpuMs(RUSAGE_THREAD) - cpu0);  // ms for 1e6 rows: ns a row
        }
        std::printf(
            "formatting alone: %.0f ns of CPU a row (median of %d x 1,000,000 rows, %.0f bytes "
            "a row; the sin and cos of the rows' values included)\n",
            median(ns), runs, static_cast<double>(bytes) / (runs * 1e6));
    }
    if (longRun) {
        // 164 passes of 1200 mm at F20: over 10 minutes of machine time.
        const std::string text = passes(164);
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
