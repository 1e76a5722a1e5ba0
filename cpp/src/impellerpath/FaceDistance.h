#pragma once
// Distance from points to one face, for many points: what BRepExtrema_DistShapeShape measures
// between a vertex and a face (the nearest of the face's interior extrema, its edges and its
// vertices), with the surface's extrema grid, the edges' curves and the face's classifier built
// once instead of at every query.
#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPC.hxx>
#include <Extrema_ExtPS.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include <memory>
#include <vector>

namespace aeronc::impellerpath {

class FaceDistance {
public:
    explicit FaceDistance(const TopoDS_Face& face);
    FaceDistance(const FaceDistance&) = delete;
    FaceDistance& operator=(const FaceDistance&) = delete;

    // Distance from p to the face; `nearest` gets the face's point nearest to p. Not for
    // concurrent use (the extrema keep their state).
    double distance(const gp_Pnt& p, gp_Pnt& nearest);
    // A box holding the face.
    const Bnd_Box& box() const { return box_; }
    // A distance the face is no nearer to p than: the nearest point of a grid over the surface's
    // parameter bounds less the grid's reach (every point of a cell is within the cell's longest
    // side or diagonal of a corner; the cells are small beside the surface's curvature).
    double lowerBound(const gp_Pnt& p) const;

private:
    struct Edge {
        BRepAdaptor_Curve curve;
        Extrema_ExtPC extrema;
        Bnd_Box box;
    };
    TopoDS_Face face_;
    BRepAdaptor_Surface surface_;  // the extrema keep a pointer to it: the object never moves
    Extrema_ExtPS extrema_;
    std::unique_ptr<BRepTopAdaptor_FClass2d> classifier_;
    std::vector<std::unique_ptr<Edge>> edges_;
    std::vector<gp_Pnt> vertices_;
    Bnd_Box box_;
    std::vector<gp_XYZ> grid_;
    double reach_ = 0;
};

}  // namespace aeronc::impellerpath
