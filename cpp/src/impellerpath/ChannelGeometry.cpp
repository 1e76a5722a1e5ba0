#include "ChannelGeometry.h"

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_IntCS.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <Precision.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

namespace {

constexpr double kPi = 3.14159265358979323846;

gp_Pnt pnt(const Vec3& v) { return gp_Pnt(v.x(), v.y(), v.z()); }
Vec3 vec(const gp_Pnt& p) { return Vec3(p.X(), p.Y(), p.Z()); }
Vec3 vec(const gp_Vec& p) { return Vec3(p.X(), p.Y(), p.Z()); }

// The foot of p on a face's surface (its parameters, point and derivatives) and the face's
// outward unit normal there.
Vec3 footAndNormal(const SurfaceProjection& projection, const Handle(Geom_Surface)& surface, const TopoDS_Face& face,
                   const Vec3& p, const char* what, double& u, double& v, gp_Pnt& on, gp_Vec& du, gp_Vec& dv) {
    double d;
    if (!projection.project(pnt(p), u, v, d, on))
        throw inputError(std::string("impeller toolpaths: cannot project onto ") + what);
    gp_Pnt q;
    surface->D1(u, v, q, du, dv);
    const Vec3 n = vec(du.Crossed(dv)).normalized();
    return face.Orientation() == TopAbs_REVERSED ? Vec3(-n) : n;
}

double wrapAngle(double a) { return std::remainder(a, 2 * kPi); }

}  // namespace

Frame::Frame(const impeller::ImpellerFeatures& f) {
    const gp_Ax3 ax(gp_Pnt(f.axisPoint[0], f.axisPoint[1], f.axisPoint[2]),
                    gp_Dir(f.axisDirection[0], f.axisDirection[1], f.axisDirection[2]));
    o_ = vec(ax.Location());
    x_ = vec(gp_Vec(ax.XDirection()));
    y_ = vec(gp_Vec(ax.YDirection()));
    z_ = vec(gp_Vec(ax.Direction()));
}

Vec3 Frame::at(double r, double theta, double z) const {
    return o_ + z * z_ + r * (std::cos(theta) * x_ + std::sin(theta) * y_);
}
double Frame::axial(const Vec3& p) const { return (p - o_).dot(z_); }
double Frame::radius(const Vec3& p) const {
    const Vec3 d = p - o_;
    return (d - d.dot(z_) * z_).norm();
}
double Frame::theta(const Vec3& p) const {
    const Vec3 d = p - o_;
    return std::atan2(d.dot(y_), d.dot(x_));
}
Vec3 Frame::turnedVector(const Vec3& v, double angle) const {
    return Eigen::AngleAxisd(angle, z_) * v;
}
Vec3 Frame::turned(const Vec3& p, double angle) const { return o_ + turnedVector(p - o_, angle); }

SurfaceProjection::SurfaceProjection(const Handle(Geom_Surface)& surface)
    : projection_(std::make_unique<GeomAPI_ProjectPointOnSurf>()) {
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    projection_->Init(surface, u0, u1, v0, v1, Precision::PConfusion());
}

bool SurfaceProjection::project(const gp_Pnt& p, double& u, double& v, double& distance, gp_Pnt& nearest) const {
    projection_->Perform(p);
    if (projection_->NbPoints() == 0) return false;
    projection_->LowerDistanceParameters(u, v);
    distance = projection_->LowerDistance();
    nearest = projection_->NearestPoint();
    return true;
}

Obstacles::Obstacles(const std::vector<TopoDS_Face>& faces, Handle(Geom_Surface) hub) {
    for (const auto& f : faces) faces_.push_back(std::make_unique<FaceDistance>(f));
    if (!hub.IsNull()) hub_ = std::make_unique<SurfaceProjection>(hub);
}

double Obstacles::distance(const Vec3& p, double limit, Vec3* nearest) const {
    double best = limit;
    if (nearest) *nearest = p;
    const gp_Pnt q = pnt(p);
    double u, v, d;
    gp_Pnt on;
    if (hub_ && hub_->project(q, u, v, d, on) && d < best) {
        best = d;
        if (nearest) *nearest = vec(on);
    }
    const Bnd_Box point(q.XYZ(), q.XYZ());
    for (const auto& f : faces_) {
        if (f->box().Distance(point) >= best || f->lowerBound(q) >= best) continue;
        const double d = f->distance(q, on);
        if (d < best) {
            best = d;
            if (nearest) *nearest = vec(on);
        }
    }
    return best;
}

Clearance clearance(const Obstacles& o, const CutterShape& c, const Vec3& centre, const Vec3& axis, double stock) {
    // The cutter is the union of spheres centred on its axis, radius radiusAt(h); the shank and
    // holder the union of spheres of the shank radius above the flutes.
    Clearance out;
    const double flutes = c.fluteLength - c.tipRadius;
    const int n = std::max(1, static_cast<int>(std::ceil(flutes / 1.5)));
    // A sample farther than its neighbour's distance minus their spacing cannot be nearer than
    // that: such samples need no query.
    double known = -1, step = flutes / n;
    for (int i = 0; i <= n; ++i) {
        const double h = flutes * i / n;
        const double need = c.radiusAt(h) + stock;
        double d = known - step;
        Vec3 near;
        const Vec3 q = centre + h * axis;
        if (d < need + 0.05) {
            d = known = o.distance(q, need + 1.0, &near);
            if (need - d > out.gouge && (q - near).norm() > 1e-12) out.away = (q - near).normalized();
        } else {
            known = d;
        }
        out.gouge = std::max(out.gouge, need - d);
    }
    const double top = c.reach - c.tipRadius;
    const int m = std::max(1, static_cast<int>(std::ceil((top - flutes) / 3.0)));
    const double hstep = (top - flutes) / m;
    for (int i = 1; i <= m && !out.holder; ++i) {
        const double h = flutes + hstep * i;
        double d = known - hstep;
        if (d < c.shankRadius + 0.05) d = known = o.distance(centre + h * axis, c.shankRadius + 1.0);
        else known = d;
        out.holder = d < c.shankRadius;
    }
    return out;
}

Channel::Channel(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f, int bladeA)
    : Channel(faces, f, bladeA, bladeA + 1) {}

Channel::Channel(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f, int bladeA, int bladeB)
    : frame_(f), obstacles_({}, {}) {
    const int n = static_cast<int>(f.blades.size());
    const auto& A = f.blades[bladeA % n];
    const auto& B = f.blades[bladeB % n];
    auto face = [&](int i) { return TopoDS::Face(faces(i)); };
    auto makeWall = [&](int id) {
        Wall w;
        w.face = face(id);
        w.surface = BRep_Tool::Surface(w.face);
        w.projection = std::make_unique<SurfaceProjection>(w.surface);
        double u0, u1, v0, v1;
        BRepTools::UVBounds(w.face, u0, u1, v0, v1);
        BRepAdaptor_Surface s(w.face);
        w.rMin = 1e300, w.rMax = 0;
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j <= 10; ++j) {
                const Vec3 p = vec(s.Value(u0 + (u1 - u0) * i / 40, v0 + (v1 - v0) * j / 10));
                w.samples.push_back(p);
                w.rMin = std::min(w.rMin, frame_.radius(p)), w.rMax = std::max(w.rMax, frame_.radius(p));
            }
        return w;
    };
    a_ = makeWall(A.pressure);
    b_ = makeWall(B.suction);
    rMin_ = std::max(a_.rMin, b_.rMin);
    rMax_ = std::min(a_.rMax, b_.rMax);
    for (int k = bladeA + 1; k < bladeB; ++k)
        for (int id : f.blades[k % n].walls) rMax_ = std::min(rMax_, makeWall(id).rMin);
    if (rMax_ <= rMin_)
        throw inputError("impeller toolpaths: blades " + std::to_string(bladeA) + " and " +
                         std::to_string(bladeB % n) + " have no stretch of channel with both walls along it");
    hub_ = face(f.hub);
    hubSurface_ = BRep_Tool::Surface(hub_);
    hubProjection_ = std::make_unique<SurfaceProjection>(hubSurface_);
    shroudSurface_ = BRep_Tool::Surface(face(A.shroud));
    std::vector<TopoDS_Face> obstacles;
    std::vector<const impeller::Blade*> blades{&A, &B};
    for (int k = bladeA + 1; k < bladeB; ++k) blades.push_back(&f.blades[k % n]);
    for (const auto* b : blades) {
        for (int w : b->walls) obstacles.push_back(face(w));
        for (int w : b->fillets) obstacles.push_back(face(w));
        obstacles.push_back(face(b->shroud));
    }
    obstacles_ = Obstacles(obstacles, hubSurface_);
}

namespace {

// Axial heights where the line parallel to the axis at (r, theta) meets the surface.
std::vector<double> heights(const Frame& fr, const Handle(Geom_Surface)& s, double r, double theta) {
    const Vec3 p = fr.at(r, theta, 0), z = fr.z();
    Handle(Geom_Line) line = new Geom_Line(pnt(p), gp_Dir(z.x(), z.y(), z.z()));
    GeomAPI_IntCS hit(line, s);
    std::vector<double> out;
    if (hit.IsDone())
        for (int i = 1; i <= hit.NbPoints(); ++i) out.push_back(fr.axial(vec(hit.Point(i))));
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

double Channel::shroudZ(double r) const {
    const auto h = heights(frame_, shroudSurface_, r, 0.0);
    if (h.empty()) throw inputError("impeller toolpaths: no shroud at radius " + std::to_string(r));
    return h.front();  // the shroud is the lower sheet of its surface of revolution
}

double Channel::hubZ(double r) const {
    const double top = shroudZ(r);
    double best = -1e300;
    for (double z : heights(frame_, hubSurface_, r, 0.0))
        if (z < top) best = std::max(best, z);
    if (best == -1e300) throw inputError("impeller toolpaths: no hub under the shroud at radius " + std::to_string(r));
    return best;
}

double Channel::guessTheta(bool b, double r) const {
    const Wall& w = wall(b);
    double best = 1e300, theta = 0;
    for (const auto& p : w.samples) {
        const double d = std::abs(frame_.radius(p) - r);
        if (d < best) best = d, theta = frame_.theta(p);
    }
    return theta;
}

double Channel::wallTheta(bool b, double r, double z, double guess) const {
    const Wall& w = wall(b);
    const Vec3 c = frame_.at(0, 0, z), zd = frame_.z(), x = frame_.at(1, 0, z) - c;
    const gp_Ax2 ax(pnt(c), gp_Dir(zd.x(), zd.y(), zd.z()), gp_Dir(x.x(), x.y(), x.z()));
    Handle(Geom_Circle) circle = new Geom_Circle(ax, r);
    GeomAPI_IntCS hit(circle, w.surface);
    double best = 1e300, theta = guess;
    if (hit.IsDone())
        for (int i = 1; i <= hit.NbPoints(); ++i) {
            const double t = frame_.theta(vec(hit.Point(i)));
            const double d = std::abs(wrapAngle(t - guess));
            if (d < best) best = d, theta = guess + wrapAngle(t - guess);
        }
    if (best > 0.5) throw inputError("impeller toolpaths: a blade wall is not found at radius " + std::to_string(r));
    return theta;
}

void Channel::wallFrame(bool b, const Vec3& p, Vec3& ruling, Vec3& normal, double* uOut, double* vOut) const {
    const Wall& w = wall(b);
    double u, v;
    gp_Pnt on;
    gp_Vec du, dv;
    normal = footAndNormal(*w.projection, w.surface, w.face, p, "a blade wall", u, v, on, du, dv);
    // The ruling: the parameter direction closer to the axis, upward.
    const Vec3 a = vec(du).normalized(), c = vec(dv).normalized();
    ruling = std::abs(a.dot(frame_.z())) > std::abs(c.dot(frame_.z())) ? a : c;
    if (ruling.dot(frame_.z()) < 0) ruling = -ruling;
    ruling = (ruling - ruling.dot(normal) * normal).normalized();
    if (uOut) *uOut = u;
    if (vOut) *vOut = v;
}

Vec3 Channel::hubNormal(const Vec3& p) const {
    double u, v;
    gp_Pnt on;
    gp_Vec du, dv;
    return footAndNormal(*hubProjection_, hubSurface_, hub_, p, "the hub", u, v, on, du, dv);
}

}  // namespace aeronc::impellerpath

namespace aeronc::impellerpath {

double Channel::wallDistance(bool b, const Vec3& p, Vec3& normal) const {
    const Wall& w = wall(b);
    double u, v;
    gp_Pnt on;
    gp_Vec du, dv;
    normal = footAndNormal(*w.projection, w.surface, w.face, p, "a blade wall", u, v, on, du, dv);
    return (p - vec(on)).dot(normal);
}

double Channel::hubDistance(const Vec3& p, Vec3& normal) const {
    double u, v;
    gp_Pnt on;
    gp_Vec du, dv;
    normal = footAndNormal(*hubProjection_, hubSurface_, hub_, p, "the hub", u, v, on, du, dv);
    return (p - vec(on)).dot(normal);
}

}  // namespace aeronc::impellerpath
