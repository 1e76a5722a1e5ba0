#pragma once
// Known hole patterns on a flat and on a curved wing skin, and known distortions of them.
#include <aeronc/compensation/Compensation.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace aeronc::compensation::test {

constexpr double kPi = 3.14159265358979323846;

inline std::string datumId(int i) { return "DH" + std::to_string(i); }

// Rows of holes; every row has datum holes at both ends and in the middle.
struct Pattern {
    std::string name;
    std::vector<Vec3> points, normals;
    std::vector<std::vector<int>> rows;  // point indices in order along each row
    std::vector<int> datums;             // point indices of the datum holes
    std::vector<int> drilling;           // the other holes
};

inline void splitDatums(Pattern& p, const std::vector<int>& datumPlaces) {
    for (const auto& row : p.rows)
        for (size_t k = 0; k < row.size(); ++k) {
            const bool datum = std::find(datumPlaces.begin(), datumPlaces.end(), static_cast<int>(k)) != datumPlaces.end();
            (datum ? p.datums : p.drilling).push_back(row[k]);
        }
}

// A flat skin: rows along x at a 40 mm row pitch, holes every 25 mm.
inline Pattern flatSkin(int rows = 5, int holes = 21) {
    Pattern p{"flat skin", {}, {}, {}, {}, {}};
    for (int r = 0; r < rows; ++r) {
        p.rows.emplace_back();
        for (int k = 0; k < holes; ++k) {
            p.rows.back().push_back(static_cast<int>(p.points.size()));
            p.points.emplace_back(25.0 * k, 40.0 * r, 0.0);
            p.normals.emplace_back(0, 0, 1);
        }
    }
    splitDatums(p, {0, holes / 2, holes - 1});
    return p;
}

// A skin curved chordwise (a cylinder of radius 800 mm about the y axis): rows follow the
// curvature (arcs of 0.7 rad), 40 mm apart spanwise. Datum holes at the rows' ends and middle,
// or at `datumPlaces`.
inline Pattern curvedSkin(int rows = 5, int holes = 21, std::vector<int> datumPlaces = {}) {
    Pattern p{"curved skin", {}, {}, {}, {}, {}};
    const double radius = 800.0;
    for (int r = 0; r < rows; ++r) {
        p.rows.emplace_back();
        for (int k = 0; k < holes; ++k) {
            const double t = -0.35 + 0.7 * k / (holes - 1);
            p.rows.back().push_back(static_cast<int>(p.points.size()));
            p.points.emplace_back(radius * std::sin(t), 40.0 * r, radius * (std::cos(t) - 1.0));
            p.normals.emplace_back(std::sin(t), 0.0, std::cos(t));
        }
    }
    splitDatums(p, datumPlaces.empty() ? std::vector<int>{0, holes / 2, holes - 1} : datumPlaces);
    return p;
}

using Distortion = std::function<Vec3(const Vec3&)>;

struct NamedDistortion {
    std::string name;
    Distortion apply;
    bool linear;  // rigid, scale and affine are; bending is not
};

// Assembly and positioning errors of the sizes a wing panel sees (tenths of a millimetre to a
// millimetre over half a metre). The bending sags the skin between its ends, over the extent of
// the pattern `p`.
inline std::vector<NamedDistortion> distortions(const Pattern& p) {
    Vec3 lo = p.points.front(), hi = p.points.front();
    for (const auto& x : p.points) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    const Vec3 size = (hi - lo).cwiseMax(Vec3::Constant(1.0));
    const Mat3 rotation = Eigen::AngleAxisd(0.004, Vec3(0.3, -0.2, 1.0).normalized()).toRotationMatrix();
    const Vec3 pivot(250, 80, 0), shift(0.8, -0.5, 0.3);
    Mat3 affine;
    affine << 1.0008, 0.0012, 0.0, 0.0005, 0.9995, 0.0, 0.0003, -0.0004, 1.0;
    return {
        {"rigid offset", [=](const Vec3& x) { return Vec3(rotation * (x - pivot) + pivot + shift); }, true},
        {"scale", [=](const Vec3& x) { return Vec3(1.0006 * (x - pivot) + pivot + shift); }, true},
        {"affine", [=](const Vec3& x) { return Vec3(affine * (x - pivot) + pivot + shift); }, true},
        {"smooth bending",
         [=](const Vec3& x) {
             const double u = (x.x() - lo.x()) / size.x(), v = (x.y() - lo.y()) / size.y();
             return Vec3(x + Vec3(0.25 * std::sin(kPi * u) * (1 + v), 0.2 * v * v - 0.15 * u * u,
                                  0.8 * std::sin(kPi * u) + 0.3 * std::cos(kPi * v)) + shift);
         },
         false},
    };
}

inline std::vector<Datum> measuredDatums(const Pattern& p, const Distortion& d) {
    std::vector<Datum> out;
    for (int i : p.datums) {
        Datum x;
        x.id = datumId(i);
        x.nominal = p.points[static_cast<size_t>(i)];
        x.measured = d(x.nominal);
        x.normal = p.normals[static_cast<size_t>(i)];
        out.push_back(x);
    }
    return out;
}

// Camera noise: every measured coordinate off by a normal variate of `sigma` mm; the same
// numbers for the same seed on every platform (Box-Muller over mt19937, whose sequence the
// standard fixes).
inline void addNoise(std::vector<Datum>& datums, double sigma, std::uint32_t seed) {
    std::mt19937 rng(seed);
    auto uniform = [&] { return (static_cast<double>(rng()) + 0.5) / 4294967296.0; };
    for (auto& d : datums)
        for (int c = 0; c < 3; ++c) {
            const double u = uniform(), v = uniform();
            d.measured[c] += sigma * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * kPi * v);
        }
}

// The curved skin of the misread-datum checks: 5 rows of 41 holes, datum holes every tenth hole
// (25 datum holes, 180 to drill), the assembly offset by (0.5, -0.3, 0.2) mm.
inline Pattern fiveByFortyOne() { return curvedSkin(5, 41, {0, 10, 20, 30, 40}); }
inline Vec3 assemblyOffset(const Vec3& x) { return x + Vec3(0.5, -0.3, 0.2); }

// The direction along the row at hole i of a curved skin (its rows run chordwise), and across it.
inline Vec3 alongRow(const Pattern& p, int i) {
    const Vec3& n = p.normals[static_cast<size_t>(i)];
    return Vec3(n.z(), 0.0, -n.x());
}
inline Vec3 acrossRow() { return Vec3::UnitY(); }

// The camera misreads datum hole i by `off`.
inline void misread(std::vector<Datum>& datums, int i, const Vec3& off) {
    for (auto& d : datums)
        if (d.id == datumId(i)) d.measured += off;
}

inline std::vector<NominalHole> drillingHoles(const Pattern& p) {
    std::vector<NominalHole> out;
    for (int i : p.drilling) {
        NominalHole h;
        h.id = "H" + std::to_string(i);
        h.position = p.points[static_cast<size_t>(i)];
        h.normal = p.normals[static_cast<size_t>(i)];
        out.push_back(h);
    }
    return out;
}

// RMS and largest distance between the compensated holes and where the distortion put them.
struct HoleError {
    double rms = 0.0, max = 0.0;
};

inline HoleError holeError(const CompensationResult& r, const Distortion& d) {
    HoleError e;
    for (const auto& h : r.holes) {
        const double x = (h.compensated - d(h.nominal)).norm();
        e.rms += x * x;
        e.max = std::max(e.max, x);
    }
    e.rms = std::sqrt(e.rms / static_cast<double>(r.holes.size()));
    return e;
}

}  // namespace aeronc::compensation::test
