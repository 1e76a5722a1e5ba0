#pragma once
// One channel of an impeller: the space between the pressure side of blade A and the suction
// side of the next blade B, over the hub and under the shroud, in cylindrical coordinates about
// the impeller's axis; and the distance queries that check a cutter in it.
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include "FaceDistance.h"

#include <Bnd_Box.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Surface.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax3.hxx>

#include <memory>
#include <vector>

namespace aeronc::impellerpath {

using kinematics::Vec3;

class Frame {
public:
    Frame(const impeller::ImpellerFeatures& f);
    Vec3 at(double r, double theta, double z) const;
    double radius(const Vec3& p) const;
    double theta(const Vec3& p) const;
    double axial(const Vec3& p) const;
    Vec3 z() const { return z_; }
    // p turned about the axis by `angle`.
    Vec3 turned(const Vec3& p, double angle) const;
    Vec3 turnedVector(const Vec3& v, double angle) const;

private:
    Vec3 o_, x_, y_, z_;
};

// Projection of points onto a whole surface (GeomAPI_ProjectPointOnSurf over the surface's
// bounds) with its search grid built once. Not for concurrent use.
class SurfaceProjection {
public:
    explicit SurfaceProjection(const Handle(Geom_Surface)& surface);
    // The nearest point's parameters and distance; false when the projection finds none.
    bool project(const gp_Pnt& p, double& u, double& v, double& distance, gp_Pnt& nearest) const;

private:
    std::unique_ptr<GeomAPI_ProjectPointOnSurf> projection_;  // its extrema point into it: never moved
};

// Faces a cutter must not cut into, with their bounding boxes for quick rejection; and the hub,
// measured to its whole surface (the hub face carries every blade's root loop, so a distance to
// the face itself would measure to all those edges; its surface runs on under the fillets and
// blades, inside the material, so it is never nearer to a point in a channel than the face is).
// A hub an exporter cut into a piece per channel is measured to each piece's surface.
// Not for concurrent use: each thread measures with its own.
class Obstacles {
public:
    Obstacles(const std::vector<TopoDS_Face>& faces, const std::vector<Handle(Geom_Surface)>& hub);
    // Distance from p to the faces and the hub, up to `limit` (beyond it, `limit`); `nearest`,
    // when given, gets the nearest point found (p itself when nothing is within the limit).
    double distance(const Vec3& p, double limit, Vec3* nearest = nullptr) const;

private:
    std::vector<std::unique_ptr<FaceDistance>> faces_;
    std::vector<std::unique_ptr<SurfaceProjection>> hub_;
};

// The faces of the part a cutter in the channels may meet besides the hub: every blade's walls,
// fillets and shroud faces, the planes and the turned faces (a nose between the blades' inner
// ends, the rim between their outer ends).
std::vector<TopoDS_Face> partObstacles(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f);
// The surfaces of every hub face (one of revolution, or a piece per channel).
std::vector<Handle(Geom_Surface)> hubSurfaces(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f);

// A wall face and what the paths ask of it.
struct Wall {
    TopoDS_Face face;
    Handle(Geom_Surface) surface;
    std::unique_ptr<SurfaceProjection> projection;
    std::vector<Vec3> samples;  // points of the face on a parameter grid, for first guesses
    double rMin = 0, rMax = 0;
};

class Channel {
public:
    Channel(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f, int bladeA);
    // The channel between blade A and a later blade B (the inducer: from one main blade to the
    // next, ahead of the splitter between them): the blades between are obstacles, and the
    // channel ends where the innermost of them begins.
    Channel(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f, int bladeA, int bladeB);

    const Frame& frame() const { return frame_; }
    double rMin() const { return rMin_; }
    double rMax() const { return rMax_; }
    double hubZ(double r) const;
    // The hub's height at radius r; false where there is no hub under the channel (where the
    // blades stand on a nose or a rim instead).
    bool hubBelow(double r, double& z) const;
    double shroudZ(double r) const;
    // Angle of the wall at radius r and height z (A: pressure side of the first blade, B: the
    // suction side of the next), near `guess`.
    double wallTheta(bool b, double r, double z, double guess) const;
    double guessTheta(bool b, double r) const;
    // Upward ruling direction of a wall near point p, and its unit normal into the channel.
    void wallFrame(bool b, const Vec3& p, Vec3& ruling, Vec3& normal, double* u = nullptr, double* v = nullptr) const;
    const Wall& wall(bool b) const { return b ? b_ : a_; }
    Vec3 hubNormal(const Vec3& p) const;
    // Signed distance from p to a wall's surface and to the hub's, positive on the channel side,
    // with the unit normal into the channel at the nearest point.
    double wallDistance(bool b, const Vec3& p, Vec3& normal) const;
    double hubDistance(const Vec3& p, Vec3& normal) const;

    // The two blades' faces and the hub.
    const Obstacles& obstacles() const { return obstacles_; }

private:
    // A hub face under this channel.
    struct HubPiece {
        TopoDS_Face face;
        Handle(Geom_Surface) surface;
        std::unique_ptr<SurfaceProjection> projection;
        double theta = 0;  // an angle inside the piece, for the heights of its surface
    };
    // The hub piece whose surface is nearest to p.
    const HubPiece& hubAt(const Vec3& p) const;
    double middleTheta(double r) const;

    Frame frame_;
    Wall a_, b_;
    std::vector<HubPiece> hub_;
    bool hubOfRevolution_ = true;  // one hub face for every channel: its surface is of revolution
    Handle(Geom_Surface) shroudSurface_;
    // Without a single shroud face of revolution (a tip of several faces: a flat top, pieces
    // following the casing): the highest point of the two blades' shroud faces by radius.
    std::vector<double> shroudR_, shroudTop_;
    Obstacles obstacles_;
    double rMin_ = 0, rMax_ = 0;
};

// How far the cutter at (centre, axis) cuts into the channel's walls and hub (> 0: a gouge, mm)
// and whether its shank or holder touches them.
struct Clearance {
    double gouge = -1e300;
    bool holder = false;
    double holderGap = 1.0;    // least gap of the shank and holder to the part, up to 1 mm
    Vec3 away = Vec3::Zero();  // unit: from the nearest obstacle point towards the deepest sample
};
// `stock`: distance the cutter must keep beyond its own radius (roughing's allowance).
Clearance clearance(const Obstacles& o, const CutterShape& cutter, const Vec3& centre, const Vec3& axis,
                    double stock = 0);

}  // namespace aeronc::impellerpath
