// Faces of one surface merged again after a fuse (FaceMerging.h). The general merge is limited to
// the edges it handles on the shared impeller (pieces of one face, coplanar faces); the groups it
// leaves are rebuilt here as one face on the largest piece's surface, its boundary the pieces'
// edges less those they share, and OCCT's face fixer adding the curves on the surface (across the
// seam of a periodic surface, or on a coincident cylinder's) that the pieces did not have.
#include <aeronc/impeller/FaceMerging.h>

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>

#include <cmath>
#include <map>
#include <numeric>
#include <vector>

namespace aeronc::impeller {

namespace {

constexpr double kLinear = 1e-6;   // mm: surfaces closer than this are one
constexpr double kAngular = 1e-9;  // 1 - |cos| of axes taken as parallel

bool sameHandle(const TopoDS_Face& a, const TopoDS_Face& b) {
    TopLoc_Location la, lb;
    const Handle(Geom_Surface) sa = BRep_Tool::Surface(a, la);
    const Handle(Geom_Surface) sb = BRep_Tool::Surface(b, lb);
    return sa == sb && la.IsEqual(lb);
}

bool coincidentPlanes(const GeomAdaptor_Surface& a, const GeomAdaptor_Surface& b) {
    const gp_Pln p = a.Plane(), q = b.Plane();
    return 1 - std::abs(p.Axis().Direction().Dot(q.Axis().Direction())) < kAngular &&
           q.Distance(p.Location()) < kLinear;
}

bool coincidentCylinders(const GeomAdaptor_Surface& a, const GeomAdaptor_Surface& b) {
    const gp_Cylinder p = a.Cylinder(), q = b.Cylinder();
    return std::abs(p.Radius() - q.Radius()) < kLinear &&
           1 - std::abs(p.Axis().Direction().Dot(q.Axis().Direction())) < kAngular &&
           gp_Lin(q.Axis()).Distance(p.Location()) < kLinear;
}

// The same B-spline surface, copied (a fuse or a fix may give a piece its own copy).
bool equalBSplines(const TopoDS_Face& a, const TopoDS_Face& b) {
    TopLoc_Location la, lb;
    const auto sa = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(a, la));
    const auto sb = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(b, lb));
    if (sa.IsNull() || sb.IsNull() || !la.IsEqual(lb)) return false;
    if (sa->UDegree() != sb->UDegree() || sa->VDegree() != sb->VDegree() || sa->NbUPoles() != sb->NbUPoles() ||
        sa->NbVPoles() != sb->NbVPoles() || sa->NbUKnots() != sb->NbUKnots() || sa->NbVKnots() != sb->NbVKnots() ||
        sa->IsUPeriodic() != sb->IsUPeriodic() || sa->IsVPeriodic() != sb->IsVPeriodic())
        return false;
    for (int i = 1; i <= sa->NbUKnots(); ++i)
        if (std::abs(sa->UKnot(i) - sb->UKnot(i)) > 1e-12 || sa->UMultiplicity(i) != sb->UMultiplicity(i)) return false;
    for (int j = 1; j <= sa->NbVKnots(); ++j)
        if (std::abs(sa->VKnot(j) - sb->VKnot(j)) > 1e-12 || sa->VMultiplicity(j) != sb->VMultiplicity(j)) return false;
    for (int i = 1; i <= sa->NbUPoles(); ++i)
        for (int j = 1; j <= sa->NbVPoles(); ++j)
            if (sa->Pole(i, j).Distance(sb->Pole(i, j)) > kLinear || std::abs(sa->Weight(i, j) - sb->Weight(i, j)) > 1e-12)
                return false;
    return true;
}

// Whether two faces lie on one surface (either orientation).
bool oneSurface(const TopoDS_Face& a, const TopoDS_Face& b) {
    if (sameHandle(a, b) || equalBSplines(a, b)) return true;
    const GeomAdaptor_Surface sa(BRep_Tool::Surface(a)), sb(BRep_Tool::Surface(b));
    if (sa.GetType() != sb.GetType()) return false;
    if (sa.GetType() == GeomAbs_Plane) return coincidentPlanes(sa, sb);
    if (sa.GetType() == GeomAbs_Cylinder) return coincidentCylinders(sa, sb);
    return false;
}

double area(const TopoDS_Shape& s) {
    GProp_GProps g;
    BRepGProp::SurfaceProperties(s, g);
    return g.Mass();
}

bool oneValidSolid(const TopoDS_Shape& s) {
    int solids = 0;
    for (TopExp_Explorer e(s, TopAbs_SOLID); e.More(); e.Next()) ++solids;
    return solids == 1 && BRepCheck_Analyzer(s).IsValid();
}

// The general merge, across the edges between pieces of one face or coplanar faces only. Any
// other merge it tries may not return (on the shared impeller's bore it ran for minutes).
TopoDS_Shape unifyPiecesAndPlanes(const TopoDS_Shape& solid) {
    ShapeUpgrade_UnifySameDomain unify(solid, false, true, false);
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int i = 1; i <= edgeFaces.Extent(); ++i) {
        const TopTools_ListOfShape& faces = edgeFaces(i);
        bool merge = faces.Extent() == 2;
        if (merge) {
            const TopoDS_Face a = TopoDS::Face(faces.First()), b = TopoDS::Face(faces.Last());
            const GeomAdaptor_Surface sa(BRep_Tool::Surface(a)), sb(BRep_Tool::Surface(b));
            merge = sameHandle(a, b) || (sa.GetType() == GeomAbs_Plane && sb.GetType() == GeomAbs_Plane &&
                                         coincidentPlanes(sa, sb));
        }
        if (!merge) unify.KeepShape(edgeFaces.FindKey(i));
    }
    try {
        unify.Build();
    } catch (const Standard_Failure&) {
        return solid;  // "TopoDS_Vertex hasn't gp_Pnt" and the like: the pieces stay
    }
    return oneValidSolid(unify.Shape()) ? unify.Shape() : solid;
}

// Groups of two or more adjacent faces of one surface, by face index in `faces`.
std::vector<std::vector<int>> faceGroups(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces) {
    std::vector<int> parent(faces.Extent() + 1);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int i = 1; i <= edgeFaces.Extent(); ++i) {
        const TopTools_ListOfShape& l = edgeFaces(i);
        if (l.Extent() != 2 || l.First().IsSame(l.Last())) continue;
        const TopoDS_Face a = TopoDS::Face(l.First()), b = TopoDS::Face(l.Last());
        if (oneSurface(a, b)) parent[root(faces.FindIndex(a))] = root(faces.FindIndex(b));
    }
    std::map<int, std::vector<int>> groups;
    for (int i = 1; i <= faces.Extent(); ++i) groups[root(i)].push_back(i);
    std::vector<std::vector<int>> out;
    for (auto& [r, g] : groups)
        if (g.size() > 1) out.push_back(g);
    return out;
}

// One face on the largest piece's surface bounded by the pieces' edges that only one of them
// has; a null face when OCCT cannot make it. `baseIndex` is set to the piece it replaces.
TopoDS_Face mergedFace(const std::vector<TopoDS_Face>& pieces, size_t& baseIndex,
                       const Handle(ShapeBuild_ReShape)& context) {
    size_t largest = 0;
    std::vector<double> areas;
    for (const TopoDS_Face& f : pieces) areas.push_back(area(f));
    for (size_t i = 1; i < pieces.size(); ++i)
        if (areas[i] > areas[largest]) largest = i;
    const TopoDS_Face& base = pieces[largest];
    baseIndex = largest;

    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    {
        TopoDS_Compound c;
        BRep_Builder b;
        b.MakeCompound(c);
        for (const TopoDS_Face& f : pieces) b.Add(c, f);
        TopExp::MapShapesAndAncestors(c, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    }
    Handle(TopTools_HSequenceOfShape) boundary = new TopTools_HSequenceOfShape;
    for (const TopoDS_Face& f : pieces) {
        for (TopExp_Explorer e(f, TopAbs_EDGE); e.More(); e.Next()) {
            const TopTools_ListOfShape& owners = edgeFaces.FindFromKey(e.Current());
            bool shared = false;
            for (TopTools_ListIteratorOfListOfShape it(owners); it.More(); it.Next())
                if (!it.Value().IsSame(f)) shared = true;
            // A seam inside a piece would be joined as one edge, not the two sides a face needs:
            // left out, the face fixer puts it back.
            if (!shared && !BRep_Tool::IsClosed(TopoDS::Edge(e.Current()), f)) boundary->Append(e.Current());
        }
    }
    Handle(TopTools_HSequenceOfShape) wires;
    ShapeAnalysis_FreeBounds::ConnectEdgesToWires(boundary, kLinear, true, wires);
    if (wires.IsNull() || wires->IsEmpty()) return {};

    TopLoc_Location loc;
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(base, loc);
    TopoDS_Face face;
    BRep_Builder b;
    b.MakeFace(face, surface, loc, BRep_Tool::Tolerance(base));
    for (int i = 1; i <= wires->Length(); ++i) b.Add(face, TopoDS::Wire(wires->Value(i)));
    ShapeFix_Face fix(face);
    fix.SetContext(context);  // edges it replaces are replaced in the neighbouring faces too
    fix.FixOrientationMode() = 1;
    fix.FixMissingSeamMode() = 1;
    fix.Perform();
    TopoDS_Face out = fix.Face();
    if (out.IsNull()) return {};
    out.Orientation(base.Orientation());
    return out;
}

}  // namespace

TopoDS_Shape mergeFacesOfOneSurface(const TopoDS_Shape& input) {
    TopoDS_Shape solid = unifyPiecesAndPlanes(input);
    // One group at a time, on a copy: the face fixer changes the curves of the edges it is given
    // in place, which would spoil the solid when the group's merge is not kept.
    for (bool merging = true; merging;) {
        merging = false;
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(solid, TopAbs_FACE, faces);
        for (const std::vector<int>& group : faceGroups(solid, faces)) {
            BRepBuilderAPI_Copy copy(solid);
            std::vector<TopoDS_Face> pieces;
            for (int i : group) pieces.push_back(TopoDS::Face(copy.ModifiedShape(faces(i))));
            TopoDS_Face merged;
            size_t base = 0;
            Handle(ShapeBuild_ReShape) reshape = new ShapeBuild_ReShape;
            try {
                merged = mergedFace(pieces, base, reshape);
            } catch (const Standard_Failure&) {
                continue;
            }
            if (merged.IsNull()) continue;
            // A valid face may still bound the wrong side of its wires (on a closed surface the
            // rest of it): the merged face covers what its pieces covered, or it is not kept.
            double piecesArea = 0;
            for (const TopoDS_Face& f : pieces) piecesArea += area(f);
            if (std::abs(area(merged) - piecesArea) > 1e-3 * piecesArea) continue;
            for (size_t i = 0; i < pieces.size(); ++i) {
                if (i == base) reshape->Replace(pieces[i], merged);
                else reshape->Remove(pieces[i]);
            }
            const TopoDS_Shape next = reshape->Apply(copy.Shape());
            if (!oneValidSolid(next)) continue;
            solid = next;  // the face indices of the other groups now refer to the old solid
            merging = true;
            break;
        }
    }
    return solid;
}

}  // namespace aeronc::impeller
