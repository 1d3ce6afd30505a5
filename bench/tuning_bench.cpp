// Issue 21 items 2, 3 and 4, the time figures (benchmarks, not tests):
//  - the metrics of a 60 s trace at 1 kHz (must take under 5 ms);
//  - "what if": a typical 2 s step re-simulated with other gains (under 100 ms);
//  - what a --trace costs a virtual-time run: none, to a file and to a pipe (at most 1.5x),
//    and the former writer (snprintf and a write per row) for comparison.
// Run with
//   build/release/bench/trilho-bench-tuning --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QFile>
#include <QSaveFile>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>
#include <thread>

#include "app/cli/run_support.h"
#include "core/gcode/compiler.h"
#include "core/tuning/step_metrics.h"
#include "core/tuning/trace_writer.h"
#include "host/session/sim_session.h"
#include "host/tuning/step_test.h"

namespace {

using namespace trilho;

void BM_Metrics60sAt1kHz(benchmark::State& state) {
    // A second-order response with a quantized encoder and a saturated stretch: every branch.
    const std::size_t n = 60000;
    std::vector<double> t(n), sp(n), x(n);
    std::vector<std::uint8_t> sat(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double tk = static_cast<double>(k) * 0.001;
        t[k] = tk;
        sp[k] = tk < 0.01 ? 0.0 : 100.0;
        const double s = std::max(0.0, tk - 0.01);
        const double y = 100.0 * (1 - std::exp(-5 * s) * std::cos(12 * s));
        x[k] = std::round(y * 22.8) / 22.8;
        sat[k] = s > 0 && s < 0.1 ? 1 : 0;
    }
    StepSignals in;
    in.timeS = t, in.setpointMm = sp, in.positionMm = x, in.saturated = sat;
    for (auto _ : state)
        benchmark::DoNotOptimize(measureStep(in));
}
BENCHMARK(BM_Metrics60sAt1kHz)->Unit(benchmark::kMillisecond);

void BM_WhatIf2sStep(benchmark::State& state) {
    // A recorded 10 mm step of 2 s on the rail (1 kHz), re-run with half its Kp.
    StepTestSpec spec;
    spec.amplitudeMm = 10.0;
    spec.settleS = 10.0;
    spec.maxDurationS = 2.0;
    const StepTestResult recorded = runStepTest(spec);
    TuningGains g = recorded.record.conditions.gains;
    g.kp *= 0.5;
    for (auto _ : state) {
        const StepTestResult r = whatIf(recorded.record.conditions, g);
        benchmark::DoNotOptimize(r.metrics.riseTimeS);
    }
    state.counters["ticks"] = static_cast<double>(recorded.record.channels.size());
}
BENCHMARK(BM_WhatIf2sStep)->Unit(benchmark::kMillisecond);

// ---- trace cost in a virtual-time run --------------------------------------------------------

enum class Writer { None, ToChars, Legacy };

/// The former row: snprintf, then one write per row (unbuffered on a pipe).
void legacyRow(QFileDevice& f, const ControllerStatus& s) {
    char line[192];
    const int len = std::snprintf(line, sizeof line, "%.4f,%d,%.4f,%.4f,%.4f,%.3f,%d\n", s.timeS,
                                  s.blockN, s.servo.setpointMm, s.servo.positionMm, s.servo.errorMm,
                                  s.servo.velocityMmS, s.servo.loop.code);
    f.write(line, len);
}

/// The row `trilho-cli run --trace` writes now (run_command.cpp's railTraceRow).
void toCharsRow(cli::TraceFile& trace, const ControllerStatus& s) {
    CsvRow row;
    row.num(s.timeS, 4)
        .integer(s.blockN)
        .num(s.servo.setpointMm, 4)
        .num(s.servo.positionMm, 4)
        .num(s.servo.errorMm, 4)
        .num(s.servo.velocityMmS, 3)
        .integer(s.servo.loop.code)
        .end();
    trace.line(row.data(), static_cast<qint64>(row.size()));
}

/// A FIFO with a reader that throws the bytes away, as `| cat > /dev/null` would.
struct PipeSink {
    QTemporaryDir dir;
    QString path = dir.filePath(QStringLiteral("trace.fifo"));
    int fd = -1;
    std::thread reader;
    PipeSink() {
        ::mkfifo(QFile::encodeName(path).constData(), 0600);
        fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK);
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    }
    void start() {
        reader = std::thread([this] {
            char buf[65536];
            // EAGAIN cannot happen (blocking); 0 is the writer's close.
            while (::read(fd, buf, sizeof buf) > 0) {
            }
        });
    }
    ~PipeSink() {
        if (reader.joinable()) reader.join();
        ::close(fd);
    }
};

double runOnce(Writer writer, bool pipe, const std::shared_ptr<const Program>& program) {
    SimSession session(MachineProfile::rail(), 1);
    RailController& c = session.controller();
    c.selectAutomatic();
    c.loadProgram(program);
    c.start(0);
    QTemporaryDir dir;
    std::unique_ptr<PipeSink> sink;
    QString path = dir.filePath(QStringLiteral("trace.csv"));
    if (pipe) {
        sink = std::make_unique<PipeSink>();
        path = sink->path;
    }
    cli::TraceFile trace;
    std::unique_ptr<QFileDevice> legacy;
    QString error;
    if (writer == Writer::ToChars) {
        trace.open(path, "t_s,block_n,setpoint_mm,position_mm,error_mm,velocity_mm_s,drive\n",
                   &error);
    } else if (writer == Writer::Legacy) {
        if (pipe) {
            const int fd = ::open(QFile::encodeName(path).constData(), O_WRONLY);
            auto f = std::make_unique<QFile>();
            f->open(fd, QIODevice::WriteOnly | QIODevice::Unbuffered, QFileDevice::AutoCloseHandle);
            legacy = std::move(f);
        } else {
            auto f = std::make_unique<QSaveFile>(path);
            f->open(QIODevice::WriteOnly);
            legacy = std::move(f);
        }
    }
    // Read once the writer is there: a FIFO without a writer reads as its end.
    if (sink) sink->start();
    while (true) {
        session.step();
        c.drainEvents([](const ControllerEvent&) {});
        const ControllerStatus& s = c.status();
        if (writer == Writer::ToChars) toCharsRow(trace, s);
        if (writer == Writer::Legacy) legacyRow(*legacy, s);
        if ((s.programFinished && s.state == ControllerState::AutoIdle) ||
            s.state == ControllerState::Alarm || session.elapsedS() > 600.0)
            break;
    }
    trace.close();
    if (auto* save = dynamic_cast<QSaveFile*>(legacy.get())) save->commit();
    legacy.reset();
    return session.elapsedS();
}

void BM_RunTrace(benchmark::State& state) {
    const auto writer = static_cast<Writer>(state.range(0));
    const bool pipe = state.range(1) != 0;
    // About 40 s of motion after homing (40,000 rows at 1 kHz): fixed costs (opening, the
    // commit) are small beside the rows.
    auto program = std::make_shared<Program>(
        compile("N10 G1 X600 F20\nN20 G1 X-600 F20\nN30 G1 X600 F20\nN40 G1 X-600 F20\n"
                "N50 G0 X0\nN60 M2\n",
                CompileOptions{}));
    if (!program->ok()) state.SkipWithError("the program does not compile");
    double virtualS = 0.0;
    for (auto _ : state)
        virtualS = runOnce(writer, pipe, program);
    state.counters["virtual_s"] = virtualS;
}
BENCHMARK(BM_RunTrace)
    ->ArgNames({"writer", "pipe"})
    ->Args({0, 0})  // no trace
    ->Args({1, 0})  // to_chars, buffered, to a file
    ->Args({1, 1})  // to_chars, buffered, to a pipe
    ->Args({2, 0})  // the former writer to a file
    ->Args({2, 1})  // the former writer to a pipe
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
