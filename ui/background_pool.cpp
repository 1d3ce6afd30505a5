#include "ui/background_pool.h"

#include <QThreadPool>

namespace trilho {
namespace ui {

namespace {
Q_GLOBAL_STATIC(QThreadPool, pool)
}  // namespace

QThreadPool* backgroundPool() {
    return pool();
}

}  // namespace ui
}  // namespace trilho
