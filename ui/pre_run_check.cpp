#include "ui/pre_run_check.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include "ui/background_pool.h"

namespace trilho {
namespace ui {

namespace {

/// Periods a check runs between looks at its cancel flag: about 2-5 ms of a core on the rail.
constexpr std::uint64_t kSlicePeriods = 8192;

struct Outcome {
    std::optional<ProgramCheck> check;
    std::string error;
};

Outcome runCheck(const MachineProfile& profile, std::shared_ptr<const Program> program,
                 const std::shared_ptr<const std::string>& source, const CompileOptions& options,
                 const ProgramCheckOptions& checkOptions, const std::atomic<bool>& cancel) {
    Outcome out;
    if (!program) program = std::make_shared<Program>(compile(*source, options));
    auto checker = ProgramChecker::make(profile, std::move(program), checkOptions, &out.error);
    if (!checker) return out;
    while (!checker->advance(kSlicePeriods))
        if (cancel.load(std::memory_order_relaxed)) return out;  // nobody reads it
    out.check = checker->result();
    return out;
}

}  // namespace

PreRunCheck::PreRunCheck(QObject* parent) : QObject(parent), rest_(new QTimer(this)) {
    rest_->setSingleShot(true);
    rest_->setInterval(kRestMs);
    connect(rest_, &QTimer::timeout, this, [this] {
        pending_.reset();
        if (!currentKey_) return;
        if (const std::optional<PreRunCheckKey> key = currentKey_()) startCheck_(*key);
    });
}

void PreRunCheck::setScreen(std::function<std::optional<PreRunCheckKey>()> currentKey,
                            std::function<void(const PreRunCheckKey&)> startCheck) {
    currentKey_ = std::move(currentKey);
    startCheck_ = std::move(startCheck);
}

void PreRunCheck::schedule() {
    const std::optional<PreRunCheckKey> key = currentKey_ ? currentKey_() : std::nullopt;
    if (!key) {
        pending_.reset();
        rest_->stop();
        if (key_) clear();
        return;
    }
    if (key_ == key || pending_ == key) return;
    pending_ = key;
    rest_->start();  // (re)started: the check waits until the changes rest
}

bool PreRunCheck::ready() const {
    const std::optional<PreRunCheckKey> key = currentKey_ ? currentKey_() : std::nullopt;
    if (!key) return false;
    const State state = stateFor(*key);
    return state == State::Done || state == State::Failed;
}

void PreRunCheck::startIfOther(const PreRunCheckKey& key) {
    if (key_ == key) return;
    rest_->stop();
    pending_.reset();
    startCheck_(key);
}

PreRunCheck::~PreRunCheck() {
    // The pool outlives the screens: the check under way ends at its next slice.
    if (cancel_) cancel_->store(true);
}

void PreRunCheck::start(const PreRunCheckKey& key, const MachineProfile& profile,
                        std::shared_ptr<const Program> program) {
    launch(key, profile, std::move(program), nullptr, {});
}

void PreRunCheck::start(const PreRunCheckKey& key, const MachineProfile& profile,
                        std::shared_ptr<const std::string> source, const CompileOptions& options) {
    launch(key, profile, nullptr, std::move(source), options);
}

void PreRunCheck::clear() {
    if (cancel_) cancel_->store(true);
    cancel_.reset();
    ++generation_;
    key_.reset();
    state_ = State::None;
    result_.reset();
    error_.clear();
}

void PreRunCheck::launch(const PreRunCheckKey& key, const MachineProfile& profile,
                         std::shared_ptr<const Program> program,
                         std::shared_ptr<const std::string> source, const CompileOptions& options) {
    if (key_ == key) return;  // under way or done
    clear();
    if (!program && !source) {
        key_ = key;
        state_ = State::Failed;
        error_ = QStringLiteral("no program to check");
        return;
    }
    key_ = key;
    state_ = State::Running;
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    const int generation = generation_;
    auto* watcher = new QFutureWatcher<Outcome>(this);
    connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher, generation] {
        watcher->deleteLater();
        if (generation != generation_) return;  // cancelled, or another program since
        Outcome out = watcher->future().takeResult();
        cancel_.reset();
        if (out.check) {
            result_ = std::move(out.check);
            state_ = State::Done;
        } else {
            error_ = QString::fromStdString(out.error);
            state_ = State::Failed;
        }
        emit finished();
    });
    watcher->setFuture(QtConcurrent::run(
        backgroundPool(), [profile, program = std::move(program), source = std::move(source),
                           options, checkOptions = key.options, cancel = cancel_] {
            return runCheck(profile, program, source, options, checkOptions, *cancel);
        }));
}

PreRunCheck::State PreRunCheck::stateFor(const PreRunCheckKey& key) const {
    return key_ == key ? state_ : State::None;
}

const ProgramCheck* PreRunCheck::resultFor(const PreRunCheckKey& key) const {
    return stateFor(key) == State::Done && result_ ? &*result_ : nullptr;
}

QString PreRunCheck::errorFor(const PreRunCheckKey& key) const {
    return stateFor(key) == State::Failed ? error_ : QString();
}

}  // namespace ui
}  // namespace trilho
