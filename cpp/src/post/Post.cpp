// The post chains (see Post.h).
#include <aeronc/post/Post.h>

#include <algorithm>

namespace aeronc::post {

using namespace kinematics;

PlanOptions planOptionsFor(const NcOptions& nc, PlanOptions plan) {
    plan.linearizeSimultaneousArcs = nc.dialect == Dialect::Sinumerik840D;
    if (!(plan.chordTolerance > 0)) throw inputError("the chord tolerance must be positive");
    return plan;
}

PostSummary postProgram(const ClProgram& program, const MachineModel& machine, const NcOptions& nc, const PlanOptions& plan) {
    if (nc.precision < 0 || nc.precision > 12 || nc.anglePrecision < 0 || nc.anglePrecision > 12 ||
        nc.vectorPrecision < 1 || nc.vectorPrecision > 15)
        throw inputError("precision must be between 0 and 12 decimals (vectors: 1 to 15)");
    const Plan p = planProgram(program, machine, planOptionsFor(nc, plan));
    PostSummary s;
    s.text = formatNc(p, nc);
    s.lines = static_cast<size_t>(std::count(s.text.begin(), s.text.end(), '\n'));
    for (const auto& st : p.steps) s.moves += st.kind == ClKind::Move || st.kind == ClKind::Cycle;
    s.branchChanges = p.branchChanges;
    s.segments = static_cast<int>(p.segments.size());
    return s;
}

PostSummary postFreeCad(const std::vector<PathSection>& sections, const MachineModel& machine, const NcOptions& nc,
                        const PlanOptions& plan) {
    return postProgram(readFreeCadPath(sections, nc.programName), machine, nc, plan);
}

PostSummary postApt(const std::string& aptText, const MachineModel& machine, const NcOptions& nc, const PlanOptions& plan) {
    return postProgram(readApt(aptText), machine, nc, plan);
}

}  // namespace aeronc::post
