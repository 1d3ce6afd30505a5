#include "core/profile/json_duplicate_keys.h"

#include <QHash>
#include <vector>

namespace trilho {

namespace {

/// One open object or array. An object remembers its keys and where each was; an array counts
/// its elements (for the path).
struct Frame {
    bool object = true;
    QString path;
    QHash<QString, TextPlace> keys;
    bool expectKey = true;  ///< object: the next string is a key (after '{' or ',')
    QString lastKey;        ///< object: the key whose value comes next
    int index = 0;          ///< array: the element being read
};

/// Walks the bytes, keeping the line and column of the next one.
class Cursor {
  public:
    explicit Cursor(const QByteArray& text) : text_(text) {}
    bool done() const { return pos_ >= text_.size(); }
    char peek() const { return text_.at(pos_); }
    TextPlace place() const { return place_; }
    char take() {
        const char c = text_.at(pos_++);
        if (c == '\n') {
            ++place_.line;
            place_.column = 1;
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
            ++place_.column;  // a UTF-8 continuation byte is not a new character
        }
        return c;
    }

  private:
    const QByteArray& text_;
    qsizetype pos_ = 0;
    TextPlace place_;
};

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/// Four hex digits after "\u"; -1 when they are not.
int readHex4(Cursor& in) {
    int v = 0;
    for (int i = 0; i < 4; ++i) {
        if (in.done()) return -1;
        const int d = hexDigit(in.peek());
        if (d < 0) return -1;
        in.take();
        v = v * 16 + d;
    }
    return v;
}

/// The string whose opening quote was just taken, decoded as a JSON reader does.
QString readString(Cursor& in) {
    QByteArray utf8;  // plain bytes, decoded once at the end
    QString decoded;
    auto flush = [&] {
        decoded += QString::fromUtf8(utf8);
        utf8.clear();
    };
    while (!in.done()) {
        const char c = in.take();
        if (c == '"') break;
        if (c != '\\') {
            utf8.append(c);
            continue;
        }
        if (in.done()) break;
        const char e = in.take();
        switch (e) {
            case 'b':
                utf8.append('\b');
                break;
            case 'f':
                utf8.append('\f');
                break;
            case 'n':
                utf8.append('\n');
                break;
            case 'r':
                utf8.append('\r');
                break;
            case 't':
                utf8.append('\t');
                break;
            case 'u': {
                const int unit = readHex4(in);
                if (unit < 0) break;
                flush();
                decoded += QChar(static_cast<char16_t>(unit));  // a surrogate pairs with the next
                break;
            }
            default:
                utf8.append(e);
                break;  // \" \\ \/ (and anything else, kept as it is)
        }
    }
    flush();
    return decoded;
}

QString childPath(const Frame& parent) {
    if (!parent.object) return QStringLiteral("%1[%2]").arg(parent.path).arg(parent.index);
    return parent.path.isEmpty() ? parent.lastKey : parent.path + QLatin1Char('.') + parent.lastKey;
}

}  // namespace

std::optional<DuplicateKey> findDuplicateKey(const QByteArray& json) {
    Cursor in(json);
    std::vector<Frame> stack;
    while (!in.done()) {
        const TextPlace at = in.place();
        const char c = in.take();
        switch (c) {
            case '{':
            case '[': {
                Frame f;
                f.object = c == '{';
                if (!stack.empty()) f.path = childPath(stack.back());
                stack.push_back(std::move(f));
                break;
            }
            case '}':
            case ']':
                if (!stack.empty()) stack.pop_back();
                break;
            case ',':
                if (!stack.empty()) {
                    if (stack.back().object)
                        stack.back().expectKey = true;
                    else
                        ++stack.back().index;
                }
                break;
            case ':':
                if (!stack.empty()) stack.back().expectKey = false;
                break;
            case '"': {
                const QString s = readString(in);
                if (stack.empty() || !stack.back().object || !stack.back().expectKey) break;
                Frame& f = stack.back();
                f.expectKey = false;
                f.lastKey = s;
                const auto seen = f.keys.constFind(s);
                if (seen != f.keys.constEnd()) return DuplicateKey{childPath(f), *seen, at};
                f.keys.insert(s, at);
                break;
            }
            default:
                break;  // white space, numbers, true, false, null
        }
    }
    return std::nullopt;
}

QString duplicateKeyError(const QString& origin, const DuplicateKey& dup, const QString& kind) {
    return (QStringLiteral("%1: %2: the key is given twice, at %3:%4 and %5:%6 (") + kind +
            QStringLiteral(" says each key once)"))
        .arg(origin, dup.path)
        .arg(dup.first.line)
        .arg(dup.first.column)
        .arg(dup.second.line)
        .arg(dup.second.column);
}

}  // namespace trilho
