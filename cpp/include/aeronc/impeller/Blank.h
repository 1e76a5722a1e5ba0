#pragma once
// The impeller blank (impeller paper §2): the largest outer profile of the part about its axis,
// grown by the allowance, revolved.
#include <aeronc/impeller/ImpellerFeatures.h>

#include <TopoDS_Shape.hxx>

namespace aeronc::impeller {

struct BlankProfile {
    // The profile as steps along the axis: from axial[i] to axial[i + 1] the blank's radius is
    // radius[i] (axial has one entry more than radius); axial 0 is the axis point's station.
    std::vector<double> axial, radius;
};

// The outer profile of `part` about the recognised axis: at each of `stations` equal steps along
// the axis, the largest radius of the part's surface there (from a triangulation with chordal
// deflection `deflection`), then grown by `allowance` radially and at both ends. Throws
// inputError for a negative allowance.
BlankProfile outerProfile(const TopoDS_Shape& part, const ImpellerFeatures& features, double allowance,
                          int stations = 80, double deflection = 0.02);

// The profile revolved about the axis: a solid with no bore (the route drills and bores it).
TopoDS_Shape revolveProfile(const BlankProfile& profile, const ImpellerFeatures& features);

}  // namespace aeronc::impeller
