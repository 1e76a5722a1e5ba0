#include <aeronc/core/Error.h>
#include <aeronc/core/TriangleMesh.h>

#include <cmath>
#include <string>

namespace aeronc {

int TriangleMesh::addVertex(double x, double y, double z) {
    vertices.push_back({x, y, z});
    return int(vertices.size()) - 1;
}

void TriangleMesh::addTriangle(int a, int b, int c, int face) {
    triangles.push_back({a, b, c});
    faces.push_back(face);
}

double signedVolume(const TriangleMesh& mesh) {
    double v = 0;
    for (const auto& t : mesh.triangles) {
        const auto& a = mesh.vertices[t[0]];
        const auto& b = mesh.vertices[t[1]];
        const auto& c = mesh.vertices[t[2]];
        v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
             a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return v / 6;
}

std::array<double, 6> bounds(const TriangleMesh& mesh) {
    if (mesh.vertices.empty()) throw inputError("the part mesh has no vertices");
    std::array<double, 6> b{HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const auto& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) {
            b[k] = std::min(b[k], p[k]);
            b[k + 3] = std::max(b[k + 3], p[k]);
        }
    return b;
}

void validate(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) throw inputError("the part mesh has no triangles");
    if (mesh.faces.size() != mesh.triangles.size())
        throw inputError("the part mesh has " + std::to_string(mesh.faces.size()) + " face tags for " +
                         std::to_string(mesh.triangles.size()) + " triangles");
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        for (double x : mesh.vertices[v])
            if (!std::isfinite(x)) throw inputError("vertex " + std::to_string(v) + " of the part mesh is not finite");
    const int n = int(mesh.vertices.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k : mesh.triangles[t])
            if (k < 0 || k >= n)
                throw inputError("triangle " + std::to_string(t) + " of the part mesh refers to vertex " +
                                 std::to_string(k) + " of " + std::to_string(n));
}

}  // namespace aeronc
