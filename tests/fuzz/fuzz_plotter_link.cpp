// libFuzzer target: the plotter's link (issue 12). PlotterHost and the emulated firmware
// (PlotterFirmware) are joined back to back; the input is a script of bytes injected towards
// either side, time steps (short, and long silences that fire the deadlines) and host jobs.
// Invariants: no crash; a host call writes nothing or one whole valid packet and sends at most
// one (one packet in flight); a failed host says why; the firmware answers at most one byte
// for each byte it received (one a packet, or one RESEND after a partial); a barrier that
// flushes late answers is a REQUEST; an unknown state is a failure.
#include <cstdint>
#include <vector>

#include "core/protocol/plotter_host.h"
#include "hal/emulator/plotter_firmware.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trilho;
    using plotter_wire::Command;
    static const MachineProfile profile = MachineProfile::xyPlotter();
    fuzz::FuzzInput in(data, size);
    PlotterFirmware device(profile, 1);
    PlotterHost host;
    double t = 0.0;
    std::uint64_t deviceIn = 0, deviceOut = 0, barriers = 0;

    auto toDevice = [&](std::uint8_t b) {
        ++deviceIn;
        device.receive(b, t);
    };
    auto hostCall = [&](auto&& call) {
        const std::uint64_t before = host.stats().packetsSent;
        call();
        const std::vector<std::uint8_t> out = host.takeOutput();
        const std::uint64_t sent = host.stats().packetsSent - before;
        FUZZ_CHECK(sent <= 1);
        FUZZ_CHECK(out.size() == sent * plotter_wire::kPacketBytes);
        if (!out.empty()) {
            plotter_wire::Packet p{};
            std::copy(out.begin(), out.end(), p.begin());
            FUZZ_CHECK(plotter_wire::decode(p).has_value());
        }
        FUZZ_CHECK(host.failed() == !host.error().empty());
        FUZZ_CHECK(!host.stateUnknown() || host.failed());
        // A barrier (issue 20 item 10) is a REQUEST: the host never sends a packet that moves
        // the head to flush late answers.
        if (host.stats().barriers > barriers) {
            FUZZ_CHECK(out.empty() || out[0] == static_cast<std::uint8_t>(Command::Request));
            barriers = host.stats().barriers;
        }
        for (std::uint8_t b : out)
            toDevice(b);
    };
    auto fromDevice = [&] {
        for (std::uint8_t b : device.takeOutput()) {
            ++deviceOut;
            hostCall([&] { host.receive(b, t); });
        }
        FUZZ_CHECK(deviceOut <= deviceIn);
    };

    for (int ops = 0; ops < 4000 && !in.done(); ++ops) {
        switch (in.byte() % 8) {
            case 0:  // noise towards the device
                toDevice(in.byte());
                fromDevice();
                break;
            case 1: {  // noise towards the host
                const std::uint8_t b = in.byte();
                hostCall([&] { host.receive(b, t); });
                break;
            }
            case 2:
            case 3: {  // a step of the board's time, 0..50 ms
                const double dt = (in.byte() % 51) * 0.001;
                t += dt;
                device.step(dt, t);
                fromDevice();
                hostCall([&] { host.poll(t); });
                break;
            }
            case 4:  // a silence of up to 12.75 s: the host's deadlines, the 2 s RESEND
                t += in.byte() * 0.05;
                device.step(0.001, t);
                fromDevice();
                hostCall([&] { host.poll(t); });
                break;
            case 5: {  // a job
                const std::uint8_t job = in.byte();
                const std::uint16_t value = in.word();
                switch (job % 6) {
                    case 0:
                        host.request();
                        break;
                    case 1:
                        host.speed(value);
                        break;
                    case 2:
                        host.origin();
                        break;
                    case 3: {
                        static constexpr Command kJogs[] = {Command::Up, Command::Down,
                                                            Command::Left, Command::Right};
                        host.jog(kJogs[value % 4]);
                        break;
                    }
                    case 4: {  // a short drawing near the origin (plots in virtual seconds)
                        std::vector<PlotPoint> drawing(1 + value % 8);
                        for (PlotPoint& p : drawing)
                            p = {(in.byte() & 1) != 0, static_cast<std::uint16_t>(in.byte()),
                                 static_cast<std::uint16_t>(in.byte())};
                        host.plot(drawing);
                        break;
                    }
                    default:
                        hostCall([&] { value % 2 ? host.retry() : host.clear(); });
                        break;
                }
                break;
            }
            default:  // the host alone, at the same time
                hostCall([&] { host.poll(t); });
                break;
        }
    }
    return 0;
}
