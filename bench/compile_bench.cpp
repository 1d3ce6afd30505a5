// Compile benchmark (issue 2): generates a 1,000,000-line standard-dialect program, then, in a
// fresh child process so the generator's memory does not count, reads and compiles it several
// times and prints the median lines per second and the peak resident memory (VmHWM, the file's
// bytes included). Shapes (issue 9: compile time must be linear for any program):
//   mixed     block numbers, G0/G1 moves with decimals, feeds, comments (the default)
//   gotos     the program: N1 G0 X0, half G0 X1, half M3 X1, M2 (was quadratic)
//   numbered  every other block a goto to an earlier numbered block
//   invalid   every line a Q: one diagnostic per line
//   cr        the mixed program with CR-only line ends
//
//   trilho-bench-compile [--shape NAME] [--lines N] [--runs R] [--keep FILE]
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/gcode/compiler.h"
#include "core/gcode/source_file.h"

namespace {

long statusKb(const char* key) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::size_t len = std::strlen(key);
    while (std::getline(in, line))
        if (line.compare(0, len, key) == 0) return std::atol(line.c_str() + len + 1);
    return -1;
}

void generate(const std::string& path, long lines, const std::string& shape) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) std::perror(path.c_str()), std::exit(2);
    if (shape == "gotos") {
        const long half = (lines - 2) / 2;
        std::fputs("N1 G0 X0\n", out);
        for (long i = 0; i < half; ++i)
            std::fputs("G0 X1\n", out);
        for (long i = 0; i < lines - 2 - half; ++i)
            std::fputs("M3 X1\n", out);
        std::fputs("M2\n", out);
        std::fclose(out);
        return;
    }
    if (shape == "numbered") {
        for (long i = 1; i < lines; ++i)
            if (i % 2)
                std::fprintf(out, "N%ld G0 X%ld\n", i, i % 1000);
            else
                std::fprintf(out, "N%ld M3 X%ld\n", i, i / 2 | 1);
        std::fprintf(out, "N%ld M2\n", lines);
        std::fclose(out);
        return;
    }
    if (shape == "invalid") {
        for (long i = 0; i < lines; ++i)
            std::fputs("Q\n", out);
        std::fclose(out);
        return;
    }
    const char eol = shape == "cr" ? '\r' : '\n';
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> pos(-1200.0, 1200.0);
    std::uniform_int_distribution<int> kind(0, 9);
    std::FILE* f = out;
    long n = 10;
    for (long i = 0; i < lines - 1; ++i, n += 10) {
        int k = kind(rng);
        if (k == 0)
            std::fprintf(f, "N%ld G1 X%.3f F%.1f ( approach )%c", n, pos(rng), 5.0 + k * 9.5, eol);
        else if (k < 5)
            std::fprintf(f, "N%ld G1 X%.3f F%d%c", n, pos(rng), 10 + k * 10, eol);
        else if (k < 9)
            std::fprintf(f, "N%ld G0 X%.2f%c", n, pos(rng), eol);
        else
            std::fprintf(f, "N%ld X%.3f ; modal move%c", n, pos(rng), eol);
    }
    std::fprintf(f, "N%ld M2%c", n, eol);
    std::fclose(f);
}

int measure(const std::string& path, int runs, bool expectErrors) {
    const long baselineKb = statusKb("VmRSS:");
    std::vector<double> seconds;
    std::size_t lines = 0, bytes = 0, blocks = 0;
    for (int r = 0; r < runs; ++r) {
        auto t0 = std::chrono::steady_clock::now();
        trilho::SourceFile src = trilho::readSourceFile(path);
        if (!src.ok) return std::fprintf(stderr, "%s\n", src.error.c_str()), 2;
        trilho::Program p = trilho::compile(src.bytes, {trilho::Dialect::Standard, {}});
        auto t1 = std::chrono::steady_clock::now();
        if (p.ok() == expectErrors)
            return std::fprintf(stderr, "generated program has %zu errors\n", p.errorCount()), 1;
        seconds.push_back(std::chrono::duration<double>(t1 - t0).count());
        lines = p.lineCount, bytes = src.bytes.size(), blocks = p.blocks.size();
    }
    std::sort(seconds.begin(), seconds.end());
    const double median = seconds[seconds.size() / 2];
    const long peakKb = statusKb("VmHWM:");
    std::printf("file: %zu lines, %.1f MB; %zu blocks of %zu bytes\n", lines,
                static_cast<double>(bytes) / 1048576.0, blocks, sizeof(trilho::Block));
    std::printf("read+compile: median %.1f ms over %d runs (min %.1f, max %.1f)\n", median * 1e3,
                runs, seconds.front() * 1e3, seconds.back() * 1e3);
    std::printf("lines per second: %.2f M (median)\n", static_cast<double>(lines) / median / 1e6);
    std::printf("peak resident memory: %.1f MB (process baseline before reading %.1f MB)\n",
                static_cast<double>(peakKb) / 1024.0, static_cast<double>(baselineKb) / 1024.0);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    long lines = 1000000;
    int runs = 7;
    std::string keep, shape = "mixed";
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--measure" && i + 3 < argc)
            return measure(argv[i + 1], std::atoi(argv[i + 2]), std::string(argv[i + 3]) == "1");
        if (a == "--lines" && i + 1 < argc)
            lines = std::atol(argv[++i]);
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (a == "--keep" && i + 1 < argc)
            keep = argv[++i];
        else if (a == "--shape" && i + 1 < argc)
            shape = argv[++i];
        else
            return std::fprintf(stderr,
                                "usage: %s [--shape mixed|gotos|numbered|invalid|cr] [--lines N] "
                                "[--runs R] [--keep FILE]\n",
                                argv[0]),
                   2;
    }
    if (shape != "mixed" && shape != "gotos" && shape != "numbered" && shape != "invalid" &&
        shape != "cr")
        return std::fprintf(stderr, "unknown shape '%s'\n", shape.c_str()), 2;
    std::printf("shape: %s\n", shape.c_str());
    std::string path = keep.empty() ? "/tmp/trilho-bench-" + std::to_string(getpid()) + ".G" : keep;
    generate(path, lines, shape);
    std::fflush(stdout);
    pid_t child = fork();
    if (child == 0) {
        std::string r = std::to_string(runs);
        execl("/proc/self/exe", argv[0], "--measure", path.c_str(), r.c_str(),
              shape == "invalid" ? "1" : "0", static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (keep.empty()) std::remove(path.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}
