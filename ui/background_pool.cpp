#include "ui/background_pool.h"

#include <QSemaphore>
#include <QThreadPool>

#include <algorithm>
#include <cerrno>
#include <memory>

#include <sys/resource.h>
#include <unistd.h>

namespace trilho {
namespace ui {

namespace {

/// The pool's threads' nice above the screens' own: they yield to the screens' thread (and to
/// the machine's), so a load of seconds never takes the core the E-stop key needs. The pool's
/// share stays: nice +10 against the screens is about a tenth of a busy core's time, all of it
/// when the core is idle.
constexpr int kBackgroundNice = 10;

QThreadPool* makePool() {
    auto* pool = new QThreadPool;  // lives as long as the process: tasks may still run at exit
    // Its threads are made once and kept (never expire), each lowered once: Linux keeps the
    // nice value per thread, and QThreadPool has no hook where a new thread starts.
    pool->setExpiryTimeout(-1);
    const int threads = pool->maxThreadCount();
    struct Gate {
        QSemaphore started, go;
    };
    // Shared: a task may still be leaving go.acquire() when this function has returned.
    const auto gate = std::make_shared<Gate>();
    for (int i = 0; i < threads; ++i)
        pool->start([gate] {
            // Above the screens' own (a trilho started with nice 5 keeps the difference).
            const auto self = static_cast<id_t>(gettid());
            errno = 0;
            const int inherited = getpriority(PRIO_PROCESS, self);
            if (errno == 0)
                setpriority(PRIO_PROCESS, self, std::min(inherited + kBackgroundNice, 19));
            gate->started.release();
            gate->go.acquire();  // holds this thread until every thread has started (one each)
        });
    gate->started.acquire(threads);
    gate->go.release(threads);
    return pool;
}

}  // namespace

QThreadPool* backgroundPool() {
    static QThreadPool* const pool = makePool();
    return pool;
}

}  // namespace ui
}  // namespace trilho
