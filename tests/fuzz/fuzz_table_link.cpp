// libFuzzer target: the DC table's link (issue 12). TableHost and the emulated firmware
// (TableFirmware, set points or calibration, from the first byte) are joined back to back, and
// every byte towards the host also feeds an EncoderStreamDecoder; the input is a script of
// bytes injected towards either side, time steps, silences, set points, retry/clear and jams.
// Invariants: no crash; a host call writes nothing or one whole set point and sends at most one
// (one in flight); a failed host says why; the firmware answers at most once a set point, 11
// bytes an answer (set points), or sends at most two bytes every 32 ms (calibration); the
// decoder gives at most one count for two bytes; the host takes no more answers than the
// board sent plus the frames the noise could hold, and off the path is a failure (issue 20
// item 10).
#include <cstdint>
#include <vector>

#include "core/protocol/table_host.h"
#include "hal/emulator/table_firmware.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    static const MachineProfile profile = MachineProfile::xyDcTable();
    fuzz::FuzzInput in(data, size);
    const bool calibration = (in.byte() & 1) != 0;
    TableFirmware device(
        profile, 1,
        calibration ? TableFirmware::Mode::Calibration : TableFirmware::Mode::SetPoints);
    TableHost host;
    table_wire::EncoderStreamDecoder decoder;
    double t = 0.0, deviceS = 0.0;
    std::uint64_t deviceOut = 0, decoderIn = 0, counts = 0;

    auto hostCall = [&](auto&& call) {
        const std::uint64_t before = host.stats().sent;
        call();
        const std::vector<std::uint8_t> out = host.takeOutput();
        const std::uint64_t sent = host.stats().sent - before;
        FUZZ_CHECK(sent <= 1);
        FUZZ_CHECK(out.size() == 4 * sent);
        FUZZ_CHECK(host.failed() == !host.error().empty());
        FUZZ_CHECK(!(host.inFlight() && host.idle()));
        FUZZ_CHECK(!host.offPath() || host.failed());
        for (std::uint8_t b : out)
            device.receive(b, t);
    };
    auto toHost = [&](std::uint8_t b) {
        ++decoderIn;
        if (decoder.feed(b, t)) ++counts;
        FUZZ_CHECK(2 * counts <= decoderIn);
        hostCall([&] { host.receive(b, t); });
    };
    auto fromDevice = [&] {
        // Until nothing is left: an ACK passed to the host sends the next set point, which the
        // board may answer at once (NAK).
        for (std::vector<std::uint8_t> out = device.takeOutput(); !out.empty();
             out = device.takeOutput())
            for (std::uint8_t b : out) {
                ++deviceOut;
                toHost(b);
            }
        const TableFirmwareStats& s = device.stats();
        if (calibration) {
            FUZZ_CHECK(deviceOut == 2 * s.countsSent);
            FUZZ_CHECK(static_cast<double>(s.countsSent) <=
                       deviceS / table_wire::kCalibrationPeriodS + 1.0);
        } else {
            FUZZ_CHECK(deviceOut == table_wire::kAnswerBytes * (s.reached + s.refused + s.cut));
            FUZZ_CHECK(s.answers == s.reached + s.refused + s.cut);
            FUZZ_CHECK(s.answers <= s.setPoints);
        }
    };
    auto stepDevice = [&](double dt) {
        deviceS += dt;
        device.step(dt, t);
        fromDevice();
    };

    for (int ops = 0; ops < 4000 && !in.done(); ++ops) {
        switch (in.byte() % 8) {
            case 0:  // noise towards the board
                device.receive(in.byte(), t);
                fromDevice();
                break;
            case 1:  // noise towards the host (and the decoder)
                toHost(in.byte());
                break;
            case 2:
            case 3: {  // a step of the board's time, 0..50 ms
                const double dt = (in.byte() % 51) * 0.001;
                t += dt;
                stepDevice(dt);
                hostCall([&] { host.poll(t); });
                break;
            }
            case 4:  // a silence of up to 12.75 s: the host's deadline, stale partials
                t += in.byte() * 0.05;
                stepDevice(0.001);
                hostCall([&] { host.poll(t); });
                break;
            case 5: {  // a set point: mostly on the table, sometimes anywhere or not whole
                const std::uint8_t kind = in.byte();
                const double x = in.word(), y = in.word(), frac = in.byte() / 128.0 - 1.0;
                if (kind & 1)
                    host.moveTo(static_cast<int>(x) % 320, static_cast<int>(y) % 320);
                else
                    host.moveTo(x + frac, y - frac);
                break;
            }
            case 6: {
                const std::uint8_t what = in.byte();
                if (what & 1)
                    hostCall([&] { what & 2 ? host.retry() : host.clear(); });
                else
                    device.table().setJammed((what >> 1) & 1, (what & 4) != 0);
                break;
            }
            default:  // the calibration stream's decoder on its own, any byte at any time
                t += in.byte() * 0.001;
                toHost(in.byte());
                break;
        }
    }
    return 0;
}
