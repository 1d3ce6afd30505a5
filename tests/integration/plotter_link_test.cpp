// The plotter's host against the emulated firmware over a virtual 57600 bit/s line (issue 12):
// the drawing the simulated plotter records is the same on a clean line, with every tenth byte
// corrupted, and with bytes dropped; RESENDs and timeouts are counted; a 1,000-point drawing
// goes as four objects and plots completely.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/protocol/plotter_host.h"
#include "hal/emulator/plotter_firmware.h"
#include "tests/support/virtual_serial_line.h"

using namespace trilho;

namespace {

struct LinkRun {
    std::vector<StepPoint> drawn;  ///< every stroke's points, in order
    std::size_t strokes = 0;
    PlotterHostStats host;
    PlotterFirmwareStats device;
    bool ok = false;
    std::string error;
    double seconds = 0.0;
};

std::vector<PlotPoint> polygon(int points, double radiusSteps, int cx, int cy) {
    std::vector<PlotPoint> d;
    for (int i = 0; i <= points; ++i) {
        const double a = 2.0 * M_PI * i / points;
        d.push_back({i > 0, static_cast<std::uint16_t>(std::lround(cx + radiusSteps * std::cos(a))),
                     static_cast<std::uint16_t>(std::lround(cy + radiusSteps * std::sin(a)))});
    }
    return d;
}

LinkRun run(const std::vector<PlotPoint>& drawing, const LineFaultSettings& faults,
            double maxS = 3600.0) {
    const MachineProfile profile = MachineProfile::xyPlotter();
    PlotterFirmware device(profile, 3);
    PlotterHostConfig config;
    config.stepsPerS = 1000.0;
    PlotterHost host(config);
    test::VirtualWire down(57600), up(57600);
    LineFaults noise(faults);
    host.request();
    host.speed(1000);
    host.origin();
    host.plot(drawing);
    const double dt = PlotterFirmware::kTickS;
    double t = 0.0;
    for (; t < maxS && !host.idle() && !host.failed(); t += dt) {
        host.poll(t);
        down.send(host.takeOutput(), t);
        down.deliver(t, [&](std::uint8_t b, double at) {
            if (auto passed = noise.pass(b)) device.receive(*passed, at + noise.delayS());
        });
        device.step(dt, t);
        up.send(device.takeOutput(), t);
        up.deliver(t, [&](std::uint8_t b, double at) { host.receive(b, at); });
    }
    LinkRun r;
    for (const DrawnStroke& s : device.plotter().strokes())
        r.drawn.insert(r.drawn.end(), s.points.begin(), s.points.end());
    r.strokes = device.plotter().strokes().size();
    r.host = host.stats();
    r.device = device.stats();
    r.ok = host.idle();
    r.error = host.error();
    r.seconds = t;
    return r;
}

bool same(const std::vector<StepPoint>& a, const std::vector<StepPoint>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
}

}  // namespace

TEST(PlotterLink, CleanLineDrawsTheObject) {
    const auto drawing = polygon(50, 300, 1000, 800);  // the seed's 50-point circle, its size
    const LinkRun clean = run(drawing, {});
    ASSERT_TRUE(clean.ok) << clean.error;
    EXPECT_EQ(clean.device.objectsPlotted, 1u);
    EXPECT_EQ(clean.device.pointsStored, drawing.size());
    EXPECT_EQ(clean.host.resends, 0u);
    EXPECT_EQ(clean.host.timeouts, 0u);
    EXPECT_GT(clean.drawn.size(), 1000u);
    std::printf("clean: %zu points drawn in %zu strokes, %.2f s, %llu packets\n",
                clean.drawn.size(), clean.strokes, clean.seconds,
                static_cast<unsigned long long>(clean.host.packetsSent));
}

TEST(PlotterLink, EveryTenthByteCorruptedDrawsTheSame) {
    const auto drawing = polygon(50, 300, 1000, 800);
    const LinkRun clean = run(drawing, {});
    LineFaultSettings f;
    f.corruptEvery = 10;
    const LinkRun noisy = run(drawing, f);
    ASSERT_TRUE(noisy.ok) << noisy.error;
    EXPECT_TRUE(same(clean.drawn, noisy.drawn));
    EXPECT_EQ(clean.strokes, noisy.strokes);
    EXPECT_GT(noisy.host.resends, 0u);
    EXPECT_EQ(noisy.host.resends, noisy.device.resendsSent);
    std::printf("every tenth byte corrupted: %llu RESENDs, %llu packets sent (clean %llu)\n",
                static_cast<unsigned long long>(noisy.host.resends),
                static_cast<unsigned long long>(noisy.host.packetsSent),
                static_cast<unsigned long long>(clean.host.packetsSent));
}

TEST(PlotterLink, DroppedBytesCostTimeoutsNotTheDrawing) {
    const auto drawing = polygon(50, 300, 1000, 800);
    const LinkRun clean = run(drawing, {});
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        LineFaultSettings f;
        f.dropP = 0.01;
        f.seed = seed;
        const LinkRun lossy = run(drawing, f);
        ASSERT_TRUE(lossy.ok) << lossy.error;
        EXPECT_TRUE(same(clean.drawn, lossy.drawn)) << "seed " << seed;
        EXPECT_GT(lossy.device.staleBytes + lossy.device.resendsSent + lossy.host.timeouts, 0u);
        std::printf(
            "1 %% of bytes dropped (seed %llu): %llu RESENDs, %llu timeouts, %.1f s "
            "(clean %.1f s)\n",
            static_cast<unsigned long long>(seed),
            static_cast<unsigned long long>(lossy.host.resends),
            static_cast<unsigned long long>(lossy.host.timeouts), lossy.seconds, clean.seconds);
    }
}

TEST(PlotterLink, AThousandPointDrawingGoesAsFourObjects) {
    std::vector<PlotPoint> drawing;
    for (int i = 0; i < 1000; ++i)  // a zigzag over the sheet
        drawing.push_back({i > 0, static_cast<std::uint16_t>(100 + (i % 2) * 40 + i),
                           static_cast<std::uint16_t>(200 + (i * 37) % 900)});
    const LinkRun r = run(drawing, {});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.device.objectsPlotted, 4u);
    EXPECT_EQ(r.device.pointsRefused, 0u);
    EXPECT_EQ(r.device.pointsStored, 1000u + 3u);  // and the three seam MOVEs
    ASSERT_FALSE(r.drawn.empty());
    EXPECT_EQ(r.drawn.back().x, drawing.back().x);
    EXPECT_EQ(r.drawn.back().y, drawing.back().y);
}

TEST(PlotterLink, GarbageFromTheDeviceSideIsAPlainFailureNotACrash) {
    PlotterHost host;
    host.request();
    double t = 0.0;
    for (; t < 30.0 && !host.failed(); t += 0.01) {
        host.poll(t);
        (void)host.takeOutput();
        for (int b : {0x00, 0xFF, 0x55, 0x6E})
            host.receive(static_cast<std::uint8_t>(b), t);
    }
    ASSERT_TRUE(host.failed());
    EXPECT_NE(host.error().find("REQUEST"), std::string::npos);
    EXPECT_GT(host.stats().unexpected, 100u);
}
