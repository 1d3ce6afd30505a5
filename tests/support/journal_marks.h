#pragma once
// The screens' start and stop marks in their journal (issue 30 item 7), as a test reads them:
// a start mark ("\tstart\t") naming the process once the screens are up, and a stop mark
// ("\tstop\t") as the last line once they closed cleanly. Each check answers what is wrong,
// empty when nothing is, so a test can say it with the journal's text.
#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QList>
#include <QString>

namespace trilho::test {

/// The journal's bytes; empty when it cannot be read.
inline QByteArray journalBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// The journal of screens just started: a start mark naming this process, no stop mark yet.
inline QString startMarkProblem(const QByteArray& journal) {
    const QString text = QString::fromUtf8(journal);
    if (!journal.contains("\tstart\t")) return QStringLiteral("no start mark in: ") + text;
    const QByteArray pid = "pid " + QByteArray::number(QCoreApplication::applicationPid());
    if (!journal.contains(pid))
        return QStringLiteral("the start mark does not name ") + QString::fromLatin1(pid) +
               QStringLiteral(": ") + text;
    if (journal.contains("\tstop\t")) return QStringLiteral("a stop mark already: ") + text;
    return {};
}

/// The journal of screens closed cleanly: its last line is the stop mark.
inline QString stopMarkProblem(const QByteArray& journal) {
    const QByteArray last = journal.trimmed().split('\n').last();
    if (!last.contains("\tstop\t"))
        return QStringLiteral("the last line is not the stop mark: ") + QString::fromUtf8(last);
    return {};
}

}  // namespace trilho::test
