// The compiler: one pass over the lines, each lexed into a scratch set of words, checked
// against every rule, and only then committed to the modal state and the block vector
// (the Grbl way). Goto targets are resolved at the end, when every n is known, through an
// index of the numbered blocks built once (linear in the program, whatever its shape).
#include "core/gcode/compiler.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "core/gcode/decimal_scan.h"

namespace trilho {
namespace {

/// Numbers longer than this are refused before parsing: nothing on the rail needs them, and
/// a 10 MB run of digits must not cost more than a glance.
constexpr int kMaxNumberDigits = 18;

struct Word {
    bool present = false;
    double value = 0.0;
    std::uint32_t column = 0;  ///< 1-based column of the letter
    bool integral = true;      ///< no decimal point and no fraction
};

struct LineWords {
    Word n, g, x, y, f, m;
    bool any() const { return g.present || x.present || y.present || f.present || m.present; }
};

bool isDigit(char c) {
    return static_cast<unsigned>(c - '0') < 10u;
}
bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c | 0x20) : c;
}
bool isAlpha(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

/// Length of a valid UTF-8 sequence starting at p, or 0 when the bytes are not valid UTF-8.
std::size_t utf8Length(const char* p, const char* end) {
    auto b0 = static_cast<unsigned char>(*p);
    std::size_t len = b0 < 0x80           ? 1
                      : (b0 >> 5) == 0x6  ? 2
                      : (b0 >> 4) == 0xE  ? 3
                      : (b0 >> 3) == 0x1E ? 4
                                          : 0;
    if (len == 0 || static_cast<std::size_t>(end - p) < len) return 0;
    for (std::size_t i = 1; i < len; ++i)
        if ((static_cast<unsigned char>(p[i]) & 0xC0) != 0x80) return 0;
    return len;
}

/// Copies src into dst (capacity cap + NUL), escaping control bytes and invalid UTF-8 as
/// \xNN so a message can always be printed; truncates with "...".
void copyEscaped(char* dst, std::size_t cap, std::string_view src) {
    std::size_t out = 0;
    const char* p = src.data();
    const char* end = p + src.size();
    while (p < end) {
        std::size_t len = utf8Length(p, end);
        auto byte = static_cast<unsigned char>(*p);
        bool escape = len == 0 || (len == 1 && (byte < 0x20 || byte == 0x7F));
        std::size_t need = escape ? 4 : len;
        if (out + need > cap) {
            if (cap >= 3)
                std::memcpy(dst + std::min(out, cap - 3), "...", 3),
                    out = std::min(out, cap - 3) + 3;
            break;
        }
        if (escape) {
            static constexpr char kHex[] = "0123456789ABCDEF";
            dst[out++] = '\\';
            dst[out++] = 'x';
            dst[out++] = kHex[byte >> 4];
            dst[out++] = kHex[byte & 0xF];
            ++p;
        } else {
            std::memcpy(dst + out, p, len);
            out += len;
            p += len;
        }
    }
    dst[out] = '\0';
}

/// The largest block number, goto target or g/m code: what an int32 holds. Numbers are checked
/// against it before any conversion (a double above it does not convert to int).
constexpr double kMaxCode = 2147483647.0;

/// "g00", "m03", "g99999999999": the normalized name of a g or m word, for messages. g and m
/// carry at most kMaxNumberDigits digits and no sign, so the value converts to uint64 exactly.
std::string_view codeWord(char letter, double value, char (&buf)[32]) {
    buf[0] = letter;
    if (!(value >= 0.0 && value < 1e19)) return {buf, 1};
    auto v = static_cast<std::uint64_t>(value);
    if (v < 10) {
        buf[1] = '0';
        buf[2] = static_cast<char>('0' + v);
        return {buf, 3};
    }
    auto r = std::to_chars(buf + 1, buf + sizeof buf, v);
    return {buf, static_cast<std::size_t>(r.ptr - buf)};
}

/// A g or m code as an int, or -1 when it is no code at all (a fraction, or beyond any code).
int codeValue(const Word& w) {
    return w.integral && w.value >= 0.0 && w.value <= 999.0 ? static_cast<int>(w.value) : -1;
}

std::string_view formatNumber(double v, char (&buf)[32]) {
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return {buf, static_cast<std::size_t>(r.ptr - buf)};
}

class Compiler {
  public:
    Compiler(std::string_view source, const CompileOptions& options)
        : source_(source), options_(options) {
        program_.dialect = options.dialect;
    }

    Program run() {
        const char* p = source_.data();
        const char* end = p + source_.size();
        // A DOS end-of-file mark (^Z, 0x1A) closing the file is not part of the program.
        while (end > p && end[-1] == '\x1A')
            --end;
        // Reserve for the whole file at once: one block per line at most, so the vector never
        // doubles (a doubling would briefly hold 1.5x the blocks).
        std::size_t lines = static_cast<std::size_t>(std::count(p, end, '\n'));
        if (lines == 0) lines = static_cast<std::size_t>(std::count(p, end, '\r'));  // CR only
        program_.blocks.reserve(lines + 1);
        if (options_.machine.hasY) program_.y.reserve(lines + 1);
        if (end - p >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;  // UTF-8 BOM
        std::uint32_t lineNo = 0;
        const char* nl = nullptr;  // the next '\n' at or after p (end when none), found once
        while (p < end) {
            if (nl < p) {
                nl = static_cast<const char*>(
                    std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
                if (!nl) nl = end;
            }
            // LF, CRLF and a lone CR (old Mac files) each end a line. The CR search stops at
            // the first CR, so a CR-only file costs one pass like any other.
            const char* contentEnd = nl;
            const char* next = nl == end ? end : nl + 1;
            const char* cr =
                static_cast<const char*>(std::memchr(p, '\r', static_cast<std::size_t>(nl - p)));
            if (cr) {
                contentEnd = cr;
                if (cr + 1 != nl || nl == end) next = cr + 1;  // a lone CR
            }
            ++lineNo;
            compileLine(p, contentEnd, lineNo);
            p = next;
        }
        program_.lineCount = lineNo;
        finish(lineNo);
        return std::move(program_);
    }

  private:
    // ---- diagnostics -----------------------------------------------------------------------
    void report(MessageId id, std::uint32_t column, std::string_view text = {},
                double value = 0.0) {
        lineError_ = true;
        if (program_.diagnostics.size() >= keepLimit_) {
            ++program_.diagnosticsOmitted;
            return;
        }
        Diagnostic& d = program_.diagnostics.emplace_back();
        d.id = id;
        d.line = line_;
        d.column = column;
        d.n = lineN_;
        d.value = value;
        d.classic = options_.dialect == Dialect::Classic;
        copyEscaped(d.text, Diagnostic::kTextCapacity, text);
    }
    std::uint32_t col(const char* q) const {
        return static_cast<std::uint32_t>(q - lineBegin_ + 1);
    }
    /// The source from q up to the next blank, for naming an offending word.
    std::string_view wordAt(const char* q) const {
        const char* e = q;
        while (e < lineEnd_ && !isBlank(*e) && e - q < 20)
            ++e;
        if (e == q && q < lineEnd_) ++e;
        return {q, static_cast<std::size_t>(e - q)};
    }
    std::string_view charAt(const char* q) const {
        if (q >= lineEnd_) return {};
        std::size_t len = utf8Length(q, lineEnd_);
        return {q, len == 0 ? 1 : len};
    }

    /// Takes the line's block number; false (reported) when it is beyond any block number.
    bool acceptN(double value, std::uint32_t column) {
        if (value > kMaxCode) {
            report(MessageId::NTooLarge, column, wordAt(lineBegin_ + (column - 1)), kMaxCode);
            return false;
        }
        lineN_ = static_cast<std::int32_t>(value);
        if (lastN_ >= 0 && lineN_ <= lastN_) {
            char buf[32];
            // An out-of-order n does not hide the line's other errors: check the rest too.
            const bool hadError = lineError_;
            report(MessageId::NOrder, column, formatNumber(lastN_, buf), lastN_);
            lineError_ = hadError;
        } else {
            lastN_ = lineN_;
        }
        return true;
    }

    // ---- one line --------------------------------------------------------------------------
    void compileLine(const char* b, const char* e, std::uint32_t lineNo) {
        line_ = lineNo;
        lineN_ = -1;
        lineError_ = false;
        lineBegin_ = b;
        lineEnd_ = e;
        LineWords w;
        bool lexed = options_.dialect == Dialect::Classic ? lexClassic(w) : lexStandard(w);
        if (w.m.present)
            lastLineWasM02_ = w.m.value == 2.0;
        else if (lexed || lineError_)
            lastLineWasM02_ = false;
        if (lexed && !lineError_) validateAndCommit(w);
        // Block numbers of lines that produced no block still count as goto targets that exist.
        if (lineN_ >= 0 && lineError_) erroneousNs_.push_back(lineN_);
        if (lineN_ >= 0 && lineN_ <= previousN_) nSorted_ = false;
        if (lineN_ >= 0) previousN_ = lineN_;
    }

    /// Classic: n9999 g99 x9999 f999 m99, one space between words, lower case, fixed widths.
    /// Returns false when the line could not be lexed (a diagnostic was reported).
    bool lexClassic(LineWords& w) {
        const char* p = lineBegin_;
        const char* e = lineEnd_;
        if (p == e || *p != 'n') {
            report(MessageId::MissingN, 1, charAt(p));
            return false;
        }
        if (!fixedNumber(p, 4, false, w.n)) return false;
        acceptN(w.n.value, 1);
        p += 5;
        if (p == e) {
            report(MessageId::NAlone, col(p));
            return false;
        }
        int rank = 0;  // classic word order: g or m first, then x (y), then f
        while (p < e) {
            // The VB's Compilar_click (seed 000): a line that starts with x under a modal g00
            // must end after x (y); anything else is "Caracter inválido ou g00 não requer f",
            // even a second space (issue 22 item 3).
            const bool yNext = p + 1 < e && p[0] == ' ' && p[1] == 'y';
            if (!w.g.present && !w.m.present && w.x.present && !w.f.present && lastMotion_ == 0 &&
                !yNext) {
                report(MessageId::G00Feed, col(p));
                return false;
            }
            if (*p != ' ' || p + 1 == e || p[1] == ' ') {
                report(MessageId::SpaceRequired, col(*p == ' ' ? p + 1 : p),
                       charAt(*p == ' ' ? p + 1 : p));
                return false;
            }
            ++p;
            // The VB's "Não pode haver mais comandos após g00 / f": nothing follows a g00's x
            // (y), nor f.
            const bool afterG00 = w.g.present && w.g.value == 0 && (w.x.present || w.y.present);
            if ((afterG00 && *p != 'y') || w.f.present) {
                report(MessageId::TrailingWords, col(p), w.f.present ? "f" : "g00");
                return false;
            }
            Word* slot = nullptr;
            int width = 0, wordRank = 0;
            bool sign = false;
            switch (*p) {
                case 'g':
                    slot = &w.g, width = 2, wordRank = 1;
                    break;
                case 'x':
                    slot = &w.x, width = 4, wordRank = 2, sign = true;
                    break;
                case 'y':
                    if (!options_.machine.hasY) return unknownAxis(p);
                    slot = &w.y, width = 4, wordRank = 3, sign = true;
                    break;
                case 'f':
                    slot = &w.f, width = 3, wordRank = 4, sign = true;
                    break;
                case 'm':
                    slot = &w.m, width = 2, wordRank = 1;
                    break;
                default:
                    if (isAxisLetter(*p)) return unknownAxis(p);
                    report(MessageId::InvalidChar, col(p), charAt(p));
                    return false;
            }
            if (slot->present) {
                report(MessageId::RepeatedWord, col(p), charAt(p));
                return false;
            }
            if (wordRank < rank) {
                report(MessageId::InvalidChar, col(p), wordAt(p));
                return false;
            }
            rank = wordRank;
            if (!fixedNumber(p, width, sign, *slot)) return false;
            p = numberEnd_;
            // The VB set its modal g (ultimog) as soon as it read g00 or g01, before checking
            // the rest of the line: the lines after a faulty one are read as it read them.
            if (slot == &w.g && (slot->value == 0 || slot->value == 1))
                lastMotion_ = static_cast<int>(slot->value);
        }
        return true;
    }

    /// Reads the classic fixed-width number after the letter at p into slot.
    bool fixedNumber(const char* p, int width, bool sign, Word& slot) {
        const char* q = p + 1;
        bool negative = false;
        if (sign && q < lineEnd_ && *q == '-') negative = true, ++q;
        // The VB read f as three characters, so "f-10" is a (negative) f of width 3.
        if (negative && *p == 'f') --width;
        int digits = 0;
        int value = 0;
        while (q < lineEnd_ && isDigit(*q) && digits <= width)
            value = value * 10 + (*q - '0'), ++q, ++digits;
        if (digits != width) {
            report(MessageId::WrongDigitCount, col(p), wordAt(p), width);
            return false;
        }
        if (q < lineEnd_ && *q != ' ') {
            report(MessageId::SpaceRequired, col(q), charAt(q));
            return false;
        }
        slot.present = true;
        slot.value = negative ? -value : value;
        slot.column = col(p);
        numberEnd_ = q;
        return true;
    }

    static bool isAxisLetter(char c) {
        switch (lower(c)) {
            case 'y':
            case 'z':
            case 'a':
            case 'b':
            case 'c':
            case 'u':
            case 'v':
            case 'w':
            case 'i':
            case 'j':
            case 'k':
                return true;
            default:
                return false;
        }
    }
    bool unknownAxis(const char* p) {
        char letter[2] = {lower(*p), 0};
        report(MessageId::UnknownAxis, col(p), letter);
        return false;
    }

    /// Standard: any case, optional n first, decimals, comments, any blanks.
    bool lexStandard(LineWords& w) {
        const char* p = lineBegin_;
        const char* e = lineEnd_;
        while (p < e && isBlank(*p))
            ++p;
        if (p < e && *p == '%') return false;  // tape marks: ignored
        bool anyWord = false;
        const char* nEnd = p;
        while (true) {
            while (p < e && isBlank(*p))
                ++p;
            if (p == e) break;
            char c = *p;
            if (c == '(') {
                const void* close = std::memchr(p, ')', static_cast<std::size_t>(e - p));
                if (!close) {
                    report(MessageId::UnclosedComment, col(p), "(");
                    return false;
                }
                p = static_cast<const char*>(close) + 1;
                continue;
            }
            if (c == ';') break;
            if (!isAlpha(c)) {
                report(MessageId::InvalidChar, col(p), charAt(p));
                return false;
            }
            char letter = lower(c);
            Word* slot = nullptr;
            bool decimal = false;
            switch (letter) {
                case 'n':
                    slot = &w.n;
                    break;
                case 'g':
                    slot = &w.g;
                    break;
                case 'm':
                    slot = &w.m;
                    break;
                case 'x':
                    slot = &w.x, decimal = true;
                    break;
                case 'f':
                    slot = &w.f, decimal = true;
                    break;
                case 'y':
                    if (!options_.machine.hasY) return unknownAxis(p);
                    slot = &w.y, decimal = true;
                    break;
                default:
                    if (isAxisLetter(letter)) return unknownAxis(p);
                    report(MessageId::InvalidChar, col(p), charAt(p));
                    return false;
            }
            if (letter == 'n' && anyWord) {
                report(MessageId::NNotFirst, col(p), wordAt(p));
                return false;
            }
            if (slot->present) {
                if (letter == 'g' || letter == 'm') {
                    char buf[32];
                    report(MessageId::TrailingWords, col(p), codeWord(letter, slot->value, buf));
                } else {
                    report(MessageId::RepeatedWord, col(p), charAt(p));
                }
                return false;
            }
            DecimalScan s = scanDecimal(p + 1, e, decimal);
            bool signOk = decimal || (p + 1 < e && p[1] != '-' && p[1] != '+');
            if (s.intDigits + s.fracDigits > kMaxNumberDigits) {
                report(MessageId::NumberTooLong, col(p), wordAt(p), kMaxNumberDigits);
                return false;
            }
            const char* after = s.end;
            bool endsWell =
                after == e || isBlank(*after) || *after == '(' || *after == ';' || isAlpha(*after);
            if (s.ok && signOk && !endsWell && *after != '.' && !isDigit(*after) && *after != '-' &&
                *after != '+') {
                report(MessageId::InvalidChar, col(after), charAt(after));
                return false;
            }
            if (!s.ok || !signOk || !endsWell) {
                report(MessageId::MalformedNumber, col(p), wordAt(p));
                return false;
            }
            slot->present = true;
            slot->value = s.value;
            slot->column = col(p);
            slot->integral = s.fracDigits == 0 && !s.hasPoint;
            if (letter == 'n') {
                if (!acceptN(s.value, col(p))) return false;
                nEnd = after;
            }
            anyWord = true;
            p = after;
        }
        if (!anyWord) return false;  // blank or comment-only line: no block
        if (!w.any()) {
            report(MessageId::NAlone, col(nEnd));
            return false;
        }
        return true;
    }

    // ---- rules -----------------------------------------------------------------------------
    /// The first of the given words that is present (smallest column), or nullptr.
    static const Word* firstPresent(std::initializer_list<const Word*> words) {
        const Word* first = nullptr;
        for (const Word* w : words)
            if (w->present && (!first || w->column < first->column)) first = w;
        return first;
    }
    std::string_view wordText(const Word& w) const { return wordAt(lineBegin_ + (w.column - 1)); }
    bool noMoreThan(const LineWords& w, char letter, double code,
                    std::initializer_list<const Word*> extras) {
        if (const Word* extra = firstPresent(extras)) {
            char buf[32];
            report(MessageId::TrailingWords, extra->column, codeWord(letter, code, buf));
            return false;
        }
        (void)w;
        return true;
    }
    bool checkFeed(const Word& f) {
        if (!f.present) return true;
        char buf[32];
        if (f.value < 0) {
            report(MessageId::NegativeFeed, f.column, formatNumber(f.value, buf), f.value);
            return false;
        }
        // Below the slowest speed the rail runs, the feed would be logged as programmed but run
        // faster: refused, naming the real minimum.
        if (f.value < kMinFeedPercent || f.value > 100.0) {
            report(MessageId::FeedRange, f.column, formatNumber(f.value, buf), kMinFeedPercent);
            return false;
        }
        return true;
    }
    /// Positions, increments, offsets and times beyond kMaxValueMagnitude are refused: a double
    /// would round the typed decimals silently.
    bool withinMagnitude(const Word& v) {
        if (!v.present || std::fabs(v.value) <= kMaxValueMagnitude) return true;
        report(MessageId::ValueRange, v.column, wordText(v), kMaxValueMagnitude);
        return false;
    }

    void validateAndCommit(const LineWords& w) {
        Block b;
        b.n = lineN_;
        b.line = line_;
        double yTarget = prevY_;
        if (w.g.present && w.m.present) {
            char buf[32];
            report(MessageId::TrailingWords, std::max(w.g.column, w.m.column),
                   w.g.column < w.m.column ? codeWord('g', w.g.value, buf)
                                           : codeWord('m', w.m.value, buf));
            return;
        }
        if (w.g.present) {
            const int g = codeValue(w.g);
            char buf[32];
            switch (g) {
                case 0:
                case 1:
                    if (!w.x.present && !w.y.present) {
                        report(g == 0 ? MessageId::MissingXG00 : MessageId::MissingXG01, w.g.column,
                               wordText(w.g));
                        return;
                    }
                    if (!motion(g, w, b, yTarget)) return;
                    lastMotion_ = g;
                    break;
                case 4:
                    if (!w.x.present)
                        return (void)report(MessageId::MissingXG04, w.g.column, wordText(w.g));
                    if (!noMoreThan(w, 'g', 4, {&w.y, &w.f})) return;
                    if (!withinMagnitude(w.x)) return;
                    if (w.x.value < 0)
                        return (void)report(MessageId::NegativeDwell, w.x.column,
                                            formatNumber(w.x.value, buf), w.x.value);
                    b.op = Op::Dwell;
                    b.x = w.x.value;
                    break;
                case 90:
                case 91:
                case 93:
                    if (!noMoreThan(w, 'g', g, {&w.x, &w.y, &w.f})) return;
                    b.op = g == 90 ? Op::Absolute : g == 91 ? Op::Incremental : Op::ResetZero;
                    break;
                case 92:
                    if (!w.x.present)
                        return (void)report(MessageId::MissingXG92, w.g.column, wordText(w.g));
                    if (!noMoreThan(w, 'g', 92, {&w.f})) return;
                    if (!withinMagnitude(w.x) || !withinMagnitude(w.y)) return;
                    b.op = Op::SetZero;
                    b.x = w.x.value;
                    break;
                default:
                    report(MessageId::InvalidG, w.g.column, wordText(w.g), w.g.value);
                    return;
            }
            commit(b, w, yTarget);
            return;
        }
        if (w.m.present) {
            const int m = codeValue(w.m);
            char buf[32];
            switch (m) {
                case 0:
                case 2:
                    if (!noMoreThan(w, 'm', m, {&w.x, &w.y, &w.f})) return;
                    b.op = m == 0 ? Op::Stop : Op::End;
                    break;
                case 3:
                    if (!w.x.present)
                        return (void)report(MessageId::MissingXM03, w.m.column, wordText(w.m));
                    if (!noMoreThan(w, 'm', 3, {&w.y, &w.f})) return;
                    if (w.x.value < 0)
                        return (void)report(MessageId::NegativeGoto, w.x.column,
                                            formatNumber(w.x.value, buf), w.x.value);
                    if (!w.x.integral || w.x.value > kMaxCode)
                        return (void)report(MessageId::GotoNotInteger, w.x.column, wordText(w.x),
                                            w.x.value);
                    b.op = Op::Goto;
                    b.x = w.x.value;
                    gotos_.push_back(program_.blocks.size());
                    break;
                default:
                    report(MessageId::InvalidM, w.m.column, wordText(w.m), w.m.value);
                    return;
            }
            commit(b, w, yTarget);
            return;
        }
        if (w.x.present || w.y.present) {
            if (lastMotion_ < 0)
                return (void)report(MessageId::NoMotionMode, firstPresent({&w.x, &w.y})->column,
                                    wordText(*firstPresent({&w.x, &w.y})));
            if (!motion(lastMotion_, w, b, yTarget)) return;
            commit(b, w, yTarget);
            return;
        }
        // Only f: sets the modal feed.
        if (!checkFeed(w.f)) return;
        b.op = Op::Feed;
        b.feed = w.f.value;
        commit(b, w, yTarget);
    }

    /// A g00/g01 move (explicit or modal): feed rules, position resolution, soft limits.
    bool motion(int g, const LineWords& w, Block& b, double& yTarget) {
        if (g == 0) {
            if (w.f.present) return report(MessageId::G00Feed, w.f.column, wordText(w.f)), false;
            b.op = Op::Rapid;
            b.feed = 100.0;
        } else {
            if (!checkFeed(w.f)) return false;
            if (!w.f.present && !haveFeed_) {
                const Word& at = w.g.present ? w.g : *firstPresent({&w.x, &w.y});
                return report(MessageId::FeedUndefined, at.column, wordText(at)), false;
            }
            b.op = Op::Linear;
            b.feed = w.f.present ? w.f.value : feed_;
        }
        if (!withinMagnitude(w.x) || !withinMagnitude(w.y)) return false;
        // Documented meaning (gcode.md): absolute = x + zero; incremental = previous target + x.
        b.x = w.x.present ? (incremental_ ? prevX_ + w.x.value : w.x.value + zeroX_) : prevX_;
        if (w.y.present) yTarget = incremental_ ? prevY_ + w.y.value : w.y.value + zeroY_;
        if (!withinTravel('x', b.x, options_.machine.x, w.x.present ? w.x : *firstPresent({&w.y})))
            return false;
        if (options_.machine.hasY &&
            !withinTravel('y', yTarget, options_.machine.y, w.y.present ? w.y : w.x))
            return false;
        return true;
    }

    bool withinTravel(char axis, double target, const AxisTravel& travel, const Word& at) {
        if (target >= travel.softMinMm && target <= travel.softMaxMm) return true;
        char text[48] = {axis, '='};
        char num[32];
        auto v = formatNumber(target, num);
        std::memcpy(text + 2, v.data(), v.size());
        double bound = target < travel.softMinMm ? travel.softMinMm : travel.softMaxMm;
        report(MessageId::SoftLimit, at.column, std::string_view(text, v.size() + 2), bound);
        return false;
    }

    void commit(const Block& b, const LineWords& w, double yTarget) {
        switch (b.op) {
            case Op::Rapid:
            case Op::Linear:
                prevX_ = b.x;
                prevY_ = yTarget;
                if (b.op == Op::Linear) haveFeed_ = true, feed_ = b.feed;
                break;
            case Op::Feed:
                haveFeed_ = true, feed_ = b.feed;
                break;
            case Op::Absolute:
                incremental_ = false;
                break;
            case Op::Incremental:
                incremental_ = true;
                break;
            case Op::SetZero:
                zeroX_ = b.x;
                if (w.y.present) zeroY_ = w.y.value;
                break;
            case Op::ResetZero:
                zeroX_ = 0.0, zeroY_ = 0.0;
                break;
            default:
                break;
        }
        program_.blocks.push_back(b);
        if (options_.machine.hasY) program_.y.push_back(yTarget);
    }

    void finish(std::uint32_t lastLine) {
        line_ = std::max<std::uint32_t>(lastLine, 1);
        lineN_ = -1;
        std::sort(erroneousNs_.begin(), erroneousNs_.end());
        if (!gotos_.empty()) buildNIndex();
        // Goto diagnostics come after the pass but belong among its lines: keep up to as many
        // again, sort, then cut back to the first maxDiagnostics by line.
        const std::size_t passKept = program_.diagnostics.size();
        keepLimit_ = passKept + std::min(options_.maxDiagnostics, gotos_.size());
        for (std::size_t gi : gotos_) {
            Block& g = program_.blocks[gi];
            const std::int32_t target = g.targetN();
            g.targetIndex = indexOfN(target);
            if (g.targetIndex >= 0 ||
                std::binary_search(erroneousNs_.begin(), erroneousNs_.end(), target))
                continue;
            line_ = g.line;
            lineN_ = g.n;
            char buf[32];
            report(MessageId::GotoTarget, 0, formatNumber(g.targetN(), buf), g.targetN());
        }
        auto& diagnostics = program_.diagnostics;
        if (diagnostics.size() > passKept)
            std::stable_sort(
                diagnostics.begin(), diagnostics.end(),
                [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; });
        keepLimit_ = options_.maxDiagnostics;
        if (diagnostics.size() > keepLimit_) {
            program_.diagnosticsOmitted += diagnostics.size() - keepLimit_;
            diagnostics.resize(keepLimit_);
        }
        if (options_.stats) options_.stats->gotoSteps = steps_;
        line_ = std::max<std::uint32_t>(lastLine, 1);
        lineN_ = -1;
        if (!lastLineWasM02_) report(MessageId::MissingM02, 0);
    }

    std::string_view source_;
    const CompileOptions& options_;
    Program program_;

    // modal state, committed only by correct lines
    int lastMotion_ = -1;  ///< -1 before any g00/g01, then 0 or 1
    bool haveFeed_ = false;
    double feed_ = 0.0;         ///< percent
    bool incremental_ = false;  ///< g91 in force
    double zeroX_ = 0.0;        ///< mm from the rail centre (g92)
    double zeroY_ = 0.0;
    double prevX_ = 0.0;  ///< previous target, mm from the rail centre; starts at the centre
    double prevY_ = 0.0;
    std::int32_t lastN_ = -1;
    bool lastLineWasM02_ = false;

    // the line being compiled
    std::uint32_t line_ = 0;
    std::int32_t lineN_ = -1;
    bool lineError_ = false;
    const char* lineBegin_ = nullptr;
    const char* lineEnd_ = nullptr;
    const char* numberEnd_ = nullptr;

    /// The numbered blocks as (n, index), sorted by n then index, built once: every goto is
    /// then one binary search, whatever the mix of numbered and unnumbered blocks.
    void buildNIndex() {
        const auto& blocks = program_.blocks;
        for (std::size_t i = 0; i < blocks.size(); ++i)
            if (blocks[i].n >= 0) nIndex_.emplace_back(blocks[i].n, static_cast<std::int32_t>(i));
        steps_ += blocks.size();
        // Strictly increasing n (a correct program) is already sorted; otherwise the first block
        // with a given n is the target, as Program::indexOfN finds it.
        if (!nSorted_) std::sort(nIndex_.begin(), nIndex_.end());
    }
    /// Index of the first block numbered n, or -1.
    std::int32_t indexOfN(std::int32_t n) {
        std::size_t lo = 0, hi = nIndex_.size();
        while (lo < hi) {
            ++steps_;
            const std::size_t mid = lo + (hi - lo) / 2;
            if (nIndex_[mid].first < n)
                lo = mid + 1;
            else
                hi = mid;
        }
        return lo < nIndex_.size() && nIndex_[lo].first == n ? nIndex_[lo].second : -1;
    }

    std::vector<std::int32_t> erroneousNs_;  ///< block numbers of lines that had errors
    std::vector<std::size_t> gotos_;         ///< indices of goto blocks
    std::vector<std::pair<std::int32_t, std::int32_t>> nIndex_;  ///< see buildNIndex
    std::int32_t previousN_ = -1;
    bool nSorted_ = true;  ///< every n so far greater than the one before
    std::size_t keepLimit_ = options_.maxDiagnostics;  ///< diagnostics kept (report)
    std::size_t steps_ = 0;                            ///< CompileStats::gotoSteps
};

}  // namespace

Program compile(std::string_view source, const CompileOptions& options) {
    return Compiler(source, options).run();
}

std::size_t Program::blockAtOrAfterLine(std::uint32_t line) const {
    auto it = std::lower_bound(blocks.begin(), blocks.end(), line,
                               [](const Block& b, std::uint32_t l) { return b.line < l; });
    return static_cast<std::size_t>(it - blocks.begin());
}

int Program::indexOfN(std::int32_t n) const {
    for (std::size_t i = 0; i < blocks.size(); ++i)
        if (blocks[i].n == n) return static_cast<int>(i);
    return -1;
}

}  // namespace trilho
