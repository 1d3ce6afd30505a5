#pragma once
// What `trilho-cli run` shares between the rail and the XY machines: the options, the report
// (history lines, alarms) and the --trace file.
#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/cli_output.h"
#include "core/files/atomic_file.h"
#include "core/machine/controller_event.h"
#include "core/machine/event_text.h"
#include "core/profile/machine_profile.h"
#include "core/timeline/timeline.h"
#include "core/xy/xy_event_text.h"
#include "hal/sim/fault_schedule.h"
#include "host/session/run_end.h"

namespace trilho::cli {

/// How a run ended (host/session/run_end.h: the rules are shared with the pre-run check).
using Outcome = RunOutcome;

struct RunOptions {
    bool virtualTime = false;
    double massFactor = 1.0;
    double continueAfterS = -1.0;  ///< < 0: never press Continue
    double maxSeconds = -1.0;      ///< < 0: unbounded (real time) / 3600 s (virtual time)
    bool json = false;
    QString tracePath;
    /// --trace-format binary: records of the columns' numbers (binary_trace.h), not CSV rows.
    bool traceBinary = false;
    double tickJitterMs = 0.0;  ///< late ticks: each period lengthened by up to this
    double jitterRate = 0.01;   ///< with this probability
    std::uint64_t seed = 1;
    std::vector<ScheduledFault> faults;  ///< switched on after homing, at their @T
    QString port;         ///< a board on this serial port instead of the simulated machine
    int baud = 0;         ///< of port; 0: the board's own rate
    QString programFile;  ///< the program's file as given (the trace's sidecar names it)
    /// The machine as loaded with --law applied and before --mass-factor (recorded on its own):
    /// the trace's sidecar records it.
    MachineProfile recordedProfile;
};

/// What the run said. Text: each history line is printed as it happens (memory bounded by
/// nothing the run does); JSON: the last kKeptLines lines are kept, the earlier ones counted.
struct Report {
    static constexpr qsizetype kKeptLines = 10000;
    bool streamText = false;
    QStringList history;
    qint64 omitted = 0;
    QJsonArray alarms;
    bool offTarget = false;  ///< warning 13: the program ended away from its last target
    bool xy = false;         ///< an XY machine: its moves name x and y (xyHistoryLine)
    /// The program's cycle time (run_end.h), fed by the runs that see every period (virtual
    /// time, and the XY machines in real time); the rail's real-time run polls the servo
    /// thread's snapshot every 5 ms and does not feed it, so it reports none.
    CycleClock cycle;
    /// The run's marks (alarms, holds, mode changes, its start and end), with the program line
    /// each belongs to: written beside the trace as NAME.events.csv (events_file.h).
    TimelineRecorder timeline;
    /// An event, drained while the block at blockIndex (-1: none), source line blockLine, ran.
    void add(const ControllerEvent& e, std::int32_t blockIndex = -1, std::uint32_t blockLine = 0) {
        const QString line = xy ? xyHistoryLine(e) : historyLine(e);
        timeline.add(e, line, blockIndex, blockLine);
        if (streamText) {
            out(line + QLatin1Char('\n'));
        } else {
            if (history.size() == kKeptLines) history.removeFirst(), ++omitted;
            history << line;
        }
        if (e.kind == EventKind::AlarmRaised && e.alarm == AlarmCode::FinalPositionOff)
            offTarget = true;
        if (e.kind == EventKind::AlarmRaised && alarms.size() < kKeptLines) {
            QJsonObject a;
            a[QStringLiteral("code")] = static_cast<int>(e.alarm);
            a[QStringLiteral("text")] =
                xy ? xyAlarmText(e.alarm, e.value) : alarmText(e.alarm, e.value);
            a[QStringLiteral("severity")] = alarmSeverity(e.alarm) == AlarmSeverity::Warning
                                                ? QStringLiteral("warning")
                                                : QStringLiteral("alarm");
            alarms.append(a);
        }
    }
};

/// The --trace file: a regular file (or a new one) is written atomically (AtomicFile: a crash or
/// a full disk never leaves half a trace where a good one was, and says so); a device or a FIFO
/// (/dev/null, a pipe to a plotter) is written straight, never replaced. Rows are gathered in a
/// buffer of kBufferBytes and written a block at a time: a write per row made a virtual-time run
/// 11x slower to a file and 28x to a pipe (issue 21 item 3). Any failed write is kept with its
/// reason and reported after the run's own result. One thread at a time: in a virtual-time
/// run the TraceQueue's writer thread (trace_queue.h) until its finish().
class TraceFile {
  public:
    /// header: the CSV's first line, with its newline.
    bool open(const QString& path, const char* header, QString* error) {
        if (path.isEmpty()) return true;
        path_ = path;
        const QFileInfo info(path);
        if (info.exists() && !info.isFile() && !info.isDir()) {
            // Opened without blocking: a FIFO nobody reads is an error now, not a hang.
            const int fd = ::open(QFile::encodeName(path).constData(), O_WRONLY | O_NONBLOCK);
            if (fd < 0) {
                const int e = errno;
                *error = QStringLiteral("cannot write trace '%1': %2")
                             .arg(path, e == ENXIO ? QStringLiteral("no program reads this FIFO")
                                                   : QString::fromLocal8Bit(std::strerror(e)));
                return false;
            }
            ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
            auto f = std::make_unique<QFile>();
            if (!f->open(fd, QIODevice::WriteOnly | QIODevice::Unbuffered,
                         QFileDevice::AutoCloseHandle)) {
                ::close(fd);
                *error = QStringLiteral("cannot write trace '%1': %2").arg(path, f->errorString());
                return false;
            }
            plain_ = std::move(f);
        } else {
            auto f = std::make_unique<AtomicFile>(path);
            if (!f->open()) {
                *error = QStringLiteral("cannot write trace: %1").arg(f->error());
                return false;
            }
            atomic_ = std::move(f);
        }
        buffer_.reserve(kBufferBytes + 1024);
        buffer_.append(header);
        return true;
    }
    /// One row, already formatted with its newline.
    void line(const char* text, qint64 len) {
        if (!active() || !error_.isEmpty() || len <= 0) return;
        ++rows_;
        buffer_.append(text, static_cast<std::size_t>(len));
        if (buffer_.size() >= kBufferBytes) flushBuffer();
    }
    /// The rows given to line() (the header given to open() is none).
    long long rows() const { return rows_; }
    const QString& path() const { return path_; }
    /// Writes what is buffered now (a real-time run, so a live reader keeps up).
    void flush() {
        if (active() && error_.isEmpty()) flushBuffer();
    }
    /// Finishes the file; false (with error()) when any write, the flush or the commit failed.
    bool close() {
        if (!active()) return true;
        if (error_.isEmpty()) flushBuffer();
        if (atomic_) {
            if (!error_.isEmpty())
                atomic_->cancel();  // the old file stays as it was
            else if (!atomic_->commit())
                error_ = atomic_->error();
        } else {
            if (error_.isEmpty() && !plain_->flush()) error_ = plain_->errorString();
            plain_->close();
        }
        atomic_.reset();
        plain_.reset();
        return error_.isEmpty();
    }
    /// Abandons the file without writing it: a file that was there stays as it was (a test
    /// refused before it ran must not leave an empty trace where a good one was).
    void cancel() {
        if (atomic_) atomic_->cancel();  // discards
        if (plain_) plain_->close();
        atomic_.reset();
        plain_.reset();
        buffer_.clear();
    }
    bool active() const { return atomic_ || plain_; }
    /// "cannot write trace 'PATH': REASON" (AtomicFile's own message already names the path).
    QString error() const {
        return error_.startsWith(QStringLiteral("cannot write '"))
                   ? QStringLiteral("cannot write trace: %1").arg(error_)
                   : QStringLiteral("cannot write trace '%1': %2").arg(path_, error_);
    }

    static constexpr std::size_t kBufferBytes = 64 * 1024;

  private:
    void flushBuffer() {
        if (!buffer_.empty()) write(buffer_.data(), static_cast<qint64>(buffer_.size()));
        written_ += static_cast<long long>(buffer_.size());
        buffer_.clear();
        startWriteBack();
    }
    /// A regular file is committed with fdatasync (AtomicFile: the trace is on disk before it
    /// replaces the old one). Left to the end, that waited for the whole trace to reach the disk
    /// (4 ms of a 13 ms run for 5 MB); the disk is asked to start on each MB as it is written
    /// (sync_file_range, which does not wait), so the commit waits only for the last of it.
    void startWriteBack() {
#if defined(__linux__)
        constexpr long long kWriteBackBytes = 1 << 20;
        if (!atomic_ || written_ - writtenBack_ < kWriteBackBytes) return;
        const int fd = atomic_->handle();
        if (fd >= 0)
            ::sync_file_range(fd, writtenBack_, written_ - writtenBack_, SYNC_FILE_RANGE_WRITE);
        writtenBack_ = written_;
#endif
    }
    void write(const char* data, qint64 len) {
        // A pipe whose reader left is EPIPE here, said after the run, never a SIGPIPE that
        // kills the whole command unreported (exit 141): blocked around the write, and the
        // signal the write raised taken back before it is unblocked, on whichever thread
        // writes (trace_queue.h's writer, or `tune step`'s own).
        sigset_t pipe, before;
        sigemptyset(&pipe);
        sigaddset(&pipe, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &pipe, &before);
        errno = 0;
        const bool whole =
            atomic_ ? atomic_->write(QByteArrayView(data, len)) : plain_->write(data, len) == len;
        const int e = errno;
        if (e == EPIPE && !sigismember(&before, SIGPIPE)) {
            const timespec now{};
            sigtimedwait(&pipe, nullptr, &now);
        }
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        if (whole || !error_.isEmpty()) return;
        if (atomic_) {
            error_ = atomic_->error();
            return;
        }
        // The system's reason where there is one (QFile on a descriptor says "Unknown error").
        if (e == EPIPE)
            error_ = QStringLiteral("the program reading it closed the pipe");
        else if (e != 0)
            error_ = QString::fromLocal8Bit(std::strerror(e));
        else
            error_ = plain_->errorString().isEmpty() ? QStringLiteral("write failed")
                                                     : plain_->errorString();
    }
    std::unique_ptr<AtomicFile> atomic_;  ///< a regular file, replaced whole at close()
    std::unique_ptr<QFile> plain_;        ///< a FIFO or a device, written straight
    std::string buffer_;
    QString path_, error_;
    long long rows_ = 0;
    long long written_ = 0, writtenBack_ = 0;  ///< bytes written, and given to sync_file_range
};

/// The JSON fields every run reports, rail or XY: ok, history (and how many lines were left
/// out), alarms.
inline QJsonObject runJson(Outcome outcome, const Report& report) {
    QJsonObject o;
    o[QStringLiteral("ok")] = outcome == Outcome::Finished && !report.offTarget;
    o[QStringLiteral("history")] = QJsonArray::fromStringList(report.history);
    if (report.omitted) o[QStringLiteral("history_omitted")] = double(report.omitted);
    o[QStringLiteral("alarms")] = report.alarms;
    if (report.cycle.started())
        o[QStringLiteral("cycle_time_s")] = std::round(report.cycle.cycleS() * 1e4) / 1e4;
    return o;
}

/// The exit status of a run (README): a trace (or its sidecar) that could not be written is said
/// after the run's own report and makes a finished run a usage error; a program that ended away
/// from where it sent the machine is no success (warning 13).
inline int runExitStatus(Outcome outcome, const Report& report, const QString& traceFailure) {
    if (!traceFailure.isEmpty()) {
        err(QStringLiteral("trilho-cli run: %1\n").arg(traceFailure));
        if (outcome == Outcome::Finished) return kUsage;
    }
    if (outcome == Outcome::Finished && report.offTarget) return kAlarm;
    switch (outcome) {
        case Outcome::Finished:
            return kOk;
        case Outcome::Alarm:
            return kAlarm;
        case Outcome::TimeLimit:
            return kTimeLimit;
    }
    return kOk;
}

}  // namespace trilho::cli
