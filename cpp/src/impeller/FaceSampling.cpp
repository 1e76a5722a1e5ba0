#include <aeronc/impeller/FaceSampling.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <gp_Pnt2d.hxx>

namespace aeronc::impeller {

std::vector<gp_Pnt> pointsInsideFace(const TopoDS_Face& face, int nu, int nv) {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    BRepAdaptor_Surface s(face);
    BRepTopAdaptor_FClass2d inside(face, 1e-7);
    std::vector<gp_Pnt> out;
    for (int i = 0; i <= nu; ++i)
        for (int j = 0; j <= nv; ++j) {
            const gp_Pnt2d uv(u0 + (u1 - u0) * i / nu, v0 + (v1 - v0) * j / nv);
            if (inside.Perform(uv) == TopAbs_IN) out.push_back(s.Value(uv.X(), uv.Y()));
        }
    return out;
}

}  // namespace aeronc::impeller
