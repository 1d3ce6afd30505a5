// Opening a very long program at the screens (issue 19): time, peak memory, and the longest
// the screen thread stopped answering (E-stop is a key on that thread), against a bare Qt text
// editor opening the same file. One mode per process, so each peak is its own:
//   trilho-bench-program-open bare FILE     QPlainTextEdit::setPlainText, shown
//   trilho-bench-program-open trilho FILE   the rail's window: select, then compile it
// Prints one line: mode, seconds to usable, peak RSS MB, longest event-loop stall ms.
// scripts/bench-program-open runs both on a generated 1M-line program.
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QPlainTextEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <fstream>
#include <string>

#include "core/profile/machine_profile.h"
#include "ui/machine_link.h"
#include "ui/main_window.h"
#include "ui/program_panel.h"

namespace {

double peakRssMb() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmHWM:") {
            double kb = 0;
            status >> kb;
            return kb / 1024.0;
        }
        std::getline(status, key);
    }
    return 0.0;
}

// The longest gap between two 2 ms ticks of a timer on the screen thread: how long a key
// (E-stop among them) would have waited.
class StallMeter : public QObject {
  public:
    StallMeter() {
        clock_.start();
        timer_.setInterval(2);
        connect(&timer_, &QTimer::timeout, this, [this] {
            const qint64 now = clock_.nsecsElapsed();
            if (last_ >= 0) worstNs_ = std::max(worstNs_, now - last_);
            last_ = now;
        });
        timer_.start();
    }
    double worstMs() const { return static_cast<double>(worstNs_) / 1e6; }

  private:
    QTimer timer_;
    QElapsedTimer clock_;
    qint64 last_ = -1;
    qint64 worstNs_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 3 ||
        (args[1] != QLatin1String("bare") && args[1] != QLatin1String("trilho"))) {
        std::fprintf(stderr, "usage: trilho-bench-program-open bare|trilho FILE\n");
        return 2;
    }
    const QString mode = args[1];
    const QString path = args[2];
    StallMeter stalls;
    QElapsedTimer clock;
    double seconds = 0.0;
    if (mode == QLatin1String("bare")) {
        QPlainTextEdit editor;
        editor.resize(800, 600);
        editor.show();
        QTimer::singleShot(50, &app, [&] {
            clock.start();
            QFile f(path);
            if (!f.open(QIODevice::ReadOnly)) app.exit(1);
            editor.setPlainText(QString::fromUtf8(f.readAll()));
            QTimer::singleShot(0, &app, [&] {
                seconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
                app.quit();
            });
        });
        if (app.exec() != 0) return 1;
    } else {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
        trilho::ui::MachineLink link(trilho::MachineProfile::rail());
        trilho::ui::MainWindow window(link, settings);
        window.setConfirmer([](const QString&, const QString&) { return true; });
        window.resize(1280, 800);
        window.show();
        QTimer poll;
        QTimer::singleShot(200, &app, [&] {
            clock.start();
            if (!window.selectProgram(path)) app.exit(1);
            window.compileSelected();
            // Usable: loaded, shown and compiled (a large program loads and compiles on worker
            // threads; the compile asked while it loads runs when it is loaded).
            poll.setInterval(1);
            QObject::connect(&poll, &QTimer::timeout, &app, [&] {
                if (window.programPanel()->loading() || window.compiling()) return;
                seconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
                app.quit();
            });
            poll.start();
        });
        if (app.exec() != 0) return 1;
    }
    std::printf("%-7s %8.2f s %8.1f MB peak %8.1f ms longest stall\n", qPrintable(mode), seconds,
                peakRssMb(), stalls.worstMs());
    return 0;
}
