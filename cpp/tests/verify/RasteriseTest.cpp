// Rasterising triangle meshes into Z-dexels: exact columns for known solids, shared edges and
// vertices counted once, face tags at the span ends.
#include <aeronc/verify/PartDexels.h>

#include "../ErrorOf.h"
#include "Fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace aeronc;
using namespace aeronc::verify;
using namespace aeronc::verify::test;

namespace {

Grid gridOf(double x0, double y0, double cell, int nx, int ny) {
    Grid g;
    g.x0 = x0, g.y0 = y0, g.cell = cell, g.nx = nx, g.ny = ny;
    return g;
}

bool insidePolygon(const std::vector<std::array<double, 2>>& poly, double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i][1] > y) != (poly[j][1] > y) &&
            x < (poly[j][0] - poly[i][0]) * (y - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0])
            in = !in;
    return in;
}

}  // namespace

TEST(Rasterise, PocketedPlateHasTheRightColumnEverywhere) {
    const PocketSpec p{10, 10, 50, 30, 4, 8};
    const Plate plate = makePlate(60, 40, 20, {p});
    double pocketArea = 0;  // of the outline as meshed, its arcs as polygons
    const auto& o = plate.outlines[0];
    for (std::size_t k = 0; k < o.size(); ++k)
        pocketArea += 0.5 * (o[k][0] * o[(k + 1) % o.size()][1] - o[(k + 1) % o.size()][0] * o[k][1]);
    EXPECT_NEAR(pocketArea, 40 * 20 - (4 - M_PI) * 16, 0.05);
    ASSERT_NEAR(signedVolume(plate.mesh), 60 * 40 * 20 - pocketArea * 12, 1e-6);

    const Grid g = gridCovering(0, 0, 60, 40, 0.5);
    const PartDexels d = rasterise(plate.mesh, g);
    EXPECT_EQ(d.inconsistentColumns, 0u);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t c = g.index(i, j);
            ASSERT_EQ(d.end(c) - d.begin(c), 1) << i << " " << j;
            const PartSpan& s = *d.begin(c);
            const bool inPocket = insidePolygon(plate.outlines[0], g.centreX(i), g.centreY(j));
            EXPECT_DOUBLE_EQ(s.z0, 0);
            EXPECT_EQ(s.face0, plate.bottom);
            EXPECT_NEAR(s.z1, inPocket ? 8 : 20, 1e-12);
            EXPECT_EQ(s.face1, inPocket ? plate.pockets[0].floor : plate.top);
            EXPECT_FLOAT_EQ(s.nz1, 1.f);
        }
    EXPECT_NEAR(d.volume(), signedVolume(plate.mesh), 0.01 * signedVolume(plate.mesh));
}

TEST(Rasterise, LinesThroughSharedEdgesAndVerticesCountOnce) {
    // Cell centres on the integer lattice: they fall on the plate's outer edges, on the pocket's
    // walls and on the diagonals that split every rectangle into two triangles.
    const PocketSpec p{10, 10, 50, 30, 0, 8};
    const Plate plate = makePlate(60, 40, 20, {p});
    const Grid g = gridOf(-0.5, -0.5, 1, 61, 41);
    const PartDexels d = rasterise(plate.mesh, g);
    EXPECT_EQ(d.inconsistentColumns, 0u);
    std::size_t full = 0, pocket = 0;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t c = g.index(i, j);
            const double x = g.centreX(i), y = g.centreY(j);
            ASSERT_LE(d.end(c) - d.begin(c), 1) << x << " " << y;
            if (d.empty(c)) continue;
            const double top = d.begin(c)->z1;
            ASSERT_TRUE(top == 20 || top == 8) << x << " " << y;
            ++(top == 20 ? full : pocket);
        }
    // A point on a boundary belongs to one side only: edges running down or along +x are owned,
    // so the plate holds x in [0, 60), y in [0, 40) and the pocket x in [10, 50), y in [10, 30).
    EXPECT_EQ(full + pocket, 60u * 40u);
    EXPECT_EQ(pocket, 40u * 20u);
}

TEST(Rasterise, OverhangGivesTwoSpans) {
    // Two shells in one mesh: a slab at z 0..5 and a smaller plate floating at z 10..12.
    TriangleMesh m;
    auto box = [&](double x0, double y0, double z0, double x1, double y1, double z1, int face) {
        const double P[8][3] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                                {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
        int v[8];
        for (int k = 0; k < 8; ++k) v[k] = m.addVertex(P[k][0], P[k][1], P[k][2]);
        const int q[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        for (auto& f : q) {
            m.addTriangle(v[f[0]], v[f[1]], v[f[2]], face);
            m.addTriangle(v[f[0]], v[f[2]], v[f[3]], face);
        }
    };
    box(0, 0, 0, 10, 10, 5, 1);
    box(2, 2, 10, 8, 8, 12, 2);
    const Grid g = gridCovering(0, 0, 10, 10, 0.5);
    const PartDexels d = rasterise(m, g);
    EXPECT_EQ(d.inconsistentColumns, 0u);
    const std::size_t c = g.index(10, 10);
    ASSERT_EQ(d.end(c) - d.begin(c), 2);
    EXPECT_DOUBLE_EQ(d.begin(c)[0].z1, 5);
    EXPECT_DOUBLE_EQ(d.begin(c)[1].z0, 10);
    EXPECT_EQ(d.begin(c)[1].face0, 2);
    EXPECT_NEAR(d.volume(), 10 * 10 * 5 + 6 * 6 * 2, 1e-9);
}

TEST(Rasterise, OpenMeshIsReportedNotHidden) {
    PocketSpec p{10, 10, 50, 30, 4, 8};
    Plate plate = makePlate(60, 40, 20, {p});
    // Drop the pocket floor: lines through the pocket now leave the part without entering it
    // again.
    TriangleMesh open;
    open.vertices = plate.mesh.vertices;
    for (std::size_t t = 0; t < plate.mesh.triangles.size(); ++t)
        if (plate.mesh.faces[t] != plate.pockets[0].floor)
            open.addTriangle(plate.mesh.triangles[t][0], plate.mesh.triangles[t][1], plate.mesh.triangles[t][2],
                             plate.mesh.faces[t]);
    const Grid g = gridCovering(0, 0, 60, 40, 0.5);
    const PartDexels d = rasterise(open, g);
    std::size_t inPocket = 0;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) inPocket += insidePolygon(plate.outlines[0], g.centreX(i), g.centreY(j));
    EXPECT_EQ(d.inconsistentColumns, inPocket);
}

TEST(Rasterise, RejectsBrokenMeshes) {
    using aeronc::test::inputErrorOf;
    TriangleMesh m;
    EXPECT_NE(inputErrorOf([&] { rasterise(m, gridCovering(0, 0, 1, 1, 0.5)); }).find("no triangles"),
              std::string::npos);
    m.addVertex(0, 0, 0), m.addVertex(1, 0, 0), m.addVertex(0, 1, 0);
    m.addTriangle(0, 1, 7, 1);
    EXPECT_NE(inputErrorOf([&] { rasterise(m, gridCovering(0, 0, 1, 1, 0.5)); }).find("vertex 7"),
              std::string::npos);
    m.triangles[0][2] = 2;
    m.vertices[1][0] = NAN;
    EXPECT_NE(inputErrorOf([&] { rasterise(m, gridCovering(0, 0, 1, 1, 0.5)); }).find("not finite"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([] { gridCovering(0, 0, 10000, 10000, 0.001); }).find("larger cell size"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([] { gridCovering(0, 0, 1, 1, 0); }).find("cell size"), std::string::npos);
}
