#pragma once
// The screens' own thread pool for long work (issue 30 item 3): reading and compiling programs,
// loading, measuring and saving runs, step tests and autotune, reading the history. Qt paints
// with its global pool (it splits large fills and image conversions across it and the screens'
// thread waits for the parts): a load of seconds queued there held a repaint, and with it the
// E-stop key, for as long as the load (1.5 s measured). Nothing of trilho's runs there. Its
// threads run at 10 above the screens' nice: they yield the core to the screens' thread.
class QThreadPool;

namespace trilho {
namespace ui {

QThreadPool* backgroundPool();

}  // namespace ui
}  // namespace trilho
