// Seeded property test: random valid programs in both dialects compile without diagnostics,
// and the resolved blocks match an independent computation (strtod for numbers, a direct
// simulation of the modal state for positions).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "core/gcode/compiler.h"

namespace trilho {
namespace {

struct Expected {
    Op op;
    double x = 0, feed = 0;
    int targetIndex = -1;
};

/// Builds a random valid program and, independently, what each block must resolve to.
struct Generator {
    std::mt19937_64 rng;
    Dialect dialect;
    std::string text;
    std::vector<Expected> expected;
    bool incremental = false;
    double zero = 0, prev = 0, feed = 0;
    int motion = -1;
    int n = 0;

    Generator(std::uint64_t seed, Dialect d) : rng(seed), dialect(d) {}

    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    std::string number(double& value, int lo, int hi, bool decimals) {
        char buf[64];
        if (dialect == Dialect::Classic || !decimals) {
            int v = pick(lo, hi);
            value = v;
            if (dialect == Dialect::Classic)
                std::snprintf(buf, sizeof buf, v < 0 ? "-%04d" : "%04d", std::abs(v));
            else
                std::snprintf(buf, sizeof buf, "%d", v);
        } else {
            int digits = pick(0, 3);
            std::snprintf(buf, sizeof buf, "%.*f", digits,
                          std::uniform_real_distribution<double>(lo, hi)(rng));
            value = std::strtod(buf, nullptr);  // the independent parse
        }
        return buf;
    }
    std::string g(int code) {
        char buf[8];
        std::snprintf(buf, sizeof buf,
                      dialect == Dialect::Classic ? "g%02d" : (pick(0, 1) ? "G%d" : "g%02d"), code);
        return buf;
    }
    void line(const std::string& words) {
        n += pick(1, 10);
        char buf[16];
        std::snprintf(buf, sizeof buf, "n%04d ", n);
        text += buf + words;
        if (dialect == Dialect::Standard && pick(0, 3) == 0) text += "  ( note )";
        text += pick(0, 1) ? "\n" : "\r\n";
    }
    /// A target that keeps the move inside the +-1270 mm soft limits.
    std::string move(int code) {
        double v = 0;
        std::string word;
        double target;
        do {
            word = number(v, incremental ? -300 : -1200, incremental ? 300 : 1200, true);
            target = incremental ? prev + v : v + zero;
        } while (std::abs(target) > 1270);
        std::string out = (code >= 0 ? g(code) + " " : "") + "x" + word;
        Expected e{code == 0 || (code < 0 && motion == 0) ? Op::Rapid : Op::Linear, target, 100};
        if (e.op == Op::Linear) {
            if (feed == 0 || pick(0, 2) == 0) {
                double f = 0;
                std::string fw = dialect == Dialect::Classic ? "" : number(f, 1, 100, true);
                if (dialect == Dialect::Classic) {
                    char buf[8];
                    f = pick(1, 100);
                    std::snprintf(buf, sizeof buf, "%03d", static_cast<int>(f));
                    fw = buf;
                }
                if (f == 0) f = 1, fw = "1";
                out += " f" + fw;
                feed = f;
            }
            e.feed = feed;
        }
        if (code >= 0) motion = code;
        prev = target;
        expected.push_back(e);
        return out;
    }

    void generate(int blocks) {
        line(move(pick(0, 1)));
        std::vector<std::pair<std::size_t, int>> gotos;  // expected index, target n
        std::vector<int> ns{n};
        for (int i = 0; i < blocks; ++i) {
            switch (pick(0, 9)) {
                case 0:
                    incremental = false, line(g(90)), expected.push_back({Op::Absolute});
                    break;
                case 1:
                    incremental = true, line(g(91)), expected.push_back({Op::Incremental});
                    break;
                case 2: {
                    double v = 0;
                    std::string w = number(v, -500, 500, true);
                    zero = v;
                    line(g(92) + " x" + w);
                    expected.push_back({Op::SetZero, v});
                    break;
                }
                case 3:
                    zero = 0, line(g(93)), expected.push_back({Op::ResetZero});
                    break;
                case 4: {
                    double v = 0;
                    std::string w = number(v, 0, 20, true);
                    line(g(4) + " x" + w);
                    expected.push_back({Op::Dwell, v});
                    break;
                }
                case 5:
                    line(dialect == Dialect::Classic ? "m00" : "M0"),
                        expected.push_back({Op::Stop});
                    break;
                case 6: {
                    int target =
                        ns[static_cast<std::size_t>(pick(0, static_cast<int>(ns.size()) - 1))];
                    char buf[24];
                    std::snprintf(buf, sizeof buf, "m03 x%04d", target);
                    line(buf);
                    gotos.push_back({expected.size(), target});
                    expected.push_back({Op::Goto, static_cast<double>(target)});
                    break;
                }
                case 7:
                    line(move(-1));
                    break;
                default:
                    line(move(pick(0, 1)));
                    break;
            }
            ns.push_back(n);
        }
        line(dialect == Dialect::Classic ? "m02" : "M02");
        expected.push_back({Op::End});
        ns.push_back(n);
        for (auto [index, target] : gotos) {
            for (std::size_t k = 0; k < ns.size(); ++k)
                if (ns[k] == target) expected[index].targetIndex = static_cast<int>(k);
        }
    }
};

class CompilerProperty : public ::testing::TestWithParam<Dialect> {};

TEST_P(CompilerProperty, RandomValidProgramsResolveAsComputedIndependently) {
    const Dialect dialect = GetParam();
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        Generator gen(seed * 7919 + (dialect == Dialect::Classic ? 1 : 2), dialect);
        gen.generate(static_cast<int>(seed % 60) + 5);
        Program p = compile(gen.text, {dialect, {}});
        ASSERT_TRUE(p.ok()) << "seed " << seed << ": " << p.diagnostics[0].code() << " at line "
                            << p.diagnostics[0].line << "\n"
                            << gen.text;
        ASSERT_EQ(p.blocks.size(), gen.expected.size()) << "seed " << seed;
        for (std::size_t i = 0; i < p.blocks.size(); ++i) {
            const Block& b = p.blocks[i];
            const Expected& e = gen.expected[i];
            ASSERT_EQ(b.op, e.op) << "seed " << seed << " block " << i;
            // Positions accumulate in the same order, so they agree to the last bit.
            EXPECT_EQ(b.x, e.x) << "seed " << seed << " block " << i;
            if (isMotion(b.op)) {
                EXPECT_EQ(b.feed, e.feed) << "seed " << seed << " block " << i;
            }
            if (b.op == Op::Goto) {
                EXPECT_EQ(b.targetIndex, e.targetIndex) << "seed " << seed;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(BothDialects, CompilerProperty,
                         ::testing::Values(Dialect::Classic, Dialect::Standard),
                         [](const auto& param_info) {
                             return std::string(dialectName(param_info.param));
                         });

}  // namespace
}  // namespace trilho
