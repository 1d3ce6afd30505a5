#pragma once
// Finds a key given twice in one JSON object (issue 20 item 14). QJsonDocument keeps one of two
// equal keys and drops the other without a word, so a profile saying "kp" twice would run with
// whichever it kept; the strict reader refuses it. This is a scan of the raw text of its own:
// it follows objects, arrays and strings (with their escapes: "\u006bp" is the key "kp"), and
// compares keys as any JSON reader does, after the escapes, letter case kept.
#include <QByteArray>
#include <QString>
#include <optional>

namespace trilho {

/// A place in the text: line and column, both from 1; the column counts characters (UTF-8
/// code points), so an editor's column agrees.
struct TextPlace {
    int line = 1;
    int column = 1;
};

struct DuplicateKey {
    QString path;             ///< "loop.kp"; an array element is "[i]": "source[1].b"
    TextPlace first, second;  ///< where each occurrence's opening quote is
};

/// The first key (in text order of the second occurrence) that an object gives twice; nullopt
/// when none. Meant for text QJsonDocument already accepted; any other bytes are scanned
/// without harm (no recursion, linear time) and give some answer.
std::optional<DuplicateKey> findDuplicateKey(const QByteArray& json);

/// The strict readers' error for dup in the file named origin: "rail.json: loop.kp: the key is
/// given twice, at 3:5 and 4:5 (a profile says each key once)"; kind names what the file is
/// ("a profile", "a sidecar").
QString duplicateKeyError(const QString& origin, const DuplicateKey& dup, const QString& kind);

}  // namespace trilho
