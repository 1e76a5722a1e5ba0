#pragma once
// The faces of a solid with what the impeller rules ask of them: surface type, area, centroid,
// and which faces meet along an edge, tangentially or not.
#include <GeomAbs_SurfaceType.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

#include <vector>

namespace aeronc::impeller {

struct FaceInfo {
    TopoDS_Face face;
    GeomAbs_SurfaceType type = GeomAbs_OtherSurface;
    double area = 0;
    gp_Pnt centroid;
};

struct Neighbour {
    int face;       // 1-based
    bool tangent;   // the faces meet with equal normals along the shared edge
};

class FaceGraph {
public:
    explicit FaceGraph(const TopoDS_Shape& shape);
    int size() const { return static_cast<int>(info_.size()); }
    const FaceInfo& operator[](int face) const { return info_[face - 1]; }
    const std::vector<Neighbour>& neighbours(int face) const { return neighbours_[face - 1]; }
    bool tangent(int a, int b) const;
    bool adjacent(int a, int b) const;
    // The outward normal of a face at the point of its surface nearest to p.
    gp_Dir normalNear(int face, const gp_Pnt& p) const;

private:
    std::vector<FaceInfo> info_;
    std::vector<std::vector<Neighbour>> neighbours_;
};

}  // namespace aeronc::impeller
