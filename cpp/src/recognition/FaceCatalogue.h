#pragma once
// Per-face geometry the recognition needs, computed once per part.
#include <aeronc/core/Vec3.h>

#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>
#include <TopoDS_Shape.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <memory>
#include <mutex>
#include <vector>

namespace aeronc::recognition {

enum class SurfaceKind { Plane, Cylinder, Cone, Torus, Sphere, Other };

// A B-spline face of degree 1 in one parameter with two rows of poles (equal weights
// pairwise): the extrusions and ruled faces CAD systems write for swept profiles and fillets.
struct RuledSpline {
    Handle(Geom_BSplineSurface) surface;  // with the face's location applied
    bool linearInV = true;    // the rows are curves along u at the two ends of v
    Vec3 extrusion{0, 0, 0};  // unit, when every pole pair differs by the same vector
};

struct FaceInfo {
    TopoDS_Face face;
    SurfaceKind kind = SurfaceKind::Other;
    Vec3 normal{0, 0, 0};   // plane: outward normal (out of the material)
    Vec3 planePoint{0, 0, 0};
    gp_Pln plane;           // the plane's own frame (its (u, v) are the face's parameters)
    Vec3 axisDir{0, 0, 0};  // cylinder / cone / torus / sphere axis direction
    Vec3 axisPoint{0, 0, 0};  // a point of the axis; a torus's or a sphere's centre
    double radius = 0;       // cylinder radius, torus minor radius, cone reference radius
    double semiAngle = 0;    // cone
    bool concave = false;    // cylinder / cone: outward normal points towards the axis
    Vec3 boxMin{0, 0, 0}, boxMax{0, 0, 0};
    std::vector<int> neighbours;  // 0-based indices of faces sharing an edge
    std::shared_ptr<const RuledSpline> ruled;  // B-spline linear in one parameter, else null
    double uMin = 0, uMax = 0, vMin = 0, vMax = 0;  // parameter range (round surfaces, ruled B-splines)
    mutable double area = -1;     // computed on demand
};

// The lazily built per-face caches are guarded, so the setups' levels may be sliced from
// several threads.
class FaceCatalogue {
public:
    explicit FaceCatalogue(const TopoDS_Shape& solid);
    int size() const { return static_cast<int>(faces_.size()); }
    const FaceInfo& operator[](int i) const { return faces_[static_cast<std::size_t>(i)]; }
    // 0-based index of a face of the solid, -1 if foreign.
    int indexOf(const TopoDS_Shape& face) const { return map_.FindIndex(face) - 1; }
    // The solid's edges, 1-based, in TopExp::MapShapes order.
    const TopTools_IndexedMapOfShape& edges() const { return edges_; }
    double area(int i) const;
    // Height range of face i along unit direction d (conservative: from its box).
    void heightRange(int i, const Vec3& d, double& lo, double& hi) const;
    // Height ranges of all faces along the frame's axis, from the boxes of their edges in
    // that frame: exact for lines and arcs, so for planes and for surfaces of revolution
    // about the axis, and rotation-independent.
    // `base` is where the face's lower boundary ends at the top: its lowest height for a
    // flat bottom edge, the top of the saddle where a hole breaks into a transverse bore.
    struct HeightRange {
        double lo, hi, base;
    };
    std::vector<HeightRange> heightRanges(const Vec3& u, const Vec3& v, const Vec3& w) const;
    // The highest point of face i's boundary along unit d, from points on its edges (their
    // ends, and along curved edges): quick, for sorting through many directions.
    double boundaryTop(int i, const Vec3& d) const;
    // A point strictly inside face i (world coordinates), cached.
    Vec3 interiorPoint(int i) const;
    // Classifier of points in face i's parameter space, built once per face and worker (a
    // classifier keeps a cursor into its sequences, so threads cannot share one).
    BRepTopAdaptor_FClass2d& classifier(int i) const;
    // Intersector of lines with face i, built once per face and worker, whatever the line's
    // direction: the setups and the direction search share it.
    IntCurvesFace_Intersector& intersector(int i) const;
    // Where a point of face i's parameter space lies: IN, OUT or ON. Faces with many
    // edges (a panel's top face with its pockets) use an index of their wires as polygons,
    // the rest OCCT's classifier.
    TopAbs_State classifyUV(int i, double u, double v) const;
    // The face's boundary as trimmed curves in its parameter space (null entry: an edge
    // without one), built once per face.
    const std::vector<Handle(Geom2d_TrimmedCurve)>& boundaryUV(int i) const;

private:
    Vec3 searchInterior(int i) const;
    std::vector<FaceInfo> faces_;
    TopTools_IndexedMapOfShape map_;
    TopTools_IndexedMapOfShape edges_;
    std::vector<std::vector<int>> faceEdges_;  // 1-based indices into edges_
    std::vector<std::vector<Vec3>> edgePoints_;  // per face: points along its boundary
    // Per edge (1-based): what its height range in any frame needs, in closed form for lines
    // and arcs (most edges); others are boxed in the frame.
    struct EdgeShape {
        enum Kind { None, Line, Arc, Other } kind = None;
        gp_Pnt a, b;    // line: its ends
        gp_Circ circle;  // arc: its circle and parameter range
        double t0 = 0, t1 = 0;
    };
    std::vector<EdgeShape> edgeShapes_;
    mutable std::vector<std::pair<bool, Vec3>> interior_;
    mutable std::vector<std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>>> classifiers_;  // by worker
    mutable std::vector<std::vector<std::unique_ptr<IntCurvesFace_Intersector>>> intersectors_;  // by worker
    mutable std::vector<std::unique_ptr<std::vector<Handle(Geom2d_TrimmedCurve)>>> boundaries_;
    struct WirePolygon {
        std::vector<std::pair<double, double>> pts;
        double u0, v0, u1, v1;
        bool contains(double u, double v) const;
    };
    mutable std::vector<std::unique_ptr<std::vector<WirePolygon>>> wireIndex_;  // [0] is the outer wire
    mutable std::recursive_mutex cache_;  // guards the caches above and FaceInfo::area
};

}  // namespace aeronc::recognition
