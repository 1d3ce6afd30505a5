// Cost of one servo tick on the simulated rail (profile sample + loop law + plant step), and
// how many times faster than real time a 1 kHz simulation runs. Google Benchmark; run with
//   build/release/bench/trilho-bench-servo --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "core/control/position_loop.h"
#include "core/control/rail_servo.h"
#include "core/motion/trapezoid.h"
#include "hal/sim/sim_rail.h"

namespace {

using namespace trilho;

// The whole tick the worker runs: servo (inputs, profile, loop, limits) + plant step of 1 ms.
void BM_ServoTickWithPlant(benchmark::State& state) {
    const MachineProfile profile = MachineProfile::rail();
    SimRail rail(profile.plant);
    RailServo servo(profile, rail);
    double target = 1000;
    long ticks = 0;
    servo.moveTo(target, 1.0);
    for (auto _ : state) {
        servo.tick(0.001);
        rail.step(0.001);
        if (servo.sample().inPosition) servo.moveTo(target = -target, 1.0);
        ++ticks;
    }
    benchmark::DoNotOptimize(servo.sample());
    state.counters["x_real_time"] =
        benchmark::Counter(static_cast<double>(ticks) * 0.001, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ServoTickWithPlant);

// The parts alone.
void BM_ProfileSample(benchmark::State& state) {
    Trapezoid t = Trapezoid::restToRest(0, 1000, 1700, 2500);
    double time = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(t.at(time));
        time = time > 1.3 ? 0 : time + 0.001;
    }
}
BENCHMARK(BM_ProfileSample);

void BM_EngineeredLoop(benchmark::State& state) {
    PositionLoop loop(LoopParams{}, PlantParams{});
    LoopInput in;
    in.setpointMm = 10;
    double x = 0;
    for (auto _ : state) {
        in.measuredMm = x;
        benchmark::DoNotOptimize(loop.update(in));
        x = x > 10 ? 0 : x + 0.01;
    }
}
BENCHMARK(BM_EngineeredLoop);

void BM_PlantStep1ms(benchmark::State& state) {
    SimRail rail;
    rail.writeDrive(200);
    for (auto _ : state) {
        rail.step(0.001);
        if (rail.state().positionMm > 1000) rail.placeAt(-1000);
    }
    benchmark::DoNotOptimize(rail.state());
}
BENCHMARK(BM_PlantStep1ms);

}  // namespace

BENCHMARK_MAIN();
