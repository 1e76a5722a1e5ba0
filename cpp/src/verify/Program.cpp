#include <aeronc/verify/Program.h>

namespace aeronc::verify {

std::vector<Segment> segmentsOf(const Operation& op) {
    std::vector<Segment> out;
    out.reserve(op.moves.size() + 8);
    bool started = false;
    std::array<double, 3> at{};
    auto go = [&](const std::array<double, 3>& to, bool rapid, int move) {
        out.push_back({started ? at : to, to, rapid, move});
        at = to, started = true;
    };
    for (int k = 0; k < int(op.moves.size()); ++k) {
        const Move& m = op.moves[k];
        if (m.kind == MoveKind::DrillCycle) {
            if (started) go({m.x, m.y, at[2]}, true, k);
            go({m.x, m.y, m.retract}, true, k);
            go({m.x, m.y, m.z}, false, k);
            go({m.x, m.y, m.retract}, true, k);
        } else {
            go({m.x, m.y, m.z}, m.kind == MoveKind::Rapid, k);
        }
    }
    return out;
}

}  // namespace aeronc::verify
