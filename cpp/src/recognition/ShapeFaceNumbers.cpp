// The solid of a shape recognised, its faces numbered as the whole shape numbers them.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <string>
#include <vector>

namespace aeronc::recognition {
namespace {

// A FaceN of the solid (1-based) as FaceN of the shape; -1 stays -1.
struct FaceNumbers {
    std::vector<int> ofSolidFace;  // index: solid FaceN - 1
    int map(int f) const { return f >= 1 ? ofSolidFace[static_cast<std::size_t>(f - 1)] : f; }
    void map(std::vector<int>& v) const {
        for (int& f : v) f = map(f);
    }
};

void renumber(DomainTree& t, const FaceNumbers& n, int shapeFaceCount, const std::vector<int>& leftOut) {
    for (DomainElement& e : t.elements) {
        n.map(e.contourFaces), n.map(e.floorFaces), n.map(e.topFaces), n.map(e.filletFaces), n.map(e.chamferFaces);
        for (auto& isl : e.islandFaces) n.map(isl);
        for (AttachedFeature& a : e.attached) n.map(a.faces);
    }
    n.map(t.unclaimedFaces);
    std::vector<FaceRole> roles(static_cast<std::size_t>(shapeFaceCount), FaceRole::Stock);
    std::vector<int> owner(static_cast<std::size_t>(shapeFaceCount), -1);
    for (std::size_t i = 0; i < t.faceRoles.size(); ++i) {
        const std::size_t j = static_cast<std::size_t>(n.map(static_cast<int>(i) + 1) - 1);
        roles[j] = t.faceRoles[i];
        owner[j] = t.faceElement[i];
    }
    t.faceRoles = std::move(roles);
    t.faceElement = std::move(owner);
    t.faceCount = shapeFaceCount;
    t.leftOutFaces = leftOut;
}

}  // namespace

DomainTree recogniseShape(const TopoDS_Shape& shape, const std::string& origin, const RecogniseOptions& options) {
    const TopoDS_Shape solid = validatedSolid(shape, origin);
    DomainTree t = recognise(solid, options);
    TopTools_IndexedMapOfShape shapeFaces, solidFaces;
    TopExp::MapShapes(shape, TopAbs_FACE, shapeFaces);
    TopExp::MapShapes(solid, TopAbs_FACE, solidFaces);
    if (shapeFaces.Extent() == solidFaces.Extent()) {
        // The solid alone (or with wires and edges only): its own numbering is the shape's
        // when both list the faces in the same order.
        bool same = true;
        for (int i = 1; same && i <= solidFaces.Extent(); ++i) same = shapeFaces(i).IsSame(solidFaces(i));
        if (same) return t;
    }
    FaceNumbers n;
    n.ofSolidFace.resize(static_cast<std::size_t>(solidFaces.Extent()));
    std::vector<bool> inSolid(static_cast<std::size_t>(shapeFaces.Extent()), false);
    for (int i = 1; i <= solidFaces.Extent(); ++i) {
        const int j = shapeFaces.FindIndex(solidFaces(i));
        n.ofSolidFace[static_cast<std::size_t>(i - 1)] = j;
        inSolid[static_cast<std::size_t>(j - 1)] = true;
    }
    std::vector<int> leftOut;
    for (int j = 1; j <= shapeFaces.Extent(); ++j)
        if (!inSolid[static_cast<std::size_t>(j - 1)]) leftOut.push_back(j);
    renumber(t, n, shapeFaces.Extent(), leftOut);
    if (!leftOut.empty()) {
        std::string list;
        for (int f : leftOut) list += (list.empty() ? "Face" : ", Face") + std::to_string(f);
        t.warnings.push_back(origin + " holds " + std::to_string(leftOut.size()) +
                             (leftOut.size() == 1 ? " face" : " faces") +
                             " outside its solid (free faces or shells), left out of the recognition: " + list);
    }
    return t;
}

}  // namespace aeronc::recognition
