// Issue 9, numbers and line ends: every number is checked before it is converted, tiny feeds
// and huge values are refused with the limit named, CR-only files and a trailing DOS ^Z work.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/gcode/compiler.h"

namespace trilho {
namespace {

Program compileIn(Dialect d, const std::string& src) {
    CompileOptions o;
    o.dialect = d;
    return compile(src, o);
}
Program std_(const std::string& src) {
    return compileIn(Dialect::Standard, src);
}

std::vector<std::string> codes(const Program& p) {
    std::vector<std::string> out;
    for (const auto& d : p.diagnostics)
        out.emplace_back(d.code());
    return out;
}

// ---- numbers above 2^31-1 ----------------------------------------------------------------------

TEST(CompilerNumbers, HugeBlockNumberIsADiagnosticNotDropped) {
    Program p = std_("N99999999999 G0 X1\nM2\n");
    ASSERT_EQ(codes(p), std::vector<std::string>{"n-range"});
    EXPECT_EQ(p.diagnostics[0].line, 1u);
    EXPECT_EQ(p.diagnostics[0].column, 1u);
    EXPECT_EQ(p.diagnostics[0].textView(), "N99999999999");
    EXPECT_DOUBLE_EQ(p.diagnostics[0].value, 2147483647.0);
    // The largest n that fits is accepted and kept.
    Program q = std_("N2147483647 G0 X1\nM2\n");
    ASSERT_TRUE(q.ok());
    EXPECT_EQ(q.blocks[0].n, 2147483647);
    EXPECT_EQ(codes(std_("N2147483648 G0 X1\nM2\n")), std::vector<std::string>{"n-range"});
}

TEST(CompilerNumbers, HugeGAndMCodesAreInvalidCodes) {
    EXPECT_EQ(codes(std_("G99999999999 X1\nM2\n")), std::vector<std::string>{"invalid-g"});
    EXPECT_EQ(codes(std_("G4294967296 X1\nM2\n")), std::vector<std::string>{"invalid-g"});
    // 2^32 + 2 must never wrap to m02 (or anything else).
    EXPECT_EQ(codes(std_("G0 X1\nM4294967298\nM2\n")), std::vector<std::string>{"invalid-m"});
    EXPECT_EQ(codes(std_("G0 X1\nM999999999999999999\nM2\n")),
              std::vector<std::string>{"invalid-m"});
}

TEST(CompilerNumbers, HugeCodeNamedAsWrittenInTrailingWords) {
    Program p = std_("G99999999999 G1 X1\nM2\n");
    ASSERT_EQ(codes(p), std::vector<std::string>{"trailing-words"});
    EXPECT_EQ(p.diagnostics[0].textView(), "g99999999999");
    Program m = std_("M4294967298 M2\nM2\n");
    ASSERT_EQ(codes(m), std::vector<std::string>{"trailing-words"});
    EXPECT_EQ(m.diagnostics[0].textView(), "m4294967298");
}

// ---- feeds below the machine's real minimum ----------------------------------------------------

TEST(CompilerNumbers, FeedBelowTheRealMinimumIsRefusedAtCompileTime) {
    for (const char* src :
         {"G1 X1 F0.0000001\nM2\n", "G1 X1 F0.05\nM2\n", "F0.09\nM2\n", "G1 X1 F0.099999\nM2\n"}) {
        Program p = std_(src);
        ASSERT_EQ(codes(p), std::vector<std::string>{"feed-range"}) << src;
        EXPECT_DOUBLE_EQ(p.diagnostics[0].value, kMinFeedPercent) << src;
    }
    EXPECT_TRUE(std_("G1 X1 F0.1\nM2\n").ok());
    EXPECT_EQ(std_("G1 X1 F0.1\nM2\n").blocks[0].feed, 0.1);
    // Above 100 % names the same range.
    Program high = std_("G1 X1 F100.5\nM2\n");
    ASSERT_EQ(codes(high), std::vector<std::string>{"feed-range"});
    EXPECT_DOUBLE_EQ(high.diagnostics[0].value, kMinFeedPercent);
}

// ---- huge positions, offsets and times --------------------------------------------------------

TEST(CompilerNumbers, HugeOffsetsPositionsAndTimesAreRefused) {
    for (const char* src : {"G92 X999999999999999999\nM2\n", "G92 X1000000.001\nM2\n",
                            "G92 X-2000000\nM2\n", "G91\nG0 X999999999999999999\nM2\n",
                            "G4 X99999999999\nM2\n", "G0 X0\nX-999999999999\nM2\n"}) {
        Program p = std_(src);
        ASSERT_EQ(codes(p), std::vector<std::string>{"value-range"}) << src;
        EXPECT_DOUBLE_EQ(p.diagnostics[0].value, kMaxValueMagnitude) << src;
    }
    Program p = std_("G92 X999999999999999999\nM2\n");
    EXPECT_EQ(p.diagnostics[0].column, 5u);
    EXPECT_EQ(p.diagnostics[0].textView(), "X999999999999999999");
    EXPECT_TRUE(std_("G92 X1000000\nG93\nG4 X1000000\nM2\n").ok());
    // Classic widths cannot reach the bound; a classic program is never affected.
    EXPECT_TRUE(compileIn(Dialect::Classic, "n0010 g92 x-9999\nn0020 m02\n").ok());
}

// ---- line ends and end of file -----------------------------------------------------------------

TEST(CompilerLineEnds, CrOnlyLineEndsSplitLines) {
    Program p = std_("G0 X1\rG0 X2\r\rM2\r");
    ASSERT_TRUE(p.ok()) << (p.diagnostics.empty() ? "" : std::string(p.diagnostics[0].code()));
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.lineCount, 4u);
    EXPECT_EQ(p.blocks[1].line, 2u);
    EXPECT_EQ(p.blocks[2].line, 4u);
    Program c = compileIn(Dialect::Classic, "n0010 g00 x0010\rn0020 m02\r");
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c.blocks[1].line, 2u);
    // Mixed endings: LF, CRLF and CR each end one line.
    Program mixed = std_("G0 X1\nG0 X2\r\nG0 X3\rG0 Q\nM2");
    ASSERT_EQ(codes(mixed), std::vector<std::string>{"invalid-char"});
    EXPECT_EQ(mixed.diagnostics[0].line, 4u);
    EXPECT_EQ(mixed.lineCount, 5u);
}

TEST(CompilerLineEnds, TrailingDosEndOfFileIsIgnored) {
    EXPECT_TRUE(std_("G0 X1\nM2\n\x1A").ok());
    EXPECT_TRUE(std_("G0 X1\r\nM2\x1A").ok());
    EXPECT_TRUE(compileIn(Dialect::Classic, "n0010 m02\r\n\x1A").ok());
    EXPECT_EQ(std_("G0 X1\nM2\n\x1A").lineCount, 2u);
    // Only at the very end: a ^Z inside the program is still an invalid character.
    EXPECT_EQ(codes(std_("G0 X1\x1A\nM2\n")), std::vector<std::string>{"invalid-char"});
}

// ---- diagnostics kept per file ----------------------------------------------------------------

TEST(CompilerDiagnosticCap, KeepsTheFirstAndCountsTheRest) {
    std::string src;
    for (int i = 0; i < 5000; ++i)
        src += "Q\n";
    src += "N10 M3 X5\n";  // goto-target, found at the end but on line 5001
    CompileOptions o;
    o.maxDiagnostics = 1000;
    Program p = compile(src, o);
    EXPECT_EQ(p.diagnostics.size(), 1000u);
    EXPECT_EQ(p.errorCount(), 5002u);  // 5000 invalid-char, goto-target, missing-m02
    EXPECT_EQ(p.diagnosticsOmitted, 4002u);
    EXPECT_EQ(p.diagnostics.back().line, 1000u);
    EXPECT_FALSE(p.ok());
    // An early goto-target comes before later errors, as in an uncapped list.
    std::string early = "N10 M3 X5\n";
    for (int i = 0; i < 50; ++i)
        early += "Q\n";
    o.maxDiagnostics = 10;
    Program e = compile(early, o);
    ASSERT_EQ(e.diagnostics.size(), 10u);
    EXPECT_EQ(e.diagnostics[0].code(), "goto-target");
    EXPECT_EQ(e.errorCount(), 52u);
}

}  // namespace
}  // namespace trilho

namespace trilho {
namespace {

// ---- goto resolution is linear (issue 9: 200,000 gotos took 35 s) ------------------------------

/// Work to resolve the gotos of a program built by shape(k): counted, not timed.
template <typename Shape>
std::size_t gotoSteps(Shape shape, int k) {
    CompileStats stats;
    CompileOptions o;
    o.stats = &stats;
    Program p = compile(shape(k), o);
    EXPECT_EQ(p.blocks.size(), static_cast<std::size_t>(2 * k + 2));
    return stats.gotoSteps;
}

/// Four times the program must cost at most about four times the work (n log n allows a little
/// more); the quadratic resolution cost sixteen times.
template <typename Shape>
void expectLinear(Shape shape, const char* name) {
    const std::size_t small = gotoSteps(shape, 20000);
    const std::size_t large = gotoSteps(shape, 80000);
    EXPECT_GT(large, 0u) << name;
    EXPECT_LE(large, 5 * small) << name << ": " << small << " -> " << large << " steps";
}

TEST(CompilerComplexity, GotosAmongUnnumberedBlocksResolveInLinearWork) {
    // The program: N1 G0 X0, k G0 X1, k M3 X1, M2.
    expectLinear(
        [](int k) {
            std::string s = "N1 G0 X0\n";
            for (int i = 0; i < k; ++i)
                s += "G0 X1\n";
            for (int i = 0; i < k; ++i)
                s += "M3 X1\n";
            return s + "M2\n";
        },
        "unnumbered");
}

TEST(CompilerComplexity, GotosWithOutOfOrderNumbersResolveInLinearWork) {
    expectLinear(
        [](int k) {
            std::string s = "N5 G0 X0\n";
            for (int i = 0; i < k; ++i)
                s += "N" + std::to_string(10 + i) + " M3 X3\n";
            for (int i = 0; i < k; ++i)
                s += "G0 X1\n";
            return s + "N3 M2\n";  // out of order (n-order), and the target of every goto
        },
        "out of order");
}

TEST(CompilerComplexity, NumberedGotosResolveInLinearWork) {
    expectLinear(
        [](int k) {
            std::string s = "N1 G0 X0\n";
            for (int i = 0; i < 2 * k; ++i)
                s += "N" + std::to_string(2 + i) + (i % 2 ? " G0 X1\n" : " M3 X1\n");
            return s + "M2\n";
        },
        "numbered");
}

}  // namespace
}  // namespace trilho
