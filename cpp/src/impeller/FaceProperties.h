#pragma once
// Area and centroid of a face, the invariants the impeller rules group faces by.
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

namespace aeronc::impeller {

struct AreaAndCentroid {
    double area = 0;
    gp_Pnt centroid;
};

// A B-spline face bounded by its parameter rectangle (fillets, rolled walls) is integrated
// directly over that rectangle, Gauss-Legendre per knot span: an order of magnitude faster and
// more accurate than OCCT's boundary integration, which for such faces errs by up to 0.2 % in
// area (the grouping tolerance). Any other face goes through BRepGProp.
AreaAndCentroid areaAndCentroid(const TopoDS_Face& face);

// Whether the face is its surface's parameter rectangle (every point of its parameter bounds is
// on the face): one wire whose every edge runs along a side of the bounds.
bool isParameterRectangle(const TopoDS_Face& face);

}  // namespace aeronc::impeller
