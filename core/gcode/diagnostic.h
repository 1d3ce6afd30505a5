#pragma once
// A compile diagnostic: a stable code (gcode.md), the place, and the values its message names.
// Messages are produced in the UI language by diagnostic_text.h; this struct holds no text
// beyond the offending source fragment, so a million diagnostics stay small.
#include <cstdint>
#include <string_view>

namespace trilho {

enum class Severity : std::uint8_t { Error, Warning };

/// One message per distinct original text; several messages share a stable code.
enum class MessageId : std::uint8_t {
    MissingN,
    NOrder,
    NAlone,
    SpaceRequired,
    TrailingWords,
    MissingXG00,
    MissingXG01,
    MissingXG04,
    MissingXG92,
    MissingXM03,
    NegativeDwell,
    NegativeGoto,
    NegativeFeed,
    InvalidG,
    InvalidM,
    NoMotionMode,
    FeedUndefined,
    G00Feed,
    InvalidChar,
    MalformedNumber,
    WrongDigitCount,
    UnclosedComment,
    RepeatedWord,
    NNotFirst,
    GotoNotInteger,
    NumberTooLong,
    MissingM02,
    GotoTarget,
    FeedRange,
    SoftLimit,
    UnknownAxis,
    NTooLarge,
    ValueRange,
    Count_
};

constexpr int kMessageCount = static_cast<int>(MessageId::Count_);

/// The stable code of a message (gcode.md "Diagnostics"); the DNC link and tests rely on it.
constexpr std::string_view diagnosticCode(MessageId id) {
    switch (id) {
        case MessageId::MissingN:
            return "missing-n";
        case MessageId::NOrder:
            return "n-order";
        case MessageId::NAlone:
            return "n-alone";
        case MessageId::SpaceRequired:
            return "space-required";
        case MessageId::TrailingWords:
            return "trailing-words";
        case MessageId::MissingXG00:
        case MessageId::MissingXG01:
        case MessageId::MissingXG04:
        case MessageId::MissingXG92:
        case MessageId::MissingXM03:
            return "missing-x";
        case MessageId::NegativeDwell:
        case MessageId::NegativeGoto:
        case MessageId::NegativeFeed:
            return "negative-value";
        case MessageId::InvalidG:
            return "invalid-g";
        case MessageId::InvalidM:
            return "invalid-m";
        case MessageId::NoMotionMode:
            return "no-motion-mode";
        case MessageId::FeedUndefined:
            return "feed-undefined";
        case MessageId::G00Feed:
            return "g00-feed";
        case MessageId::InvalidChar:
        case MessageId::MalformedNumber:
        case MessageId::WrongDigitCount:
        case MessageId::UnclosedComment:
        case MessageId::RepeatedWord:
        case MessageId::NNotFirst:
        case MessageId::GotoNotInteger:
        case MessageId::NumberTooLong:
            return "invalid-char";
        case MessageId::MissingM02:
            return "missing-m02";
        case MessageId::GotoTarget:
            return "goto-target";
        case MessageId::FeedRange:
            return "feed-range";
        case MessageId::SoftLimit:
            return "soft-limit";
        case MessageId::UnknownAxis:
            return "unknown-axis";
        case MessageId::NTooLarge:
            return "n-range";
        case MessageId::ValueRange:
            return "value-range";
        case MessageId::Count_:
            break;
    }
    return "?";
}

struct Diagnostic {
    static constexpr std::size_t kTextCapacity = 23;

    MessageId id = MessageId::InvalidChar;
    Severity severity = Severity::Error;
    std::uint32_t line = 0;    ///< 1-based source line
    std::uint32_t column = 0;  ///< 1-based byte column, 0 when the message has no column
    std::int32_t n = -1;       ///< block number of the line, -1 when unknown
    double value = 0.0;        ///< a numeric value the message names (a limit, a previous n)
    bool classic = false;      ///< compiled in the classic dialect: the place is said as the VB did
    char text[kTextCapacity + 1] = {};  ///< offending source text, escaped, NUL-terminated

    std::string_view code() const { return diagnosticCode(id); }
    std::string_view textView() const { return std::string_view(text); }
};

}  // namespace trilho
