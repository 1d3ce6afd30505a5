// Line generators benchmark (issue 11): Bresenham's integer generator (seed 001 annex C,
// core/motion/bresenham_line.h) against the floating-point one (annex G, float_line.h) over
// the seed's objects (resources/programs/plotter_*.G, compiled for the plotter) and over a
// long seeded random polyline. Each case runs several times; the medians are printed as step
// events per second, with the seed's figure of merit: (float time - Bresenham time) / float
// time, which table 8 measured on the AVR (3.4 % to 13.5 %, 6.45 % on average).
//
// The consumer of the events is the step counter (x += dx, y += dy per event), what the
// plotter does with them besides the pulse; "next" runs the event-at-a-time interface that
// PlotterMotion uses, "forEach" the loop in one call.
//
//   trilho-bench-lines [--runs R] [--min-events N]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/motion/bresenham_line.h"
#include "core/motion/float_line.h"
#include "core/profile/machine_profile.h"

namespace {

using trilho::BresenhamLine;
using trilho::FloatLine;
using trilho::StepEvent;
using trilho::StepPoint;

struct Segment {
    StepPoint from, to;
};

struct Case {
    std::string name;
    std::vector<Segment> segments;  ///< one pass
    long long eventsPerPass = 0;
    int passes = 1;  ///< passes per timed run, so a run has at least --min-events events
};

/// The moves of a plotter program in steps, from the origin (G00 and G01 alike: the seed's
/// Arduino ran Bresenham for MOVE and LINE).
std::vector<Segment> programSegments(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const trilho::MachineProfile profile = trilho::MachineProfile::xyPlotter();
    trilho::CompileOptions opt;
    opt.machine = profile.limits;
    const trilho::Program prog = trilho::compile(ss.str(), opt);
    std::vector<Segment> segs;
    if (!prog.ok()) {
        std::fprintf(stderr, "%s: does not compile\n", path.c_str());
        std::exit(2);
    }
    StepPoint at{0, 0};
    for (std::size_t i = 0; i < prog.blocks.size(); ++i) {
        const auto& b = prog.blocks[i];
        if (b.op != trilho::Op::Rapid && b.op != trilho::Op::Linear) continue;
        const StepPoint to{
            static_cast<std::int32_t>(std::lround(b.x / profile.plotter.mmPerStepX)),
            static_cast<std::int32_t>(std::lround(prog.y[i] / profile.plotter.mmPerStepY))};
        segs.push_back({at, to});
        at = to;
    }
    return segs;
}

long long eventsOf(const std::vector<Segment>& segs) {
    long long n = 0;
    for (const auto& s : segs)
        n += std::max(std::llabs(std::int64_t{s.to.x} - s.from.x),
                      std::llabs(std::int64_t{s.to.y} - s.from.y));
    return n;
}

struct Counter {
    std::int64_t x = 0, y = 0;
    void operator()(StepEvent e) {
        x += e.dx;
        y += e.dy;
    }
};

/// Keeps a result alive without letting the compiler see through it.
volatile std::int64_t gSink = 0;

enum class Algo { BresenhamForEach, BresenhamNext, FloatForEach, FloatNext };

/// CPU time of this thread, s: the figures stay those of the code on a machine shared with
/// builds (wall time there counts the time the thread waited for a core).
double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double runOnce(const Case& c, Algo algo) {
    Counter cnt;
    const double t0 = cpuSeconds();
    for (int p = 0; p < c.passes; ++p) {
        for (const Segment& s : c.segments) {
            switch (algo) {
                case Algo::BresenhamForEach: {
                    BresenhamLine l(s.from, s.to);
                    l.forEach(cnt);
                    break;
                }
                case Algo::BresenhamNext: {
                    BresenhamLine l(s.from, s.to);
                    while (!l.done())
                        cnt(l.next());
                    break;
                }
                case Algo::FloatForEach: {
                    FloatLine l(s.from, s.to);
                    l.forEach(cnt);
                    break;
                }
                case Algo::FloatNext: {
                    FloatLine l(s.from, s.to);
                    while (!l.done())
                        cnt(l.next());
                    break;
                }
            }
        }
    }
    const double t1 = cpuSeconds();
    gSink = gSink + cnt.x + cnt.y;
    return t1 - t0;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 9;
    long long minEvents = 50'000'000;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--runs")) runs = std::max(1, std::atoi(argv[i + 1]));
        if (!std::strcmp(argv[i], "--min-events"))
            minEvents = std::max(1LL, std::atoll(argv[i + 1]));
    }

    std::vector<Case> cases;
    const char* objects[][2] = {{"square (fig. 44)", "plotter_quadrado.G"},
                                {"triangle", "plotter_triangulo.G"},
                                {"spiral, 25 points", "plotter_espiral.G"},
                                {"text, 74 points", "plotter_texto.G"},
                                {"circle, 50 points", "plotter_circulo.G"}};
    for (const auto& o : objects)
        cases.push_back(
            {o[0], programSegments(std::string(TRILHO_RESOURCES_DIR "/programs/") + o[1])});
    {
        // A long seeded random polyline in the 16-bit field's lower corner: 20,000 segments
        // from 0 to 4000 steps long, every direction.
        Case r{"random polyline, 20000 segments", {}};
        std::mt19937_64 rng(2014);
        std::uniform_int_distribution<int> c(0, 4000);
        StepPoint at{c(rng), c(rng)};
        for (int k = 0; k < 20000; ++k) {
            const StepPoint to{c(rng), c(rng)};
            r.segments.push_back({at, to});
            at = to;
        }
        cases.push_back(std::move(r));
    }
    {
        // The least periodic slope for the branch predictor: consecutive Fibonacci numbers
        // (their ratio tends to the golden ratio), back and forth.
        Case g{"golden slope 2584/4181, 100 lines", {}};
        for (int k = 0; k < 100; ++k)
            g.segments.push_back(k % 2 ? Segment{{4181, 2584}, {0, 0}}
                                       : Segment{{0, 0}, {4181, 2584}});
        cases.push_back(std::move(g));
    }
    for (Case& c : cases) {
        c.eventsPerPass = eventsOf(c.segments);
        c.passes =
            static_cast<int>(std::max(1LL, (minEvents + c.eventsPerPass - 1) / c.eventsPerPass));
    }

    std::printf(
        "line generators: step events per second (M/s of thread CPU time), median of %d "
        "runs, at least %lld events a run\n",
        runs, minEvents);
    std::printf("%-32s %10s %12s %12s %12s %12s %9s\n", "case", "events", "Bres M/s", "Bres next",
                "float M/s", "float next", "merit %");
    for (const Case& c : cases) {
        std::vector<double> tb, tbn, tf, tfn;
        for (int r = 0; r < runs; ++r) {
            tb.push_back(runOnce(c, Algo::BresenhamForEach));
            tbn.push_back(runOnce(c, Algo::BresenhamNext));
            tf.push_back(runOnce(c, Algo::FloatForEach));
            tfn.push_back(runOnce(c, Algo::FloatNext));
        }
        const double ev = static_cast<double>(c.eventsPerPass) * c.passes;
        const double b = median(tb), bn = median(tbn), f = median(tf), fn = median(tfn);
        std::printf("%-32s %10lld %12.0f %12.0f %12.0f %12.0f %9.2f\n", c.name.c_str(),
                    c.eventsPerPass, ev / b / 1e6, ev / bn / 1e6, ev / f / 1e6, ev / fn / 1e6,
                    100.0 * (f - b) / f);
    }
    std::printf(
        "merit %% = (float time - Bresenham time) / float time, forEach; seed 001 table 8 "
        "on the AVR: 3.44 to 13.53, mean 6.45\n");
    return gSink == 42 ? 1 : 0;
}
