#pragma once
// The posts in one call each: FreeCAD Path objects or an APT file -> NC text, through the
// same reader -> planner (kinematics) -> dialect formatter chain; and FreeCAD Path -> APT.
#include <aeronc/post/Apt.h>
#include <aeronc/post/NcFormat.h>
#include <aeronc/post/PathReader.h>

namespace aeronc::post {

struct PostSummary {
    std::string text;
    size_t lines = 0;
    size_t moves = 0;          // planned moves, added ones included
    int branchChanges = 0;     // retract / reposition / re-enter sequences
    int segments = 0;
};

// Planner options that follow from the dialect: TRAORI segments of the 840D take no arcs in
// a tilted plane, so those arcs are linearised.
kinematics::PlanOptions planOptionsFor(const NcOptions& nc, kinematics::PlanOptions plan);

PostSummary postProgram(const kinematics::ClProgram& program, const kinematics::MachineModel& machine, const NcOptions& nc,
                        const kinematics::PlanOptions& plan);

PostSummary postFreeCad(const std::vector<PathSection>& sections, const kinematics::MachineModel& machine,
                        const NcOptions& nc, const kinematics::PlanOptions& plan);

PostSummary postApt(const std::string& aptText, const kinematics::MachineModel& machine, const NcOptions& nc,
                    const kinematics::PlanOptions& plan);

}  // namespace aeronc::post
