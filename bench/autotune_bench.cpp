// Wall time of a whole autotune on the simulated rail (and on a DC table axis) in virtual time
// (issue 21: under 1 s),
// and of its parts: the identification experiment, the fit, and the frequency view. Google
// Benchmark; run with
//   build/release/bench/trilho-bench-autotune --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
// The counter machine_s is the machine time the autotune took (identification plus the
// verification moves), which the issue bounds at 10 s.
#include <benchmark/benchmark.h>

#include "core/tuning/dc_axis_autotune.h"
#include "core/tuning/rail_autotune.h"
#include "host/session/sim_dc_table_rig.h"
#include "host/session/sim_rail_rig.h"

namespace {

using namespace trilho;

void BM_Autotune(benchmark::State& state) {
    const MachineProfile profile = MachineProfile::rail();
    const double mass = static_cast<double>(state.range(0)) / 10.0;
    double machine = 0.0;
    for (auto _ : state) {
        SimRailRig rig(profile, 1, -500.0, mass);
        const AutotuneResult r = autotuneRail(rig, profile);
        if (!r.ok) state.SkipWithError("autotune failed");
        machine = r.machineTimeS;
        benchmark::DoNotOptimize(r);
    }
    state.counters["machine_s"] = machine;
}
BENCHMARK(BM_Autotune)->Arg(5)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond);

/// One DC table axis (x), its mass factor x10 as the argument, from the middle of the table.
void BM_DcAxisAutotune(benchmark::State& state) {
    const MachineProfile profile = MachineProfile::xyDcTable();
    const double mass = static_cast<double>(state.range(0)) / 10.0;
    double machine = 0.0;
    for (auto _ : state) {
        SimDcTableRig rig(profile, 0, 1, 150.0, 150.0, mass);
        const DcAutotuneResult r = autotuneDcAxis(rig);
        if (!r.ok) state.SkipWithError("DC table autotune failed");
        machine = r.machineTimeS;
        benchmark::DoNotOptimize(r);
    }
    state.counters["machine_s"] = machine;
}
BENCHMARK(BM_DcAxisAutotune)->Arg(5)->Arg(10)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_IdentificationExperiment(benchmark::State& state) {
    const MachineProfile profile = MachineProfile::rail();
    for (auto _ : state) {
        SimRailRig rig(profile, 1, -500.0, 1.0);
        benchmark::DoNotOptimize(runIdentificationExperiment(rig));
    }
}
BENCHMARK(BM_IdentificationExperiment)->Unit(benchmark::kMillisecond);

void BM_Fit(benchmark::State& state) {
    const MachineProfile profile = MachineProfile::rail();
    SimRailRig rig(profile, 1, -500.0, 1.0);
    const IdentificationRecord rec = runIdentificationExperiment(rig);
    for (auto _ : state)
        benchmark::DoNotOptimize(identifyRail(rec, profile));
}
BENCHMARK(BM_Fit)->Unit(benchmark::kMillisecond);

void BM_FrequencyView(benchmark::State& state) {
    const RailModel model{14.84, 0.015, 3450.0, 200.0};
    const LoopGains gains{2.54, 0.127, 0.038};
    for (auto _ : state)
        benchmark::DoNotOptimize(railFrequencyView(model, gains, 0.001));
}
BENCHMARK(BM_FrequencyView)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
