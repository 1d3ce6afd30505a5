// The E-stop's latency at the screens (issue 30 item 3): from the F1 key event to the drive
// commanded to zero, with the screens at their busiest: a program running on the simulated
// machine, every dock open (floating, so each one paints), a large run loading in the tuning
// workbench over and over, the plots live, the history kept in a journal (in the temporary
// folder: its disk's sync time counts). A second thread posts F1 to the screens' event queue
// at random moments while the program runs (as a key from the X server waits there for the
// screens' thread); the machine stamps when the key reached the event filter and when its
// thread wrote the drive to zero (EStopStamp). Then the screens reset the E-stop and start the
// program again, and the next key waits for it to run.
//   trilho-bench-estop [--machine rail|dc_table|both] [--samples N] [--run-seconds S]
//                      [--run FILE.csv] [--seed K] [--stall-stacks MS]
// Prints, per machine: key event to drive at zero (median, p99, max), of which key event to the
// filter (the screens' thread's queue) and filter to drive at zero (the machine's thread), and
// the longest the screens' thread did not answer a 2 ms timer. QT_QPA_PLATFORM=offscreen.
// --stall-stacks MS: what holds the screens' thread: each time it has not answered for MS, a
// watcher thread interrupts it (SIGUSR2) and prints its stack to stderr (c++filt reads it).
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QKeyEvent>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include <execinfo.h>
#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include "core/profile/machine_profile.h"
#include "core/runtime/estop_stamp.h"
#include "core/tuning/run_record.h"
#include "host/session/xy_session_runnable.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/workbench/workbench_window.h"
#include "ui/xy/xy_main_window.h"

using namespace trilho;

namespace {

/// --stall-stacks: the screens' thread's stack whenever it has not answered for a while.
namespace stacks {
pthread_t screens;
std::atomic<std::int64_t> beatNs{0};  ///< the screens' thread's last 2 ms tick
void* frames[64];
std::atomic<int> depth{0};
void onSignal(int) {
    depth = backtrace(frames, 64);  // on the screens' thread, interrupted where it is
}
void start(double thresholdMs) {
    screens = pthread_self();
    signal(SIGUSR2, onSignal);
    void* warm[1];
    backtrace(warm, 1);  // loads what backtrace needs before a signal handler calls it
    auto* beat = new QTimer(qApp);
    beat->setInterval(2);
    QObject::connect(beat, &QTimer::timeout, [] { beatNs = monotonicNs(); });
    beat->start();
    const auto threshold = static_cast<std::int64_t>(thresholdMs * 1e6);
    std::thread([threshold] {
        std::int64_t reported = 0;
        while (true) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            const std::int64_t last = beatNs.load();
            const std::int64_t late = monotonicNs() - last;
            if (last == 0 || last == reported || late < threshold) continue;
            reported = last;
            depth = 0;
            pthread_kill(screens, SIGUSR2);
            for (int i = 0; i < 1000 && depth == 0; ++i)
                std::this_thread::sleep_for(std::chrono::microseconds(100));
            std::fprintf(stderr, "=== the screens' thread has not answered for %.1f ms:\n",
                         static_cast<double>(late) / 1e6);
            backtrace_symbols_fd(frames, depth, 2);
        }
    }).detach();
}
}  // namespace stacks

struct Options {
    QString machine = QStringLiteral("both");
    int samples = 100;
    double runSeconds = 600.0;  // the 10-minute run
    QString run;                // an existing run instead of the generated one
    std::uint64_t seed = 1;
    double stallStacksMs = 0.0;  ///< 0: off
};

/// A run of the rail at 1 kHz with every channel (loop terms too), seconds long: a shuttle of
/// +-400 mm with a lagging position, written as the workbench saves runs (CSV and sidecar).
bool writeRun(const QString& path, double seconds, QString* error) {
    RunRecord r;
    r.conditions.profile = MachineProfile::rail();
    r.conditions.test = QStringLiteral("run");
    r.conditions.periodS = 0.001;
    r.hasConditions = true;
    RunChannels& c = r.channels;
    const auto n = static_cast<std::size_t>(seconds / r.conditions.periodS);
    c.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * r.conditions.periodS;
        const double sp = 400.0 * std::sin(t * 0.5);
        const double pos = 400.0 * std::sin((t - 0.02) * 0.5);
        c.timeS.push_back(t);
        c.blockN.push_back(20 + 20 * static_cast<int>(std::fmod(t, 8.0) / 2.0));
        c.setpointMm.push_back(sp);
        c.positionMm.push_back(pos);
        c.errorMm.push_back(sp - pos);
        c.velocityMmS.push_back(200.0 * std::cos(t * 0.5));
        c.setpointVelocityMmS.push_back(200.0 * std::cos(t * 0.5));
        const double p = 3.0 * (sp - pos), i = 0.5 * std::sin(t), d = 0.1 * std::cos(t);
        c.pCodes.push_back(p);
        c.iCodes.push_back(i);
        c.dCodes.push_back(d);
        c.ffCodes.push_back(1.0);
        c.sumCodes.push_back(p + i + d + 1.0);
        c.commandCodes.push_back(p + i + d + 1.0);
        c.drive.push_back(std::round(128.0 + p + i + d + 1.0));
        c.saturated.push_back(0);
    }
    c.hasLoopTerms = true;
    c.hasSaturation = true;
    return saveRunRecord(r, path, nullptr, error);
}

/// The longest gap between two ticks of a 2 ms timer on the screens' thread, once counting.
class StallMeter : public QObject {
  public:
    StallMeter() {
        timer_.setInterval(2);
        connect(&timer_, &QTimer::timeout, this, [this] {
            const std::int64_t now = monotonicNs();
            if (last_ > 0 && counting.load()) worstNs_ = std::max(worstNs_, now - last_);
            last_ = now;
        });
        timer_.start();
    }
    double worstMs() const { return static_cast<double>(worstNs_) / 1e6; }
    std::atomic<bool> counting{false};  ///< from the first E-stop's wait on

  private:
    QTimer timer_;
    std::int64_t last_ = 0;
    std::int64_t worstNs_ = 0;
};

struct Samples {
    std::vector<double> keyToZeroMs, keyToFilterMs, filterToZeroMs;
};

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    // Nearest rank: the smallest value with at least q of the samples at or below it.
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

void print(const char* machine, const Samples& s, double stallMs) {
    auto line = [](const char* what, const std::vector<double>& v) {
        std::printf("  %-34s median %7.2f ms   p99 %7.2f ms   max %7.2f ms\n", what,
                    quantile(v, 0.5), quantile(v, 0.99),
                    v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()));
    };
    std::printf("%s: %zu E-stops\n", machine, s.keyToZeroMs.size());
    line("key event -> drive at zero", s.keyToZeroMs);
    line("  key event -> event filter", s.keyToFilterMs);
    line("  event filter -> drive at zero", s.filterToZeroMs);
    std::printf("  longest the screens' thread did not answer: %.1f ms\n", stallMs);
    std::fflush(stdout);
}

/// What differs between the rail and the DC table: the window, how the program is (re)started
/// while the bench runs, and where the stamp is read.
struct Machine {
    QMainWindow* window = nullptr;
    ui::WorkbenchWindow* workbench = nullptr;
    std::function<bool()> running;  ///< any thread: the program runs now
    /// Screens' thread: the next step towards a running program (reset, Automatic, start);
    /// true when it took one.
    std::function<bool()> keepRunning;
    std::function<EStopStamp()> stamp;  ///< any thread
    std::function<QString()> state;     ///< any thread: what the machine is doing (a stuck bench)
};

/// Machine::state's line, the same for both machines' statuses (ControllerStatus, XyStatus).
template <typename Status>
QString stateLine(const Status& s) {
    return QStringLiteral("state %1, automatic %2, homed %3, alarms %4")
        .arg(int(s.state))
        .arg(s.automatic)
        .arg(s.homed)
        .arg(s.activeAlarms);
}

/// Every dock floating and shown: each one paints (tabbed docks paint only the front one).
void openEveryDock(QMainWindow* w) {
    for (QDockWidget* d : w->findChildren<QDockWidget*>()) {
        d->setFloating(true);
        d->show();
    }
}

/// The workbench loads the run again and again: one load always under way, the next asked as
/// the last one's run is added (and the run before it cleared, so memory holds about two).
void keepLoading(ui::WorkbenchWindow* bench, const QString& path, std::atomic<bool>& stop) {
    QObject::connect(bench, &ui::WorkbenchWindow::runLoaded, bench, [bench, path, &stop] {
        if (stop.load()) return;
        if (bench->runs().size() > 1) bench->clearRuns();
        bench->loadRun(path);
    });
    bench->loadRun(path);
}

Samples measure(Machine& m, const Options& o, const QString& runPath, double* stallMs) {
    Samples out;
    StallMeter stalls;
    std::atomic<bool> stop{false};
    m.window->show();
    openEveryDock(m.window);
    m.workbench->show();
    keepLoading(m.workbench, runPath, stop);
    // Every 20 ms, and at most one step every 300 ms (a step takes a few periods to be seen).
    QTimer keeper;
    keeper.setInterval(20);
    std::int64_t lastStepNs = 0;
    QObject::connect(&keeper, &QTimer::timeout, m.window, [&] {
        if (stop.load()) return QApplication::quit();
        if (monotonicNs() - lastStepNs < 300'000'000) return;
        if (m.keepRunning()) lastStepNs = monotonicNs();
    });
    keeper.start();
    std::thread keys([&] {
        std::mt19937_64 rng(o.seed);
        std::uniform_real_distribution<double> pause(0.1, 2.0);  // s after the program started
        for (int k = 0; k < o.samples; ++k) {
            for (int waited = 0; !m.running(); ++waited) {
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                if (waited % 60000 == 59999)
                    std::fprintf(stderr,
                                 "trilho-bench-estop: the program has not run again for %d s "
                                 "(sample %d): %s\n",
                                 (waited + 1) / 1000, k + 1, qPrintable(m.state()));
            }
            std::this_thread::sleep_for(std::chrono::duration<double>(pause(rng)));
            if (!m.running()) {
                --k;  // it stopped on its own (an alarm): not a sample of a running program
                continue;
            }
            stalls.counting = true;
            const std::uint64_t before = m.stamp().count;
            const std::int64_t postNs = monotonicNs();
            QCoreApplication::postEvent(
                m.window, new QKeyEvent(QEvent::KeyPress, Qt::Key_F1, Qt::NoModifier));
            QCoreApplication::postEvent(
                m.window, new QKeyEvent(QEvent::KeyRelease, Qt::Key_F1, Qt::NoModifier));
            EStopStamp s = m.stamp();
            while (s.count == before) {
                std::this_thread::sleep_for(std::chrono::microseconds(200));
                s = m.stamp();
            }
            out.keyToZeroMs.push_back(static_cast<double>(s.driveZeroNs - postNs) / 1e6);
            out.keyToFilterMs.push_back(static_cast<double>(s.requestNs - postNs) / 1e6);
            out.filterToZeroMs.push_back(static_cast<double>(s.driveZeroNs - s.requestNs) / 1e6);
            while (m.running())  // the E-stop latched: wait until the screens saw it
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        stop = true;  // the keeper below quits the event loop
    });
    QApplication::exec();
    keys.join();
    keeper.stop();
    *stallMs = stalls.worstMs();
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    Options o;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        const QString& a = args[i];
        const bool more = i + 1 < args.size();
        if (a == QLatin1String("--machine") && more)
            o.machine = args[++i];
        else if (a == QLatin1String("--samples") && more)
            o.samples = std::max(1, args[++i].toInt());
        else if (a == QLatin1String("--run-seconds") && more)
            o.runSeconds = std::max(1.0, args[++i].toDouble());
        else if (a == QLatin1String("--run") && more)
            o.run = args[++i];
        else if (a == QLatin1String("--seed") && more)
            o.seed = args[++i].toULongLong();
        else if (a == QLatin1String("--stall-stacks") && more)
            o.stallStacksMs = std::max(1.0, args[++i].toDouble());
        else {
            std::fprintf(stderr,
                         "usage: trilho-bench-estop [--machine rail|dc_table|both] [--samples N] "
                         "[--run-seconds S] [--run FILE.csv] [--seed K] [--stall-stacks MS]\n");
            return 2;
        }
    }
    // The offscreen platform has no keyboard: the first key event makes one, here on the
    // screens' thread rather than in the thread that posts the keys.
    { const QKeyEvent first(QEvent::KeyPress, Qt::Key_F1, Qt::NoModifier); }
    if (o.stallStacksMs > 0.0) stacks::start(o.stallStacksMs);
    QTemporaryDir dir;
    QString runPath = o.run;
    if (runPath.isEmpty()) {
        runPath = dir.filePath(QStringLiteral("run.csv"));
        QString error;
        if (!writeRun(runPath, o.runSeconds, &error)) {
            std::fprintf(stderr, "trilho-bench-estop: %s\n", qPrintable(error));
            return 1;
        }
    }
    std::printf("run loading in the workbench: %s, %.1f MB\n", qPrintable(runPath),
                static_cast<double>(QFileInfo(runPath).size()) / 1e6);
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);

    if (o.machine == QLatin1String("rail") || o.machine == QLatin1String("both")) {
        ui::MachineLink link(MachineProfile::rail());
        QString error;
        // The history as the screens keep it: every line written, synced every 100 ms.
        if (!link.openJournal(dir.filePath(QStringLiteral("history.log")), &error)) {
            std::fprintf(stderr, "trilho-bench-estop: %s\n", qPrintable(error));
            return 1;
        }
        ui::MainWindow window(link, settings);
        window.setConfirmer([](const QString&, const QString&) { return true; });
        window.resize(1366, 768);
        if (!window.selectProgram(QStringLiteral(TRILHO_PROGRAMS_DIR "/ciclo_continuo.G")))
            return 1;
        window.openWorkbench();
        Machine m;
        m.window = &window;
        m.workbench = window.workbench();
        m.running = [&] {
            const ControllerState s = link.worker().snapshot().state;
            return s == ControllerState::Running || s == ControllerState::Waiting;
        };
        m.keepRunning = [&] {
            const ControllerStatus& s = link.status();
            if (s.state == ControllerState::EStop)
                link.resetEmergencyStop();
            else if (s.state == ControllerState::Alarm)
                link.acknowledge();
            else if (s.state == ControllerState::Manual)
                link.selectAutomatic();
            else if (s.state == ControllerState::AutoIdle && !s.homed)
                link.home();  // after an alarm that lost the reference
            else if (s.state == ControllerState::AutoIdle && !window.compiling())
                window.executeSelected(0);
            else if (s.state == ControllerState::Paused)
                link.resume();
            else
                return false;
            return true;
        };
        m.stamp = [&] { return link.lastEmergencyStop(); };
        m.state = [&] { return stateLine(link.worker().snapshot()); };
        double stall = 0.0;
        const Samples s = measure(m, o, runPath, &stall);
        print("rail", s, stall);
    }
    if (o.machine == QLatin1String("dc_table") || o.machine == QLatin1String("both")) {
        const ProfileLoad profile =
            loadMachineProfile(QStringLiteral(TRILHO_MACHINES_DIR "/xy_dc_table.json"));
        if (!profile.profile) {
            std::fprintf(stderr, "trilho-bench-estop: %s\n", qPrintable(profile.error));
            return 1;
        }
        XySessionMake made = makeXySession(*profile.profile, 1);
        XyLink link(std::make_unique<XySessionRunnable>(std::move(made.session)),
                    XyLink::Drive::Thread);
        ui::XyMainWindow window(link, settings);
        window.setConfirmer([](const QString&, const QString&) { return true; });
        QString error;
        if (!window.openJournal(dir.filePath(QStringLiteral("history-xy_dc_table.log")), &error)) {
            std::fprintf(stderr, "trilho-bench-estop: %s\n", qPrintable(error));
            return 1;
        }
        window.resize(1366, 768);
        // A shuttle between two corners that never ends (m03 jumps back to block 20).
        const QString program = dir.filePath(QStringLiteral("shuttle.G"));
        QFile f(program);
        if (!f.open(QIODevice::WriteOnly)) return 1;
        f.write("N10 G90\nN20 G01 X250 Y200 F80\nN30 G01 X50 Y50\nN40 M03 X20\nN50 M02\n");
        f.close();
        if (!window.selectProgram(program)) return 1;
        window.openWorkbench();
        Machine m;
        m.window = &window;
        m.workbench = window.workbench();
        m.running = [&] {
            const ControllerState s = link.status().state;
            return s == ControllerState::Running || s == ControllerState::Waiting;
        };
        m.keepRunning = [&] {
            const XyStatus s = link.status();
            if (s.state == ControllerState::EStop)
                link.post([](XyController& c) { c.resetEmergencyStop(); });
            else if (s.state == ControllerState::Alarm)
                link.post([](XyController& c) { c.acknowledgeAlarms(); });
            else if (s.state == ControllerState::AutoIdle && !s.homed)
                link.post([](XyController& c) { c.home(); });
            else if (s.state == ControllerState::Manual || s.state == ControllerState::AutoIdle)
                window.startProgram(false);
            else if (s.state == ControllerState::Paused)
                link.post([](XyController& c) { c.resume(); });
            else
                return false;
            return true;
        };
        m.stamp = [&] { return link.lastEmergencyStop(); };
        m.state = [&] { return stateLine(link.status()); };
        double stall = 0.0;
        const Samples s = measure(m, o, runPath, &stall);
        print("DC table", s, stall);
        std::printf("  the table's thread %s SCHED_FIFO\n",
                    link.realtime() ? "ran" : "did not run");
    }
    return 0;
}
