#pragma once
// What the workbench's widget tests share: waiting for a run the window started (virtual time,
// on its worker), and the JSON `trilho-cli` prints for the same test, to compare the screens'
// numbers with the CLI's.
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QStringList>

#include "ui/workbench/workbench_window.h"

namespace trilho::test {

/// True once the window says its run finished, within 60 s.
inline bool waitRun(ui::WorkbenchWindow& w) {
    QSignalSpy done(&w, &ui::WorkbenchWindow::runFinished);
    return done.wait(60000);
}

/// `cli args...`'s standard output as one JSON object; empty when it did not finish in 60 s or
/// printed none.
inline QJsonObject cliJson(const QString& cli, const QStringList& args) {
    QProcess p;
    p.start(cli, args);
    if (!p.waitForFinished(60000)) return {};
    return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
}

}  // namespace trilho::test
