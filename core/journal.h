#pragma once
// The persistent alarm and status history: an append-only file of one tab-separated line per
// entry, written with a single write() each, so a killed program loses at most the entry being
// written and never earlier ones; a torn last line is skipped on reading. Exports to CSV.
#include <QDateTime>
#include <QFile>
#include <QList>
#include <QString>

namespace trilho {

struct JournalEntry {
    QDateTime when;  ///< UTC
    QString kind;    ///< "status", "alarm", "ack"
    int code = 0;    ///< alarm code, 0 for status lines
    QString text;
};

class Journal {
  public:
    /// Opens (creating) the journal for appending. Returns false with a message otherwise.
    bool open(const QString& path, QString* error = nullptr);
    bool isOpen() const { return file_.isOpen(); }
    QString path() const { return file_.fileName(); }
    bool append(const JournalEntry& entry);

    /// Reads a journal; lines that are not complete entries (a torn last line) are skipped.
    static QList<JournalEntry> read(const QString& path);
    /// Writes entries as CSV (RFC 4180: quoted fields), atomically.
    static bool exportCsv(const QList<JournalEntry>& entries, const QString& path,
                          QString* error = nullptr);

  private:
    QFile file_;
};

}  // namespace trilho
