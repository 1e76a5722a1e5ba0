// Area and centroid of faces, the invariants recognition groups by, against closed forms: a
// rational B-spline quarter cylinder (integrated over its parameter rectangle) and a square with
// a round hole (OCCT's boundary integration).
#include "impeller/FaceProperties.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_Circle.hxx>
#include <gp_Ax3.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include <gtest/gtest.h>

#include <cmath>

using aeronc::impeller::areaAndCentroid;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST(FaceProperties, BSplineQuarterCylinder) {
    const double r = 10, h = 5, span = kPi / 2;
    Handle(Geom_CylindricalSurface) cyl = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), r);
    Handle(Geom_RectangularTrimmedSurface) patch = new Geom_RectangularTrimmedSurface(cyl, 0, span, 0, h);
    Handle(Geom_BSplineSurface) bs = GeomConvert::SurfaceToBSplineSurface(patch);
    ASSERT_TRUE(bs->IsURational() || bs->IsVRational());
    const TopoDS_Face f = BRepBuilderAPI_MakeFace(bs, 1e-7);
    const auto a = areaAndCentroid(f);
    EXPECT_NEAR(a.area, r * span * h, 1e-6 * r * span * h);
    // Centroid of a circular arc: r sin(φ)/φ along its bisector.
    const double c = r * std::sin(span / 2) / (span / 2);
    EXPECT_NEAR(a.centroid.X(), c * std::cos(span / 2), 1e-6);
    EXPECT_NEAR(a.centroid.Y(), c * std::sin(span / 2), 1e-6);
    EXPECT_NEAR(a.centroid.Z(), h / 2, 1e-6);
}

TEST(FaceProperties, PlaneWithHole) {
    const double side = 20, hole = 3;
    BRepBuilderAPI_MakeFace mk(gp_Pln(gp::XOY()), 0, side, 0, side);
    Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(gp_Pnt(5, 5, 0), gp::DZ()), hole);
    TopoDS_Wire w = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle));
    w.Reverse();
    mk.Add(w);
    const auto a = areaAndCentroid(mk.Face());
    const double area = side * side - kPi * hole * hole;
    EXPECT_NEAR(a.area, area, 1e-6 * area);
    // Moments: the square's about its centre less the hole's about (5, 5).
    const double cx = (side * side * 10 - kPi * hole * hole * 5) / area;
    EXPECT_NEAR(a.centroid.X(), cx, 1e-6);
    EXPECT_NEAR(a.centroid.Y(), cx, 1e-6);
}
