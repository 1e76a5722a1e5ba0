// Where a CL record came from (see ClProgram.h).
#include <aeronc/kinematics/ClProgram.h>

namespace aeronc::kinematics {

std::string ClProgram::where(const ClRecord& r) const {
    if (fromApt) return "APT line " + std::to_string(r.line);
    const bool known = r.op >= 0 && r.op < static_cast<int>(operations.size());
    // A tool controller's call and speed come before the first move of their operation.
    if (r.line == 0 && (r.kind == ClKind::LoadTool || r.kind == ClKind::Spindle) && !r.text.empty())
        return "tool controller '" + r.text + "'" + (known ? " of " + operations[r.op].label : std::string());
    if (!known) return "command " + std::to_string(r.line);
    return operations[r.op].label + ", move " + std::to_string(r.line);
}

}  // namespace aeronc::kinematics
