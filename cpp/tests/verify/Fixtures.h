#pragma once
// Parts and paths with known truth for the verification tests and bench: a plate with
// rectangular pockets (rounded corners), meshed by hand, and a pocketing path for a flat end
// mill that machines such a pocket completely.
#include <aeronc/verify/Program.h>
#include <aeronc/core/TriangleMesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace aeronc::verify::test {

struct PocketSpec {
    double x0, y0, x1, y1;  // the pocket's box
    double cornerRadius;    // of its vertical corners (0: sharp)
    double floorZ;
};

struct PocketFaces {
    int floor = 0;
    std::vector<int> walls;  // in order: bottom, corner, right, corner, top, corner, left, corner
};

struct Plate {
    TriangleMesh mesh;
    double width = 0, depth = 0, thickness = 0;
    int bottom = 1, top = 2;  // faces 3..6 are the outer sides
    std::vector<PocketFaces> pockets;
    // The pocket outlines as meshed, counter-clockwise.
    std::vector<std::vector<std::array<double, 2>>> outlines;
};

// The outline of a rounded pocket, counter-clockwise from (x0 + r, y0); side[k] is the wall of
// edge pts[k] -> pts[k + 1]: 0 bottom, 1 its corner, 2 right, 3 corner, 4 top, 5 corner, 6 left,
// 7 corner. Straight sides of zero length and corners of radius 0 are left out.
inline void pocketOutline(const PocketSpec& p, int arcSegments, std::vector<std::array<double, 2>>& pts,
                          std::vector<int>& side) {
    const double r = p.cornerRadius;
    // Straight side c runs from start[c] to end[c], then corner c turns to start[c + 1].
    const std::array<double, 2> start[4] = {{p.x0 + r, p.y0}, {p.x1, p.y0 + r}, {p.x1 - r, p.y1}, {p.x0, p.y1 - r}};
    const std::array<double, 2> end[4] = {{p.x1 - r, p.y0}, {p.x1, p.y1 - r}, {p.x0 + r, p.y1}, {p.x0, p.y0 + r}};
    const std::array<double, 2> centre[4] = {{p.x1 - r, p.y0 + r}, {p.x1 - r, p.y1 - r}, {p.x0 + r, p.y1 - r},
                                             {p.x0 + r, p.y0 + r}};
    std::vector<std::array<double, 2>> all;
    std::vector<int> tags;
    for (int c = 0; c < 4; ++c) {
        all.push_back(start[c]), tags.push_back(2 * c);
        if (r <= 0) continue;
        all.push_back(end[c]), tags.push_back(2 * c + 1);
        const double a0 = (c - 1) * M_PI / 2;
        for (int k = 1; k < arcSegments; ++k) {
            const double a = a0 + M_PI / 2 * k / arcSegments;
            all.push_back({centre[c][0] + r * std::cos(a), centre[c][1] + r * std::sin(a)});
            tags.push_back(2 * c + 1);
        }
    }
    pts.clear(), side.clear();
    for (std::size_t k = 0; k < all.size(); ++k) {
        const auto& a = all[k];
        const auto& b = all[(k + 1) % all.size()];
        if (a == b) continue;  // a straight side of zero length
        pts.push_back(a), side.push_back(tags[k]);
    }
}

// A plate [0, width] x [0, depth] x [0, thickness] with pockets from the top down to their
// floors. Pockets must not overlap nor touch the plate's border.
inline Plate makePlate(double width, double depth, double thickness, const std::vector<PocketSpec>& pockets,
                       int arcSegments = 24) {
    Plate plate;
    plate.width = width, plate.depth = depth, plate.thickness = thickness;
    TriangleMesh& m = plate.mesh;
    auto tri = [&](std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c, int face) {
        m.addTriangle(m.addVertex(a[0], a[1], a[2]), m.addVertex(b[0], b[1], b[2]), m.addVertex(c[0], c[1], c[2]),
                      face);
    };
    // Horizontal triangle facing up (or down) whatever the order given.
    auto flat = [&](std::array<double, 2> a, std::array<double, 2> b, std::array<double, 2> c, double z, bool up,
                    int face) {
        const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (area == 0) return;
        if ((area > 0) != up) std::swap(b, c);
        tri({a[0], a[1], z}, {b[0], b[1], z}, {c[0], c[1], z}, face);
    };
    // Vertical quad over edge p -> q, from z0 to z1, facing left of p -> q (or right).
    auto wall = [&](std::array<double, 2> p, std::array<double, 2> q, double z0, double z1, bool left, int face) {
        if (!left) std::swap(p, q);
        tri({q[0], q[1], z0}, {p[0], p[1], z0}, {p[0], p[1], z1}, face);
        tri({q[0], q[1], z0}, {p[0], p[1], z1}, {q[0], q[1], z1}, face);
    };
    const double W = width, H = depth, T = thickness;
    flat({0, 0}, {W, 0}, {W, H}, 0, false, plate.bottom);
    flat({0, 0}, {W, H}, {0, H}, 0, false, plate.bottom);
    const std::array<double, 2> box[4] = {{0, 0}, {W, 0}, {W, H}, {0, H}};
    for (int k = 0; k < 4; ++k) wall(box[k], box[(k + 1) % 4], 0, T, false, 3 + k);

    // Top: the plate minus the pockets' boxes, as rectangles between the boxes' x-coordinates...
    std::vector<double> xs = {0, W};
    for (const auto& p : pockets) xs.push_back(p.x0), xs.push_back(p.x1);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    for (std::size_t s = 0; s + 1 < xs.size(); ++s) {
        const double xa = xs[s], xb = xs[s + 1];
        std::vector<std::pair<double, double>> cut;
        for (const auto& p : pockets)
            if (p.x0 <= xa && p.x1 >= xb) cut.push_back({p.y0, p.y1});
        std::sort(cut.begin(), cut.end());
        double y = 0;
        cut.push_back({H, H});
        for (const auto& [ya, yb] : cut) {
            if (ya > y) {
                flat({xa, y}, {xb, y}, {xb, ya}, T, true, plate.top);
                flat({xa, y}, {xb, ya}, {xa, ya}, T, true, plate.top);
            }
            y = std::max(y, yb);
        }
    }
    // ... and each pocket: the corners of its box outside the rounded outline, floor, walls.
    int face = 7;
    for (const auto& p : pockets) {
        std::vector<std::array<double, 2>> pts;
        std::vector<int> side;
        pocketOutline(p, arcSegments, pts, side);
        PocketFaces f;
        f.floor = face++;
        int sideFace[8];
        for (int s = 0; s < 8; ++s) {
            const bool present = std::find(side.begin(), side.end(), s) != side.end();
            sideFace[s] = present ? face++ : 0;
            if (present) f.walls.push_back(sideFace[s]);
        }
        const std::array<double, 2> boxCorner[4] = {{p.x1, p.y0}, {p.x1, p.y1}, {p.x0, p.y1}, {p.x0, p.y0}};
        const std::array<double, 2> centre = {0.5 * (p.x0 + p.x1), 0.5 * (p.y0 + p.y1)};
        for (std::size_t k = 0; k < pts.size(); ++k) {
            const auto& a = pts[k];
            const auto& b = pts[(k + 1) % pts.size()];
            flat(centre, a, b, p.floorZ, true, f.floor);
            wall(a, b, p.floorZ, T, true, sideFace[side[k]]);
            if (side[k] % 2 == 1) flat(boxCorner[side[k] / 2], a, b, T, true, plate.top);
        }
        plate.pockets.push_back(f);
        plate.outlines.push_back(pts);
    }
    return plate;
}

// The plate turned upside down (z -> thickness - z): its pockets open downwards.
inline TriangleMesh mirroredInZ(const TriangleMesh& m, double thickness) {
    TriangleMesh out = m;
    for (auto& v : out.vertices) v[2] = thickness - v[2];
    for (auto& t : out.triangles) std::swap(t[1], t[2]);
    return out;
}

// A move [kind, x, y, z].
inline Move move(MoveKind kind, double x, double y, double z) {
    Move m;
    m.kind = kind, m.x = x, m.y = y, m.z = z;
    return m;
}

// Machines a rounded pocket with a flat end mill of radius R (R <= cornerRadius <= 3 R) at the
// height z: a plunge, zig-zag lines over the inner rectangle at `stepover`, then one pass round
// the outline at R from the walls, and a retract to safeZ.
inline std::vector<Move> pocketPath(const PocketSpec& p, double R, double stepover, double z, double safeZ,
                                    int arcSegments = 24) {
    std::vector<Move> out;
    const double r = p.cornerRadius;
    const double xa = p.x0 + r, xb = p.x1 - r, ya = p.y0 + r, yb = p.y1 - r;
    out.push_back(move(MoveKind::Rapid, xa, ya, safeZ));
    out.push_back(move(MoveKind::Plunge, xa, ya, z));
    const int lines = std::max(1, int(std::ceil((yb - ya) / stepover)));
    for (int k = 0; k <= lines; ++k) {
        const double y = ya + (yb - ya) * k / lines;
        const bool forward = k % 2 == 0;
        out.push_back(move(MoveKind::Feed, forward ? xa : xb, y, z));
        out.push_back(move(MoveKind::Feed, forward ? xb : xa, y, z));
    }
    // Round the outline offset by R (corner arcs of radius r - R about the same centres).
    const double rr = r - R;
    const std::array<double, 2> centres[4] = {{xb, ya}, {xb, yb}, {xa, yb}, {xa, ya}};
    out.push_back(move(MoveKind::Feed, xa, p.y0 + R, z));
    for (int c = 0; c < 4; ++c) {
        const double a0 = (c - 1) * M_PI / 2;
        for (int k = 0; k <= arcSegments; ++k) {
            const double a = a0 + M_PI / 2 * k / arcSegments;
            out.push_back(move(MoveKind::Feed, centres[c][0] + rr * std::cos(a), centres[c][1] + rr * std::sin(a), z));
        }
    }
    out.push_back(move(MoveKind::Feed, xa, p.y0 + R, z));
    out.push_back(move(MoveKind::Rapid, xa, p.y0 + R, safeZ));
    return out;
}

}  // namespace aeronc::verify::test
