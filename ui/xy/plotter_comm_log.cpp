#include "ui/xy/plotter_comm_log.h"

#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include "ui/fixed_font.h"

namespace trilho {
namespace ui {

namespace {
QString bytesText(const std::uint8_t* b, std::size_t n) {
    QStringList parts;
    for (std::size_t i = 0; i < n; ++i)
        parts << QString::number(static_cast<std::int8_t>(b[i]));  // Java's signed byte
    return QStringLiteral("[%1]").arg(parts.join(QStringLiteral(", ")));
}
}  // namespace

QString packetText(const plotter_wire::Packet& p) {
    const std::string_view name =
        plotter_wire::isCommand(p[0])
            ? plotter_wire::commandName(static_cast<plotter_wire::Command>(p[0]))
            : std::string_view("?");
    return QStringLiteral("%1 %2").arg(
        QString::fromLatin1(name.data(), static_cast<qsizetype>(name.size())),
        bytesText(p.data(), p.size()));
}

QString answerText(std::uint8_t answer, std::uint8_t commandInFlight) {
    using plotter_wire::Command;
    using plotter_wire::Reply;
    QString name = QStringLiteral("?");
    switch (answer) {
        case static_cast<std::uint8_t>(Reply::RequestOk):
            name = QStringLiteral("REQUEST_OK");
            break;
        case static_cast<std::uint8_t>(Reply::Resend):
            name = QStringLiteral("RESEND");
            break;
        case static_cast<std::uint8_t>(Reply::Next):
            name = QStringLiteral("NEXT");
            break;
        case static_cast<std::uint8_t>(Reply::Done):
            name = QStringLiteral("DONE");
            break;
        case static_cast<std::uint8_t>(Reply::OriginOk):
            name = QStringLiteral("ORIGIN_OK");
            break;
        case static_cast<std::uint8_t>(Reply::SpeedOk):
            name = QStringLiteral("SPEED_OK");
            break;
        default:
            // A jog answers with its own byte when done.
            if (plotter_wire::isCommand(answer) && answer == commandInFlight) {
                const std::string_view n = plotter_wire::commandName(static_cast<Command>(answer));
                name = QString::fromLatin1(n.data(), static_cast<qsizetype>(n.size()));
            }
            break;
    }
    return QStringLiteral("%1 %2").arg(name, bytesText(&answer, 1));
}

PlotterCommLog::PlotterCommLog(QWidget* parent) : QWidget(parent) {
    view_ = new QPlainTextEdit(this);
    view_->setObjectName(QStringLiteral("plotterCommLogText"));
    view_->setReadOnly(true);
    view_->setMaximumBlockCount(kMaxLines);
    view_->setLineWrapMode(QPlainTextEdit::NoWrap);
    view_->setFont(fixedFont());
    clear_ = new QPushButton(this);
    clear_->setObjectName(QStringLiteral("plotterCommLogClear"));
    lastObject_ = new QLabel(this);
    auto* top = new QHBoxLayout;
    top->addWidget(clear_);
    top->addWidget(lastObject_, 1);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(2, 2, 2, 2);
    v->addLayout(top);
    v->addWidget(view_, 1);
    connect(clear_, &QPushButton::clicked, this, &PlotterCommLog::clear);
    retranslate();
}

void PlotterCommLog::addEntry(const PlotterLogEntry& e) {
    const QString at = QStringLiteral("%1 s").arg(e.timeS, 9, 'f', 3);
    if (e.sent) {
        if (!pendingSent_.isEmpty()) view_->appendPlainText(pendingSent_);  // no answer came
        if (e.objectStart) {
            view_->appendPlainText(QStringLiteral("====="));
            view_->appendPlainText(tr("Sending object %1").arg(e.object));
            view_->appendPlainText(QStringLiteral("-----"));
        }
        pendingSent_ =
            QStringLiteral("%1  %2").arg(at, tr("Sending: %1").arg(packetText(e.packet)));
        return;
    }
    const QString received = tr("Received: %1").arg(answerText(e.answer, e.answeredCommand));
    if (!pendingSent_.isEmpty()) {
        view_->appendPlainText(
            QStringLiteral("%1   %2").arg(pendingSent_.leftJustified(56), received));
        pendingSent_.clear();
    } else {
        view_->appendPlainText(QStringLiteral("%1  %2").arg(at, received));
    }
    if (e.objectEnd) {
        lastObjectS_ = e.objectSeconds;
        view_->appendPlainText(tr("Time: %1 s").arg(e.objectSeconds, 0, 'f', 3));
        retranslate();
    }
}

void PlotterCommLog::clear() {
    view_->clear();
    pendingSent_.clear();
    lastObjectS_ = -1.0;
    retranslate();
}

QString PlotterCommLog::text() const {
    return view_->toPlainText();
}

int PlotterCommLog::lines() const {
    return view_->document()->isEmpty() ? 0 : view_->blockCount();
}

void PlotterCommLog::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(e);
}

void PlotterCommLog::retranslate() {
    if (auto* dock = qobject_cast<QDockWidget*>(parentWidget()))
        dock->setWindowTitle(tr("Communication log"));
    clear_->setText(tr("Clear log"));
    lastObject_->setText(lastObjectS_ < 0.0 ? tr("No object sent yet")
                                            : tr("Last object: %1 s").arg(lastObjectS_, 0, 'f', 3));
}

}  // namespace ui
}  // namespace trilho
