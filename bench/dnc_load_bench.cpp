// trilho-bench-dnc: load on a Modbus TCP server (issue 13 item 6), with libmodbus as the client
// so that the client's own overhead stays small and threads run in parallel (a Python client's
// GIL would put its own pauses into the p99).
//
//   trilho-bench-dnc load PORT [CLIENTS=20] [RATE_HZ=100] [SECONDS=60]
//     CLIENTS threads, each with its own connection, read the status block (input registers
//     0..33, function 04) at RATE_HZ on absolute times (clock_nanosleep, no drift), their
//     phases spread evenly over one period. Counts requests sent, answered, lost (timeout or
//     error: the response timeout is 1 s), late (answered more than 50 ms after it was due:
//     the client's view, which a client thread woken late also makes late) and slow (answered
//     more than 50 ms after it was sent: the server's part).
//   trilho-bench-dnc throughput PORT [CLIENTS=8] [SECONDS=5]
//     CLIENTS threads send the same request back to back: requests per second.
//
// Both print a human line and a last line of key=value pairs (scripts/bench-dnc reads it);
// latencies are from the send to the whole reply, in milliseconds, exact percentiles. Exit 0
// when every request was answered, 1 otherwise, 64 on bad usage.
#include <modbus.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr int kStatusRegisters = 34;        // input registers 0..33 (core/dnc/register_map.h)
constexpr std::int64_t kLateNs = 50000000;  // 50 ms: the bound

std::int64_t nowNs() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

void sleepUntil(std::int64_t ns) {
    timespec ts{static_cast<time_t>(ns / 1000000000LL), static_cast<long>(ns % 1000000000LL)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

struct ClientResult {
    std::uint64_t sent = 0, answered = 0, lost = 0;
    std::uint64_t late = 0;  ///< answered more than 50 ms after it was due (client's view)
    std::uint64_t slow = 0;  ///< answered more than 50 ms after it was sent (the server's part)
    bool connected = false;
    std::vector<std::int64_t> latencyNs;  ///< send to reply, answered requests only
};

/// One connection; nullptr (and a message) when it cannot connect.
modbus_t* connectClient(int port) {
    modbus_t* ctx = modbus_new_tcp("127.0.0.1", port);
    if (!ctx) return nullptr;
    modbus_set_response_timeout(ctx, 1, 0);  // 1 s: a reply later than that counts as lost
    modbus_set_slave(ctx, 1);
    if (modbus_connect(ctx) != 0) {
        std::fprintf(stderr, "trilho-bench-dnc: connect to 127.0.0.1:%d: %s\n", port,
                     modbus_strerror(errno));
        modbus_free(ctx);
        return nullptr;
    }
    return ctx;
}

/// One request; false when it failed (the socket is then flushed so a late reply cannot be
/// taken for the next one's).
bool readStatus(modbus_t* ctx) {
    std::uint16_t regs[kStatusRegisters];
    if (modbus_read_input_registers(ctx, 0, kStatusRegisters, regs) == kStatusRegisters)
        return true;
    modbus_flush(ctx);
    return false;
}

void paced(modbus_t* ctx, double rateHz, double seconds, std::int64_t startNs, std::int64_t phaseNs,
           ClientResult& r) {
    const auto periodNs = static_cast<std::int64_t>(1e9 / rateHz);
    const auto count = static_cast<std::uint64_t>(seconds * rateHz);
    r.latencyNs.reserve(count);
    for (std::uint64_t k = 0; k < count; ++k) {
        const std::int64_t due = startNs + phaseNs + static_cast<std::int64_t>(k) * periodNs;
        sleepUntil(due);  // when behind, at once: the lateness is counted, not hidden
        const std::int64_t sent = nowNs();
        ++r.sent;
        const bool ok = readStatus(ctx);
        const std::int64_t done = nowNs();
        if (!ok) {
            ++r.lost;
            continue;
        }
        ++r.answered;
        r.latencyNs.push_back(done - sent);
        if (done - due > kLateNs) ++r.late;
        if (done - sent > kLateNs) ++r.slow;
    }
}

void flat(modbus_t* ctx, std::int64_t endNs, ClientResult& r) {
    r.latencyNs.reserve(1 << 20);
    while (nowNs() < endNs) {
        const std::int64_t sent = nowNs();
        ++r.sent;
        if (!readStatus(ctx)) {
            ++r.lost;
            continue;
        }
        ++r.answered;
        r.latencyNs.push_back(nowNs() - sent);
    }
}

double ms(std::int64_t ns) {
    return static_cast<double>(ns) * 1e-6;
}

int usage() {
    std::fprintf(stderr,
                 "usage: trilho-bench-dnc load PORT [CLIENTS=20] [RATE_HZ=100] [SECONDS=60]\n"
                 "       trilho-bench-dnc throughput PORT [CLIENTS=8] [SECONDS=5]\n");
    return 64;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return usage();
    const std::string mode = argv[1];
    const bool load = mode == "load";
    if (!load && mode != "throughput") return usage();
    const int port = std::atoi(argv[2]);
    const int clients = argc > 3 ? std::atoi(argv[3]) : (load ? 20 : 8);
    const double rateHz = load && argc > 4 ? std::atof(argv[4]) : 100.0;
    const int secondsArg = load ? 5 : 4;
    const double seconds = argc > secondsArg ? std::atof(argv[secondsArg]) : (load ? 60.0 : 5.0);
    if (port < 1 || port > 65535 || clients < 1 || clients > 1000 || rateHz <= 0 ||
        rateHz > 10000 || seconds <= 0 || seconds > 86400)
        return usage();

    std::vector<ClientResult> results(static_cast<std::size_t>(clients));
    // Every client connects before the clock starts, so a slow connect is not a late request.
    std::vector<modbus_t*> contexts;
    for (int i = 0; i < clients; ++i) {
        contexts.push_back(connectClient(port));
        results[static_cast<std::size_t>(i)].connected = contexts.back() != nullptr;
    }
    std::vector<std::thread> threads;
    const std::int64_t startNs = nowNs() + 100000000LL;  // 100 ms for the threads to start
    const auto periodNs = static_cast<std::int64_t>(1e9 / rateHz);
    for (int i = 0; i < clients; ++i) {
        ClientResult& r = results[static_cast<std::size_t>(i)];
        modbus_t* ctx = contexts[static_cast<std::size_t>(i)];
        if (!ctx) continue;
        if (load)
            threads.emplace_back(paced, ctx, rateHz, seconds, startNs, periodNs * i / clients,
                                 std::ref(r));
        else
            threads.emplace_back([&r, ctx, startNs, seconds] {
                sleepUntil(startNs);
                flat(ctx, startNs + static_cast<std::int64_t>(seconds * 1e9), r);
            });
    }
    for (std::thread& t : threads)
        t.join();
    const double elapsedS = ms(nowNs() - startNs) * 1e-3;
    for (modbus_t* ctx : contexts) {
        if (!ctx) continue;
        modbus_close(ctx);
        modbus_free(ctx);
    }

    ClientResult all;
    int unconnected = 0;
    for (ClientResult& r : results) {
        unconnected += r.connected ? 0 : 1;
        all.sent += r.sent, all.answered += r.answered, all.lost += r.lost;
        all.late += r.late, all.slow += r.slow;
        all.latencyNs.insert(all.latencyNs.end(), r.latencyNs.begin(), r.latencyNs.end());
    }
    std::sort(all.latencyNs.begin(), all.latencyNs.end());
    auto q = [&](double p) {
        if (all.latencyNs.empty()) return 0.0;
        const auto i = static_cast<std::size_t>(p * static_cast<double>(all.latencyNs.size() - 1));
        return ms(all.latencyNs[i]);
    };
    const double maxMs = all.latencyNs.empty() ? 0.0 : ms(all.latencyNs.back());
    const double perS = static_cast<double>(all.answered) / elapsedS;
    using ull = unsigned long long;
    if (load)
        std::printf(
            "%d clients x %g Hz x %g s: %llu sent, %llu answered, %llu lost, %llu late "
            "(answered > 50 ms after due), %llu slow (> 50 ms after sent); latency ms "
            "p50 %.3f p99 %.3f max %.3f; %.0f requests/s\n",
            clients, rateHz, seconds, ull{all.sent}, ull{all.answered}, ull{all.lost},
            ull{all.late}, ull{all.slow}, q(0.5), q(0.99), maxMs, perS);
    else
        std::printf(
            "%d clients back to back for %g s: %.0f requests/s; latency ms p50 %.3f p99 "
            "%.3f max %.3f; %llu lost\n",
            clients, seconds, perS, q(0.5), q(0.99), maxMs, ull{all.lost});
    std::printf(
        "result mode=%s clients=%d unconnected=%d sent=%llu answered=%llu lost=%llu "
        "late=%llu slow=%llu rps=%.0f p50_ms=%.3f p99_ms=%.3f max_ms=%.3f\n",
        mode.c_str(), clients, unconnected, ull{all.sent}, ull{all.answered}, ull{all.lost},
        ull{all.late}, ull{all.slow}, perS, q(0.5), q(0.99), maxMs);
    return unconnected == 0 && all.lost == 0 && all.sent > 0 ? 0 : 1;
}
