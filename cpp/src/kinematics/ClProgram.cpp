// Where a CL record came from (see ClProgram.h).
#include <aeronc/kinematics/ClProgram.h>

namespace aeronc::kinematics {

std::string ClProgram::where(const ClRecord& r) const {
    if (fromApt) return "APT line " + std::to_string(r.line);
    if (r.op < 0 || r.op >= static_cast<int>(operations.size())) return "command " + std::to_string(r.line);
    return operations[r.op].label + ", move " + std::to_string(r.line);
}

}  // namespace aeronc::kinematics
