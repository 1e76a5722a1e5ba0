#include "ChannelGeometry.h"

#include <aeronc/core/Error.h>
#include <aeronc/impeller/FaceSampling.h>

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

// Points inside a face on a grid over its parameter range.
std::vector<Vec3> insidePoints(const TopoDS_Face& f, int nu, int nv) {
    std::vector<Vec3> out;
    for (const auto& p : impeller::pointsInsideFace(f, nu, nv)) out.push_back(vec(p));
    return out;
}

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

Obstacles::Obstacles(const std::vector<TopoDS_Face>& faces, const std::vector<Handle(Geom_Surface)>& hub) {
    for (const auto& f : faces) faces_.push_back(std::make_unique<FaceDistance>(f));
    for (const auto& h : hub)
        if (!h.IsNull()) hub_.push_back(std::make_unique<SurfaceProjection>(h));
}

std::vector<TopoDS_Face> partObstacles(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f) {
    std::vector<TopoDS_Face> out;
    auto add = [&](int id) {
        if (id >= 1 && id <= faces.Extent()) out.push_back(TopoDS::Face(faces(id)));
    };
    for (const auto& b : f.blades) {
        for (int w : b.walls) add(w);
        for (int w : b.fillets) add(w);
        if (b.shroudFaces.empty()) add(b.shroud);
        for (int w : b.shroudFaces) add(w);
    }
    for (int p : f.planes) add(p);
    for (int t : f.turned) add(t);
    return out;
}

std::vector<Handle(Geom_Surface)> hubSurfaces(const TopTools_IndexedMapOfShape& faces, const impeller::ImpellerFeatures& f) {
    std::vector<Handle(Geom_Surface)> out;
    if (f.hubFaces.size() <= 1) return {BRep_Tool::Surface(TopoDS::Face(faces(f.hub)))};
    for (int h : f.hubFaces) out.push_back(BRep_Tool::Surface(TopoDS::Face(faces(h))));
    return out;
}

double Obstacles::distance(const Vec3& p, double limit, Vec3* nearest) const {
    double best = limit;
    if (nearest) *nearest = p;
    const gp_Pnt q = pnt(p);
    double u, v, d;
    gp_Pnt on;
    for (const auto& h : hub_)
        if (h->project(q, u, v, d, on) && d < best) {
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
        out.holderGap = std::min(out.holderGap, d - c.shankRadius);
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
    // The hub under this channel: the one face of revolution, or the pieces (an exporter's
    // piece per channel) with a share of their points between the two walls.
    auto addPiece = [&](int id) {
        HubPiece h;
        h.face = face(id);
        h.surface = BRep_Tool::Surface(h.face);
        h.projection = std::make_unique<SurfaceProjection>(h.surface);
        hub_.push_back(std::move(h));
    };
    hubOfRevolution_ = f.hubFaces.size() <= 1;
    if (hubOfRevolution_) {
        addPiece(f.hub);
    } else {
        double hubLo = 1e300, hubHi = 0;
        for (int id : f.hubFaces) {
            const auto pts = insidePoints(face(id), 12, 12);
            int in = 0;
            for (const auto& p : pts) {
                const double r = frame_.radius(p), t = frame_.theta(p);
                const double ta = guessTheta(false, r), tb = guessTheta(true, r);
                const double span = wrapAngle(tb - ta);
                in += span > 0 && wrapAngle(t - ta) > 0 && wrapAngle(t - ta) < span;
            }
            // A tenth: an exporter's pieces need not follow the channels (on the shared impeller
            // each channel runs over two pieces, a third to a half of each inside it).
            if (pts.empty() || in < 0.1 * pts.size()) continue;
            addPiece(id);
            hub_.back().theta = frame_.theta(pts[pts.size() / 2]);
            for (const auto& p : pts) hubLo = std::min(hubLo, frame_.radius(p)), hubHi = std::max(hubHi, frame_.radius(p));
        }
        if (hub_.empty())
            throw inputError("impeller toolpaths: no hub face between blades " + std::to_string(bladeA) + " and " +
                             std::to_string(bladeB % n));
        // Inside the hub's first and last radius the blades stand on the nose or the rim: the
        // channel is where there is hub under it.
        rMin_ = std::max(rMin_, hubLo), rMax_ = std::min(rMax_, hubHi);
    }
    shroudSurface_ = BRep_Tool::Surface(face(A.shroud));
    if (A.shroudFaces.size() > 1 || B.shroudFaces.size() > 1) {
        // The tip's height by radius: the highest point of the shroud faces in bands of radius.
        constexpr int kBands = 60;
        std::vector<std::pair<double, double>> pts;  // radius, axial
        double lo = 1e300, hi = 0;
        for (const auto* blade : {&A, &B})
            for (int id : blade->shroudFaces)
                for (const auto& p : insidePoints(face(id), 30, 10)) {
                    pts.push_back({frame_.radius(p), frame_.axial(p)});
                    lo = std::min(lo, pts.back().first), hi = std::max(hi, pts.back().first);
                }
        std::vector<double> top(kBands, -1e300);
        for (const auto& [r, z] : pts) {
            const int k = std::clamp(static_cast<int>((r - lo) / std::max(hi - lo, 1e-9) * kBands), 0, kBands - 1);
            top[k] = std::max(top[k], z);
        }
        for (int k = 0; k < kBands; ++k)
            if (top[k] > -1e300) shroudR_.push_back(lo + (k + 0.5) * (hi - lo) / kBands), shroudTop_.push_back(top[k]);
        if (shroudR_.empty()) throw inputError("impeller toolpaths: the blades' shroud faces hold no points");
    }
    std::vector<Handle(Geom_Surface)> hubs;
    for (const auto& h : hub_) hubs.push_back(h.surface);
    // The channel's own blades (the blades between, for the inducer), the nose and the rim.
    impeller::ImpellerFeatures own = f;
    own.blades.clear();
    for (int k = bladeA; k <= bladeB; ++k) own.blades.push_back(f.blades[k % n]);
    obstacles_ = Obstacles(partObstacles(faces, own), hubs);
}

const Channel::HubPiece& Channel::hubAt(const Vec3& p) const {
    if (hub_.size() == 1) return hub_.front();
    const HubPiece* best = &hub_.front();
    double nearest = 1e300, u, v, d;
    gp_Pnt on;
    for (const auto& h : hub_)
        if (h.projection->project(pnt(p), u, v, d, on) && d < nearest) nearest = d, best = &h;
    return *best;
}

double Channel::middleTheta(double r) const { return 0.5 * (guessTheta(false, r) + guessTheta(true, r)); }

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
    if (!shroudR_.empty()) {
        if (r <= shroudR_.front()) return shroudTop_.front();
        if (r >= shroudR_.back()) return shroudTop_.back();
        const size_t k = std::upper_bound(shroudR_.begin(), shroudR_.end(), r) - shroudR_.begin();
        const double t = (r - shroudR_[k - 1]) / (shroudR_[k] - shroudR_[k - 1]);
        return shroudTop_[k - 1] + t * (shroudTop_[k] - shroudTop_[k - 1]);
    }
    const auto h = heights(frame_, shroudSurface_, r, 0.0);
    if (h.empty()) throw inputError("impeller toolpaths: no shroud at radius " + std::to_string(r));
    return h.front();  // the shroud is the lower sheet of its surface of revolution
}

double Channel::hubZ(double r) const {
    double z;
    if (!hubBelow(r, z)) throw inputError("impeller toolpaths: no hub under the shroud at radius " + std::to_string(r));
    return z;
}

bool Channel::hubBelow(double r, double& z) const {
    const double top = shroudZ(r);
    double best = -1e300;
    // A hub of pieces: each piece's surface where the channel runs (a piece need not reach
    // round to angle 0).
    for (const auto& piece : hub_)
        for (double h : heights(frame_, piece.surface, r, hubOfRevolution_ ? 0.0 : middleTheta(r)))
            if (h < top) best = std::max(best, h);
    z = best;
    return best > -1e300;
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
    auto nearestTo = [&](double g, double& best) {
        best = 1e300;
        double theta = g;
        if (hit.IsDone())
            for (int i = 1; i <= hit.NbPoints(); ++i) {
                const double t = frame_.theta(vec(hit.Point(i)));
                const double d = std::abs(wrapAngle(t - g));
                if (d < best) best = d, theta = g + wrapAngle(t - g);
            }
        return theta;
    };
    double best;
    double theta = nearestTo(guess, best);
    if (best > 0.5) {
        // A strongly wrapped blade turns further than that from one station to the next: the
        // wall's own point nearest in radius and height is the guess then.
        double near = 1e300, g = guess;
        for (const auto& p : w.samples) {
            const double d = std::hypot(frame_.radius(p) - r, frame_.axial(p) - z);
            if (d < near) near = d, g = frame_.theta(p);
        }
        theta = nearestTo(guess + wrapAngle(g - guess), best);
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
    const HubPiece& h = hubAt(p);
    return footAndNormal(*h.projection, h.surface, h.face, p, "the hub", u, v, on, du, dv);
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
    const HubPiece& h = hubAt(p);
    normal = footAndNormal(*h.projection, h.surface, h.face, p, "the hub", u, v, on, du, dv);
    return (p - vec(on)).dot(normal);
}

}  // namespace aeronc::impellerpath
