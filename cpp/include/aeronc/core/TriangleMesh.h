#pragma once
// A part as triangles: what the verification rasterises. No CAD kernel here; brep/ShapeMesh.h
// makes one from an OCCT shape.
#include <array>
#include <vector>

namespace aeronc {

using Point3 = std::array<double, 3>;

// A closed, outward-oriented triangle mesh. Each triangle carries the 1-based index of the B-rep
// face it came from (FreeCAD's FaceN; 0 where unknown).
struct TriangleMesh {
    std::vector<Point3> vertices;
    std::vector<std::array<int, 3>> triangles;  // indices into vertices, counter-clockwise seen from outside
    std::vector<int> faces;                     // one per triangle

    int addVertex(double x, double y, double z);
    void addTriangle(int a, int b, int c, int face);
};

// The enclosed volume (positive for an outward-oriented closed mesh).
double signedVolume(const TriangleMesh& mesh);

// {xmin, ymin, zmin, xmax, ymax, zmax} of the vertices; throws for an empty mesh.
std::array<double, 6> bounds(const TriangleMesh& mesh);

// Throws aeronc::Error (input) for an empty mesh, indices out of range, a face list of the wrong
// length, or coordinates that are not finite.
void validate(const TriangleMesh& mesh);

}  // namespace aeronc
