#pragma once
// Holes: elements bounded by one circle of concave cylinders about the setup axis, with
// their countersinks, drill points and counterbores.
#include "ElementDraft.h"
#include "SetupView.h"

#include <vector>

namespace aeronc::recognition {

// Radius of a cone face at a height along the setup's axis.
double coneRadiusAt(const FaceInfo& cone, const Vec3& axis, double height);

// Whether face f's bottom at height h rests on a drill point (cone or sphere below it).
// A cone that narrows downwards is a drill point; one that widens is a countersink at the
// far end of a through hole.
bool onDrillPoint(const SetupView& view, int f, double h);

// Makes holes of the drafts that are holes (type, HoleInfo, countersink, drill point as
// floor).
void recogniseHoles(std::vector<ElementDraft>& made, const SetupView& view);

// Gives each hole standing in a wider hole on its axis (its parent) that counterbore.
void recogniseCounterbores(std::vector<ElementDraft>& made, const SetupView& view);

}  // namespace aeronc::recognition
