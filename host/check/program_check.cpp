#include "host/check/program_check.h"

#include <algorithm>
#include <cmath>

#include "core/machine/event_text.h"
#include "core/xy/xy_event_text.h"
#include "host/session/run_end.h"
#include "host/session/sim_session.h"
#include "host/session/xy_session.h"

namespace trilho {

namespace {

/// What the check reads after each period: the end rules' fields (RunEnd::check) and the axes.
struct Reading {
    ControllerState state = ControllerState::Manual;
    PauseReason pause = PauseReason::None;
    bool programFinished = false;
    bool heldByController = false;
    double timeS = 0.0;
    std::uint32_t blockLine = 0;
    std::array<double, 2> setpointMm{};
    std::array<double, 2> measuredMm{};
    std::array<bool, 2> saturated{};
};

/// What every controller's status says alike (ControllerStatus, XyStatus): the axes apart.
template <typename Status>
Reading commonReading(const Status& s) {
    Reading r;
    r.state = s.state;
    r.pause = s.pause;
    r.programFinished = s.programFinished;
    r.heldByController = s.heldByController;
    r.timeS = s.timeS;
    r.blockLine = s.blockLine;
    return r;
}

/// A controller and its simulated plant, started: Automatic (homing), the program loaded and
/// started after homing, as `trilho-cli run` starts them.
class Machine {
  public:
    virtual ~Machine() = default;
    /// One nominal period: the controller ticks, then the plant runs it.
    virtual void step() = 0;
    virtual Reading read() = 0;
    virtual void pressContinue() = 0;
    /// The events since the last call, in order, into `into` (cleared first).
    virtual void drain(std::vector<ControllerEvent>& into) = 0;
    virtual QString alarmText(AlarmCode code, double value) const = 0;
    /// The plant's true speed on an axis, mm/s (the coast after an alarm).
    virtual double plantSpeedMmS(int axis) = 0;
    virtual double periodS() = 0;
    virtual int axes() const = 0;
    virtual bool saturationModelled() const = 0;
};

class RailMachine final : public Machine {
  public:
    RailMachine(const MachineProfile& profile, std::shared_ptr<const Program> program,
                std::uint64_t seed, double feedOverride, bool* loaded)
        : session_(profile, seed) {
        RailController& c = session_.controller();
        c.setFeedOverride(feedOverride);
        c.selectAutomatic();
        *loaded = c.loadProgram(std::move(program));
        c.start(0);  // after homing
    }
    void step() override { session_.step(); }
    Reading read() override {
        const ControllerStatus& s = session_.controller().status();
        Reading r = commonReading(s);
        r.setpointMm[0] = s.servo.setpointMm;
        r.measuredMm[0] = s.servo.positionMm;
        r.saturated[0] = s.servo.loop.saturated;
        return r;
    }
    void pressContinue() override { session_.controller().pressContinue(); }
    void drain(std::vector<ControllerEvent>& into) override {
        into.clear();
        session_.controller().drainEvents([&](const ControllerEvent& e) { into.push_back(e); });
    }
    QString alarmText(AlarmCode code, double value) const override {
        return trilho::alarmText(code, value);
    }
    double plantSpeedMmS(int) override { return session_.rail().state().velocityMmS; }
    double periodS() override { return session_.controller().profile().loop.samplePeriodS; }
    int axes() const override { return 1; }
    bool saturationModelled() const override { return true; }

  private:
    SimSession session_;
};

class XyMachine final : public Machine {
  public:
    XyMachine(const MachineProfile& profile, std::unique_ptr<XySession> session,
              std::shared_ptr<const Program> program, double feedOverride, bool* loaded)
        : session_(std::move(session)),
          plotter_(profile.kind == MachineKind::Plotter),
          clampPercent_(profile.dcTable.pwmClampPercent) {
        XyController& c = session_->controller();
        c.setFeedOverride(feedOverride);
        c.selectAutomatic();
        *loaded = c.loadProgram(std::move(program));
        c.start(0);
    }
    void step() override { session_->step(); }
    Reading read() override {
        const XyStatus& s = session_->controller().status();
        Reading r = commonReading(s);
        const XyAxisSample* axis[2] = {&s.sample.x, &s.sample.y};
        for (int k = 0; k < 2; ++k) {
            const auto i = static_cast<std::size_t>(k);
            r.setpointMm[i] = axis[k]->setpointMm;
            // The plotter's count is its command: the head (the truth) is what it drew.
            r.measuredMm[i] = plotter_ ? session_->plant().positionMm(k) : axis[k]->positionMm;
            r.saturated[i] = !plotter_ && std::abs(axis[k]->drive) >= clampPercent_ - 1e-9;
        }
        return r;
    }
    void pressContinue() override { session_->controller().pressContinue(); }
    void drain(std::vector<ControllerEvent>& into) override {
        into.clear();
        session_->controller().drainEvents([&](const ControllerEvent& e) { into.push_back(e); });
    }
    QString alarmText(AlarmCode code, double value) const override {
        return xyAlarmText(code, value);
    }
    double plantSpeedMmS(int axis) override { return session_->plant().velocityMmS(axis); }
    double periodS() override { return session_->periodS(); }
    int axes() const override { return 2; }
    bool saturationModelled() const override { return !plotter_; }

  private:
    std::unique_ptr<XySession> session_;
    bool plotter_;
    double clampPercent_;
};

/// After an alarm the drives are off and the machine coasts: followed until every axis of the
/// plant has been still (under kStillMmS) for kStillForS, at most kFollowS, for the envelope.
constexpr double kStillMmS = 1e-3;
constexpr double kStillForS = 0.1;
constexpr double kFollowS = 10.0;

bool executing(ControllerState s) {
    return s == ControllerState::Running || s == ControllerState::Waiting ||
           s == ControllerState::Paused;
}

class Checker final : public ProgramChecker {
  public:
    Checker(const MachineProfile& profile, std::unique_ptr<Machine> machine,
            const ProgramCheckOptions& options)
        : machine_(std::move(machine)), end_{options.maxSeconds, 0.0} {
        result_.maxSeconds = options.maxSeconds;
        result_.axes = machine_->axes();
        result_.saturationModelled = machine_->saturationModelled();
        const AxisTravel* travel[2] = {&profile.limits.x, &profile.limits.y};
        for (std::size_t k = 0; k < 2; ++k) {
            result_.envelope[k].softMinMm = travel[k]->softMinMm;
            result_.envelope[k].softMaxMm = travel[k]->softMaxMm;
        }
        periodS_ = machine_->periodS();
    }

    bool advance(std::uint64_t periods) override {
        for (std::uint64_t i = 0; i < periods && !result_.done(); ++i)
            following_ ? followOne() : stepOne();
        return result_.done();
    }
    const ProgramCheck& result() const override { return result_; }

  private:
    void stepOne() {
        machine_->step();
        ++result_.periods;
        const Reading r = machine_->read();
        cycle_.observe(r.state, r.timeS);
        if (!result_.started && cycle_.started()) {
            result_.started = true;
            result_.homingS = cycle_.startS();
        }
        machine_->drain(events_);
        for (const ControllerEvent& e : events_)
            if (e.kind == EventKind::AlarmRaised) addAlarm(e, r);
        if (result_.started) {
            measureEnvelope(r);
            // The period that ended the program by an alarm is measured too: it is where the
            // error that tripped it was read.
            if (executing(r.state) || wasExecuting_) measureLoop(r);
        }
        wasExecuting_ = executing(r.state);
        RunOutcome outcome = RunOutcome::Finished;
        bool press = false;
        if (end_.check(r, r.timeS, outcome, press)) {
            result_.cycleTimeS = cycle_.cycleS();
            result_.endS = r.timeS;
            switch (outcome) {
                case RunOutcome::Finished:
                    result_.end = CheckEnd::Finished;
                    break;
                case RunOutcome::TimeLimit:
                    result_.end = CheckEnd::TimeLimit;
                    break;
                case RunOutcome::Alarm:
                    // The drives are off: follow the coast (the envelope) before the end.
                    endAfterFollow_ = r.state == ControllerState::Paused && r.heldByController
                                          ? CheckEnd::MotionlessLoop
                                          : CheckEnd::Alarm;
                    following_ = true;
                    followedS_ = stillS_ = 0.0;
                    break;
            }
            return;
        }
        if (press) {
            machine_->pressContinue();
            ++result_.operatorStops;
        }
    }

    void followOne() {
        machine_->step();
        ++result_.periods;
        const Reading r = machine_->read();
        machine_->drain(events_);
        for (const ControllerEvent& e : events_)
            if (e.kind == EventKind::AlarmRaised) addAlarm(e, r);
        if (result_.started) measureEnvelope(r);
        followedS_ += periodS_;
        bool still = true;
        for (int k = 0; k < result_.axes; ++k)
            still = still && std::abs(machine_->plantSpeedMmS(k)) < kStillMmS;
        stillS_ = still ? stillS_ + periodS_ : 0.0;
        if (stillS_ >= kStillForS - 1e-12 || followedS_ >= kFollowS - 1e-12)
            result_.end = endAfterFollow_;
    }

    void addAlarm(const ControllerEvent& e, const Reading& r) {
        if (e.alarm == AlarmCode::FinalPositionOff) result_.offTarget = true;
        if (result_.alarms.size() >= ProgramCheck::kMaxAlarms) {
            ++result_.alarmsOmitted;
            return;
        }
        CheckedAlarm a;
        a.code = e.alarm;
        a.value = e.value;
        a.warning = alarmSeverity(e.alarm) == AlarmSeverity::Warning;
        // The block executing: its line stays in the status after an alarm abandons the run.
        a.line = result_.started ? r.blockLine : 0;
        a.homingPhase = !result_.started;
        a.timeS = e.timeS;
        a.text = machine_->alarmText(e.alarm, e.value);
        // The DC table's following-error alarm carries the error that tripped it, mm, read in
        // a period whose sample the cut left unpublished: it is the worst there was.
        if (e.alarm == AlarmCode::FollowingError && result_.started &&
            e.value > result_.worstFollowingErrorMm) {
            result_.worstFollowingErrorMm = e.value;
            result_.worstFollowingErrorLine = a.line;
            result_.worstFollowingErrorAtS = e.timeS - cycle_.startS();
            // Its axis is not said: the one further behind in the last sample published.
            result_.worstFollowingErrorAxis =
                result_.axes == 2 && std::abs(r.setpointMm[1] - r.measuredMm[1]) >
                                         std::abs(r.setpointMm[0] - r.measuredMm[0])
                    ? 1
                    : 0;
        }
        result_.alarms.push_back(std::move(a));
    }

    void measureEnvelope(const Reading& r) {
        for (int k = 0; k < result_.axes; ++k) {
            AxisEnvelope& env = result_.envelope[static_cast<std::size_t>(k)];
            const double at = r.measuredMm[static_cast<std::size_t>(k)];
            if (!env.seen) {
                env.seen = true;
                env.minMm = env.maxMm = at;
            }
            env.minMm = std::min(env.minMm, at);
            env.maxMm = std::max(env.maxMm, at);
            const double beyond = std::max({0.0, at - env.softMaxMm, env.softMinMm - at});
            env.beyondMm = std::max(env.beyondMm, beyond);
            if (!env.outside && beyond > kEnvelopeToleranceMm) {
                env.outside = true;
                env.outsideLine = r.blockLine;
                env.outsideAtS = r.timeS;
            }
        }
    }

    void measureLoop(const Reading& r) {
        bool saturated = false;
        for (int k = 0; k < result_.axes; ++k) {
            const auto i = static_cast<std::size_t>(k);
            const double e = std::abs(r.setpointMm[i] - r.measuredMm[i]);
            if (e > result_.worstFollowingErrorMm) {
                result_.worstFollowingErrorMm = e;
                result_.worstFollowingErrorLine = r.blockLine;
                result_.worstFollowingErrorAxis = k;
                result_.worstFollowingErrorAtS = r.timeS - cycle_.startS();
            }
            saturated = saturated || r.saturated[i];
        }
        if (!saturated) {
            saturatedS_ = 0.0;
            return;
        }
        if (saturatedS_ == 0.0) {
            stretchLine_ = r.blockLine;
            stretchAtS_ = r.timeS - cycle_.startS();
        }
        saturatedS_ += periodS_;
        if (saturatedS_ > result_.longestSaturationS) {
            result_.longestSaturationS = saturatedS_;
            result_.longestSaturationLine = stretchLine_;
            result_.longestSaturationAtS = stretchAtS_;
        }
    }

    std::unique_ptr<Machine> machine_;
    RunEnd end_;
    CycleClock cycle_;
    ProgramCheck result_;
    std::vector<ControllerEvent> events_;
    double periodS_ = 0.001;
    double saturatedS_ = 0.0;  ///< the saturated stretch under way, s
    std::uint32_t stretchLine_ = 0;
    double stretchAtS_ = 0.0;
    bool wasExecuting_ = false;  ///< the program executed at the end of the last period
    bool following_ = false;
    CheckEnd endAfterFollow_ = CheckEnd::Alarm;
    double followedS_ = 0.0, stillS_ = 0.0;
};

}  // namespace

bool ProgramCheck::outsideSoftLimits() const {
    for (int k = 0; k < axes; ++k)
        if (envelope[static_cast<std::size_t>(k)].outside) return true;
    return false;
}

bool ProgramCheck::ok() const {
    if (end != CheckEnd::Finished || offTarget || outsideSoftLimits()) return false;
    return std::none_of(alarms.begin(), alarms.end(),
                        [](const CheckedAlarm& a) { return !a.warning; });
}

std::unique_ptr<ProgramChecker> ProgramChecker::make(const MachineProfile& machine,
                                                     std::shared_ptr<const Program> program,
                                                     const ProgramCheckOptions& options,
                                                     std::string* error) {
    auto fail = [&](const char* why) {
        if (error) *error = why;
        return std::unique_ptr<ProgramChecker>();
    };
    if (!(options.maxSeconds > 0.0) || !std::isfinite(options.maxSeconds))
        return fail("the check's bound must be a positive number of seconds");
    // The controllers clamp it; a figure outside is a caller's mistake, said rather than clamped.
    if (!(options.feedOverride >= 0.0 && options.feedOverride <= 1.5))
        return fail("the feed override must be from 0 to 1.5 (0 to 150 %)");
    if (!program) return fail("no program to check");
    if (!program->ok()) return fail("the program has compile errors: nothing to check");
    const bool xy = machine.kind != MachineKind::Rail;
    if (xy && program->y.size() != program->blocks.size())
        return fail("the program was compiled for a machine without Y: compile it for this one");
    MachineProfile profile = machine;
    if (options.railLoop) {
        if (xy)
            return fail(
                "a control law and gains are the rail's: an XY machine's are its profile's");
        const LoopGains& g = options.railLoop->gains;
        if (!std::isfinite(g.kp) || !std::isfinite(g.ki) || !std::isfinite(g.kd))
            return fail("the loop's gains must be finite numbers");
        // As the screens' Options > Control law and `run --law`: the law comes with its period
        // (issue 22 item 1), and runs with the gains given.
        const LoopLaw law = options.railLoop->law;
        const double engineeredS = profile.loop.law == LoopLaw::Engineered
                                       ? profile.loop.samplePeriodS
                                       : LoopParams{}.samplePeriodS;
        profile.loop.samplePeriodS = periodForLaw(law, profile.loop.samplePeriodS, engineeredS);
        profile.loop.law = law;
        (law == LoopLaw::Classic ? profile.loop.classic : profile.loop.engineered) = g;
    }
    bool loaded = false;
    std::unique_ptr<Machine> plant;
    if (xy) {
        XySessionMake made = makeXySession(profile, options.seed);
        if (!made.session) {
            if (error) *error = made.error;
            return nullptr;
        }
        plant = std::make_unique<XyMachine>(profile, std::move(made.session), std::move(program),
                                            options.feedOverride, &loaded);
    } else {
        plant = std::make_unique<RailMachine>(profile, std::move(program), options.seed,
                                              options.feedOverride, &loaded);
    }
    if (!loaded) return fail("the controller refused the program");
    return std::make_unique<Checker>(profile, std::move(plant), options);
}

std::optional<ProgramCheck> checkProgram(const MachineProfile& profile,
                                         std::shared_ptr<const Program> program,
                                         const ProgramCheckOptions& options, std::string* error) {
    auto checker = ProgramChecker::make(profile, std::move(program), options, error);
    if (!checker) return std::nullopt;
    checker->run();
    return checker->result();
}

}  // namespace trilho
