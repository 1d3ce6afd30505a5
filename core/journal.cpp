#include "core/journal.h"

#include <unistd.h>
#include <QSaveFile>

namespace trilho {

namespace {
QString clean(QString s) {
    s.replace(QLatin1Char('\t'), QLatin1Char(' '));
    s.replace(QLatin1Char('\n'), QLatin1Char(' '));
    s.replace(QLatin1Char('\r'), QLatin1Char(' '));
    return s;
}
QString csvField(const QString& s) {
    QString q = s;
    q.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}
}  // namespace

bool Journal::open(const QString& path, QString* error) {
    file_.setFileName(path);
    if (!file_.open(QIODevice::Append | QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        if (error)
            *error = QStringLiteral("cannot open journal '%1': %2").arg(path, file_.errorString());
        return false;
    }
    return true;
}

bool Journal::append(const JournalEntry& e) {
    if (!file_.isOpen()) return false;
    const QByteArray line = (e.when.toUTC().toString(Qt::ISODateWithMs) + QLatin1Char('\t') +
                             clean(e.kind) + QLatin1Char('\t') + QString::number(e.code) +
                             QLatin1Char('\t') + clean(e.text) + QLatin1Char('\n'))
                                .toUtf8();
    // Unbuffered: one write() per entry, in the kernel's hands as soon as it returns.
    const bool ok = file_.write(line) == line.size();
    ::fdatasync(file_.handle());
    return ok;
}

QList<JournalEntry> Journal::read(const QString& path) {
    QList<JournalEntry> entries;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return entries;
    const QByteArray all = f.readAll();
    const QList<QByteArray> lines = all.split('\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (i == lines.size() - 1) break;  // after the last '\n': empty or torn
        const QList<QByteArray> fields = lines[i].split('\t');
        if (fields.size() != 4) continue;
        JournalEntry e;
        e.when = QDateTime::fromString(QString::fromUtf8(fields[0]), Qt::ISODateWithMs);
        if (!e.when.isValid()) continue;
        e.kind = QString::fromUtf8(fields[1]);
        bool ok = false;
        e.code = fields[2].toInt(&ok);
        if (!ok) continue;
        e.text = QString::fromUtf8(fields[3]);
        entries.append(e);
    }
    return entries;
}

bool Journal::exportCsv(const QList<JournalEntry>& entries, const QString& path, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error) *error = QStringLiteral("cannot write '%1': %2").arg(path, f.errorString());
        return false;
    }
    QByteArray out = "time_utc,kind,code,text\r\n";
    for (const JournalEntry& e : entries) {
        out += (csvField(e.when.toUTC().toString(Qt::ISODateWithMs)) + QLatin1Char(',') +
                csvField(e.kind) + QLatin1Char(',') + QString::number(e.code) + QLatin1Char(',') +
                csvField(e.text) + QStringLiteral("\r\n"))
                   .toUtf8();
    }
    f.write(out);
    if (!f.commit()) {
        if (error) *error = QStringLiteral("cannot write '%1': %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

}  // namespace trilho
