#include <aeronc/core/Error.h>
#include <aeronc/brep/ShapeMesh.h>

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <string>

namespace aeronc {

TriangleMesh meshShape(const TopoDS_Shape& shape, double deflection, double angularDeflection) {
    if (shape.IsNull()) throw inputError("no shape to mesh");
    if (!(deflection > 0) || !(angularDeflection > 0))
        throw inputError("the mesh deflections must be positive");
    BRepMesh_IncrementalMesh mesher(shape, deflection, false, angularDeflection, true);
    if (!mesher.IsDone()) throw geometryError("OCCT could not mesh the part");

    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    TriangleMesh mesh;
    for (int f = 1; f <= faces.Extent(); ++f) {
        const TopoDS_Face& face = TopoDS::Face(faces(f));
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
        if (tri.IsNull() || tri->NbTriangles() == 0)
            throw geometryError("face " + std::to_string(f) + " of the part could not be meshed");
        const gp_Trsf trsf = loc.Transformation();
        const int base = int(mesh.vertices.size());
        for (int k = 1; k <= tri->NbNodes(); ++k) {
            const gp_Pnt p = tri->Node(k).Transformed(trsf);
            mesh.addVertex(p.X(), p.Y(), p.Z());
        }
        // A reversed face's triangles wind the other way round its outward normal.
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        for (int k = 1; k <= tri->NbTriangles(); ++k) {
            int a, b, c;
            tri->Triangle(k).Get(a, b, c);
            if (reversed) std::swap(b, c);
            mesh.addTriangle(base + a - 1, base + b - 1, base + c - 1, f);
        }
    }
    // A solid stored inside out still gives the right dexels once turned outward.
    if (signedVolume(mesh) < 0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

}  // namespace aeronc
