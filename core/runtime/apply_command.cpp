#include "core/runtime/apply_command.h"

#include <algorithm>

namespace trilho {

void applyCommand(RailController& m, const Command& c) {
    switch (c.kind) {
        case CommandKind::SelectManual:
            m.selectManual();
            break;
        case CommandKind::Home:
            m.home();
            break;
        case CommandKind::SelectAutomatic:
            m.selectAutomatic();
            break;
        case CommandKind::ManualLeft:
            m.manualLeft();
            break;
        case CommandKind::ManualRight:
            m.manualRight();
            break;
        case CommandKind::ManualStop:
            m.manualStop();
            break;
        case CommandKind::JogStart:
            m.jogStart(static_cast<int>(c.i), c.a);
            break;
        case CommandKind::JogStop:
            m.jogStop();
            break;
        case CommandKind::JogIncrement:
            m.jogIncrement(c.a, c.b);
            break;
        case CommandKind::Start:
            m.start(static_cast<std::size_t>(std::max<std::int64_t>(0, c.i)));
            break;
        case CommandKind::Continue:
            m.pressContinue();
            break;
        case CommandKind::Hold:
            m.hold();
            break;
        case CommandKind::Resume:
            m.resume();
            break;
        case CommandKind::SingleBlock:
            m.setSingleBlock(c.i != 0);
            break;
        case CommandKind::FeedOverride:
            m.setFeedOverride(c.a);
            break;
        case CommandKind::Acknowledge:
            m.acknowledgeAlarms();
            break;
        case CommandKind::ResetEStop:
            m.resetEmergencyStop();
            break;
        case CommandKind::SetGains:
            m.setGains(static_cast<LoopLaw>(c.i), {c.a, c.b, c.c});
            break;
        case CommandKind::SetLaw:
            m.setLaw(static_cast<LoopLaw>(c.i));
            break;
        case CommandKind::LoadProgram:
            break;
    }
}

}  // namespace trilho
