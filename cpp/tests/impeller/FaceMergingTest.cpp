// Faces a fuse splits on one surface merged again (FaceMerging.h, BodyFusion.h), on bodies made
// here as the shared impeller's are exported: a hub whose outer side is one B-spline face with a
// seam, its bore a cylinder about +Z, and blade bodies that reach into the bore, their inner ends
// on the bore's cylinder about -Z, and out through the hub's side, one channel over the seam.
#include <aeronc/impeller/BodyFusion.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Trsf.hxx>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace aeronc::impeller;

namespace {

constexpr double kHubRadius = 30, kHubHeight = 10, kBoreRadius = 4;

double volume(const TopoDS_Shape& s) {
    GProp_GProps g;
    BRepGProp::VolumeProperties(s, g, 1e-9);  // B-spline faces: the default integration is 0.05 % off
    return g.Mass();
}

// The hub: a disc with a bore, every face but the bore a B-spline (the side one face with its
// seam at 0°).
TopoDS_Shape hub() {
    // The disc's faces made B-splines, then the bore cut: it stays a cylinder (the blades' ends
    // lie on it).
    const TopoDS_Shape disc =
        BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeCylinder(kHubRadius, kHubHeight).Shape(), true).Shape();
    const TopoDS_Shape bore = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp_Dir(0, 0, 1)), kBoreRadius,
                                                       kHubHeight + 2).Shape();
    return BRepAlgoAPI_Cut(disc, bore).Shape();
}

// A blade at `deg` about +Z: a slab from the bore out past the hub's side and through the hub's
// height, its inner end on the bore's cylinder taken about -Z.
TopoDS_Shape blade(double deg) {
    const TopoDS_Shape slab = BRepPrimAPI_MakeBox(gp_Pnt(0, -1, -2), kHubRadius + 5, 2, kHubHeight + 12).Shape();
    const TopoDS_Shape core = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 30), gp_Dir(0, 0, -1)), kBoreRadius, 40).Shape();
    gp_Trsf t;
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), deg * M_PI / 180);
    return BRepBuilderAPI_Transform(BRepAlgoAPI_Cut(slab, core).Shape(), t, true).Shape();
}

int facesOn(const TopoDS_Shape& s, GeomAbs_SurfaceType type, double radius = -1) {
    int n = 0;
    for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) {
        const GeomAdaptor_Surface a(BRep_Tool::Surface(TopoDS::Face(e.Current())));
        if (a.GetType() != type) continue;
        if (radius > 0 && std::abs(a.Cylinder().Radius() - radius) > 1e-6) continue;
        ++n;
    }
    return n;
}

}  // namespace

TEST(BodyFusion, PiecesOverTheSeamAndOnTheBoreAreMergedAgain) {
    const TopoDS_Shape h = hub();
    ASSERT_EQ(facesOn(h, GeomAbs_Cylinder, kBoreRadius), 1);
    ASSERT_EQ(facesOn(h, GeomAbs_BSplineSurface), 3);  // the side, the top and the back
    const std::vector<double> angles{30, 150, 270};    // the seam (0°) in the channel 270°..30°
    TopoDS_Compound c;
    BRep_Builder b;
    b.MakeCompound(c);
    b.Add(c, h);
    double truth = volume(h);
    for (double a : angles) {
        const TopoDS_Shape bl = blade(a);
        b.Add(c, bl);
        truth += volume(bl) - volume(BRepAlgoAPI_Common(bl, h).Shape());
    }

    const FusedBodies f = fuseBodies(c);
    EXPECT_EQ(f.fused, 4);
    ASSERT_EQ(solidCount(f.solid), 1);
    EXPECT_TRUE(BRepCheck_Analyzer(f.solid).IsValid());
    EXPECT_NEAR(volume(f.solid), truth, 1e-6 * truth);
    // One bore face (the blades' ends in it), and the side, top and back each one piece per
    // channel (the side's piece over the seam one face).
    EXPECT_EQ(facesOn(f.solid, GeomAbs_Cylinder, kBoreRadius), 1);
    EXPECT_EQ(facesOn(f.solid, GeomAbs_BSplineSurface), 3 * 3);
}
