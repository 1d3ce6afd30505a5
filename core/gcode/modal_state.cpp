#include "core/gcode/modal_state.h"

#include <algorithm>

namespace trilho {

void ModalState::apply(const Block& b) {
    switch (b.op) {
        case Op::Rapid:
        case Op::Linear:
            motion = b.op == Op::Rapid ? 0 : 1;
            if (b.op == Op::Linear) feed = b.feed;
            hasPosition = true;
            positionMm = b.x;
            break;
        case Op::Feed:
            feed = b.feed;
            break;
        case Op::Absolute:
            incremental = false;
            break;
        case Op::Incremental:
            incremental = true;
            break;
        case Op::SetZero:
            zeroMm = b.x;
            break;
        case Op::ResetZero:
            zeroMm = 0.0;
            break;
        default:
            break;
    }
}

ModalState modalStateBefore(const Program& program, std::size_t index) {
    ModalState s;
    const std::size_t end = std::min(index, program.blocks.size());
    for (std::size_t i = 0; i < end; ++i)
        s.apply(program.blocks[i]);
    return s;
}

}  // namespace trilho
