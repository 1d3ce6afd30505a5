#include "core/timeline/events_file.h"

#include <QFile>
#include <QFileInfo>
#include <cmath>

#include "core/files/atomic_file.h"
#include "core/files/replace_target.h"

namespace trilho {

QString eventsPathFor(const QString& tracePath) {
    if (tracePath.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive))
        return tracePath.left(tracePath.size() - 4) + QStringLiteral(".events.csv");
    return tracePath + QStringLiteral(".events.csv");
}

QByteArray timelineToCsv(const Timeline& timeline) {
    QByteArray out(kEventsFileHeader);
    out += '\n';
    for (const TimelineMark& m : timeline.marks()) {
        QString text = m.text;
        text.replace(QLatin1Char('\r'), QLatin1Char(' '));
        text.replace(QLatin1Char('\n'), QLatin1Char(' '));
        text.replace(QLatin1Char('"'), QStringLiteral("\"\""));
        out += QByteArray::number(m.timeS, 'f', 4) + ',' + markKindName(m.kind) + ',' +
               QByteArray::number(m.code) + ',' +
               (m.line > 0 ? QByteArray::number(m.line) : QByteArray()) + ",\"" + text.toUtf8() +
               "\"\n";
    }
    return out;
}

bool writeEventsFile(const QString& path, const Timeline& timeline, QString* error) {
    if (const QString refused = refuseToReplace(path); !refused.isEmpty()) {
        if (error) *error = QStringLiteral("cannot write %1").arg(refused);
        return false;
    }
    return saveFileAtomically(path, timelineToCsv(timeline), error);
}

namespace {

/// One line's fields with the 1-based column each starts at.
struct Field {
    QByteArray bytes;
    qsizetype column = 1;
};

/// Splits a line at commas, RFC 4180 quotes allowed; false with *what and *column on a quote
/// left open or text after a closing quote.
bool splitFields(QByteArrayView line, std::vector<Field>& fields, QString* what,
                 qsizetype* column) {
    fields.clear();
    qsizetype i = 0;
    const qsizetype n = line.size();
    while (true) {
        Field f;
        f.column = i + 1;
        if (i < n && line[i] == '"') {
            ++i;
            while (true) {
                if (i >= n) {
                    *what = QStringLiteral("a quoted field is not closed on its line");
                    *column = f.column;
                    return false;
                }
                if (line[i] == '"') {
                    if (i + 1 < n && line[i + 1] == '"') {
                        f.bytes += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                f.bytes += line[i++];
            }
            if (i < n && line[i] != ',') {
                *what = QStringLiteral("text after a closing quote");
                *column = i + 1;
                return false;
            }
        } else {
            const qsizetype start = i;
            while (i < n && line[i] != ',') {
                if (line[i] == '"') {
                    *what = QStringLiteral("a quote inside an unquoted field");
                    *column = i + 1;
                    return false;
                }
                ++i;
            }
            f.bytes = line.sliced(start, i - start).toByteArray();
        }
        fields.push_back(std::move(f));
        if (i >= n) return true;
        ++i;  // the comma
        if (fields.size() > 5) {
            *what = QStringLiteral("more than the 5 columns of the header");
            *column = i;
            return false;
        }
    }
}

QString tooLarge(qint64 bytes) {
    return QStringLiteral("%1 bytes, more than an events file may hold (%2)")
        .arg(bytes)
        .arg(kMaxEventsFileBytes);
}

QString shown(const QByteArray& b) {
    constexpr qsizetype kShown = 40;
    QString s = QString::fromUtf8(b.left(kShown));
    if (b.size() > kShown) s += QStringLiteral("...");
    return s;
}

}  // namespace

TimelineLoad timelineFromCsv(const QByteArray& bytes, const QString& name) {
    TimelineLoad load;
    auto fail = [&](qsizetype line, qsizetype column, const QString& what) {
        load.error = QStringLiteral("%1:%2:%3: %4").arg(name).arg(line).arg(column).arg(what);
        load.timeline.reset();
        return load;
    };
    auto refuse = [&](const QString& what) {
        load.error = QStringLiteral("%1: %2").arg(name, what);
        return load;
    };
    if (bytes.size() > kMaxEventsFileBytes) return refuse(tooLarge(bytes.size()));
    Timeline t;
    qsizetype pos = 0, lineNo = 0;
    bool sawHeader = false;
    std::vector<Field> fields;
    double lastTime = 0.0;
    while (pos < bytes.size()) {
        qsizetype end = bytes.indexOf('\n', pos);
        const bool lastLine = end < 0;
        if (lastLine) end = bytes.size();
        ++lineNo;
        QByteArrayView line(bytes.constData() + pos, end - pos);
        pos = end + 1;
        if (line.endsWith('\r')) line.chop(1);
        if (line.size() > kMaxEventLine)
            return fail(lineNo, 1,
                        QStringLiteral("a line of %1 bytes, more than %2")
                            .arg(line.size())
                            .arg(kMaxEventLine));
        if (!sawHeader) {
            if (line != QByteArrayView(kEventsFileHeader))
                return fail(lineNo, 1,
                            QStringLiteral("expected the header '%1', found '%2'")
                                .arg(QLatin1String(kEventsFileHeader), shown(line.toByteArray())));
            sawHeader = true;
            continue;
        }
        if (line.isEmpty()) {
            if (lastLine) break;
            return fail(lineNo, 1, QStringLiteral("an empty line"));
        }
        QString what;
        qsizetype column = 1;
        if (!splitFields(line, fields, &what, &column)) return fail(lineNo, column, what);
        if (fields.size() != 5)
            return fail(lineNo, line.size() + 1,
                        QStringLiteral("%1 columns; the header has 5 (time_s, kind, code, line, "
                                       "text)")
                            .arg(fields.size()));
        if (t.size() == Timeline::kMaxMarks)
            return fail(lineNo, 1, QStringLiteral("more than %1 marks").arg(Timeline::kMaxMarks));
        TimelineMark m;
        bool ok = false;
        m.timeS = fields[0].bytes.toDouble(&ok);
        if (!ok || !std::isfinite(m.timeS) || m.timeS < 0.0 || m.timeS > 1e9)
            return fail(lineNo, fields[0].column,
                        QStringLiteral("time_s '%1' is not a number of seconds from 0 to 1e9")
                            .arg(shown(fields[0].bytes)));
        if (m.timeS < lastTime)
            return fail(lineNo, fields[0].column,
                        QStringLiteral("time_s %1 is before the mark above it (%2): the marks "
                                       "are in time order")
                            .arg(shown(fields[0].bytes))
                            .arg(lastTime));
        lastTime = m.timeS;
        const std::optional<MarkKind> kind = markKindFromName(QString::fromUtf8(fields[1].bytes));
        if (!kind)
            return fail(lineNo, fields[1].column,
                        QStringLiteral("kind '%1' is none of start, end, alarm, warning, ack, "
                                       "hold, resume, stop, override, mode, dnc_write")
                            .arg(shown(fields[1].bytes)));
        m.kind = *kind;
        m.code = fields[2].bytes.toInt(&ok);
        if (!ok || m.code < 0 || m.code > 9999)
            return fail(lineNo, fields[2].column,
                        QStringLiteral("code '%1' is not a whole number from 0 to 9999")
                            .arg(shown(fields[2].bytes)));
        if (!fields[3].bytes.isEmpty()) {
            const qlonglong l = fields[3].bytes.toLongLong(&ok);
            if (!ok || l < 1 || l > 100000000)
                return fail(lineNo, fields[3].column,
                            QStringLiteral("line '%1' is not a line number from 1 to 100000000 "
                                           "(empty: none)")
                                .arg(shown(fields[3].bytes)));
            m.line = static_cast<std::uint32_t>(l);
        }
        m.text = QString::fromUtf8(fields[4].bytes);
        t.add(std::move(m));
    }
    if (!sawHeader) return refuse(QStringLiteral("empty: no header"));
    load.timeline = std::move(t);
    return load;
}

TimelineLoad readEventsFile(const QString& path) {
    TimelineLoad load;
    auto refuse = [&](const QString& what) {
        load.error = QStringLiteral("%1: %2").arg(path, what);
        return load;
    };
    QFile f(path);
    const QFileInfo info(path);
    // A FIFO or a device could block or never end: an events file is a regular file.
    if (info.exists() && !info.isFile()) return refuse(QStringLiteral("not a regular file"));
    if (!f.open(QIODevice::ReadOnly))
        return refuse(QStringLiteral("cannot read: %1").arg(f.errorString()));
    if (f.size() > kMaxEventsFileBytes) return refuse(tooLarge(f.size()));
    return timelineFromCsv(f.read(kMaxEventsFileBytes + 1), path);
}

}  // namespace trilho
