#include "app/device/host_open_watch.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <QSocketNotifier>
#include <cerrno>
#include <cstring>

namespace trilho {

HostOpenWatch::HostOpenWatch(QString path, std::function<void()> opened, QObject* parent)
    : QObject(parent), path_(std::move(path)), opened_(std::move(opened)) {}

HostOpenWatch::~HostOpenWatch() {
    if (fd_ >= 0) ::close(fd_);
}

bool HostOpenWatch::start(QString* error) {
    fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd_ < 0 || ::inotify_add_watch(fd_, path_.toLocal8Bit().constData(), IN_OPEN) < 0) {
        if (error)
            *error = QStringLiteral("cannot watch %1 for a host: %2")
                         .arg(path_, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    notifier_ = new QSocketNotifier(fd_, QSocketNotifier::Read, this);
    connect(notifier_, &QSocketNotifier::activated, this, &HostOpenWatch::readEvents);
    return true;
}

void HostOpenWatch::readEvents() {
    // Drain the events (each at least sizeof(inotify_event)); any of them is an open.
    alignas(inotify_event) char buf[4096];
    bool any = false;
    while (::read(fd_, buf, sizeof buf) > 0)
        any = true;
    if (!any || fired_) return;
    fired_ = true;
    notifier_->setEnabled(false);
    opened_();
}

}  // namespace trilho
