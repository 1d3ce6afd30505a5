// Issue 21 items 2 and 4, the time figures (benchmarks, not tests):
//  - the metrics of a 60 s trace at 1 kHz (must take under 5 ms);
//  - "what if": a typical 2 s step re-simulated with other gains (under 100 ms);
//  - the Prediction page's curve, redone on the GUI thread at every slider move: 10 s of the
//    model's loop at 1 ms (10 000 periods) and at the rail's shortest period, 0.5 ms (20 000),
//    against the 20 ms of a 50 Hz frame.
// What a --trace costs a run is trilho-bench-trace's (trace_cost_bench.cpp).
// Run with
//   build/release/bench/trilho-bench-tuning --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/tuning/model_step_prediction.h"
#include "core/tuning/step_metrics.h"
#include "host/tuning/step_experiment.h"

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

void BM_PredictionPage10s(benchmark::State& state) {
    // The rail's identified model (lesson 19: K 14.84 mm/s a code, tau 15.0 ms), its gains.
    DiscreteLoopSpec spec;
    spec.model.speedGainMmSPerCode = 14.84;
    spec.model.timeConstantS = 0.015;
    spec.gains = {1.2, 0.5, 0.02};
    spec.periodS = static_cast<double>(state.range(0)) * 1e-4;
    spec.derivativeFilterS = 0.004;  // the profile's velocity filter
    std::size_t periods = 0;
    for (auto _ : state) {
        const ModelStepPrediction p = predictStepOnModel(spec, 10.0, 10.0);
        periods = p.timeS.size();
        benchmark::DoNotOptimize(p.settlingTimeS);
    }
    state.counters["periods"] = static_cast<double>(periods);
}
BENCHMARK(BM_PredictionPage10s)->Arg(10)->Arg(5)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
