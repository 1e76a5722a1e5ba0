// Recognition on parts nobody here made: the NIST CTC/FTC test parts (shared/data/nist) and
// the milled parts of shared/data/real.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/HoleTruth.h>

#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>

using namespace aeronc;
using namespace aeronc::recognition;

namespace {

std::vector<std::string> partsIn(const char* folder) {
    std::vector<std::string> out;
    const std::filesystem::path dir = std::filesystem::path(AERONC_SHARED_DATA) / folder;
    if (!std::filesystem::exists(dir)) return out;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".stp") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}
std::vector<std::string> nistParts() { return partsIn("nist"); }
std::vector<std::string> realParts() { return partsIn("real"); }

// Every hole wall by geometry (a concave cylinder whose coaxial faces cover more than half the
// circle) has the role hole_wall, and 95 % of the hole walls found are such: recall and
// precision of hole recognition on one part.
void expectHolesFound(const TopoDS_Shape& part, const DomainTree& t) {
    const std::vector<bool> truth = testparts::holeWallsByGeometry(part);
    ASSERT_EQ(truth.size(), t.faceRoles.size());
    int holes = 0, found = 0, right = 0;
    std::string missed;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const bool wall = t.faceRoles[i] == FaceRole::HoleWall;
        holes += truth[i], found += wall, right += truth[i] && wall;
        if (truth[i] && !wall) missed += " Face" + std::to_string(i + 1) + " (" + toString(t.faceRoles[i]) + ")";
    }
    EXPECT_GE(right, 0.95 * holes) << right << " of " << holes << " hole walls found; missed:" << missed;
    EXPECT_GE(right, 0.95 * found) << right << " of " << found << " faces called hole walls are";
}

std::map<std::string, int> countTypes(const DomainTree& t) {
    std::map<std::string, int> c;
    for (const DomainElement& e : t.elements) c[toString(e.type)]++;
    return c;
}

}  // namespace

class NistPart : public ::testing::TestWithParam<std::string> {};

TEST_P(NistPart, RecognisedWithoutErrorAndNoFaceClaimedTwice) {
    const TopoDS_Shape part = loadPart(GetParam());
    const DomainTree t = recognise(part);
    EXPECT_GT(t.elements.size(), 0u);
    // A floor belongs to one element and is nobody's wall; a wall face may bound several
    // pockets (a pocket and the deeper one under it, or two regions either side of a notch).
    std::map<int, int> floorOwner;
    std::set<int> walls;
    for (const DomainElement& e : t.elements) {
        for (int f : e.floorFaces) {
            EXPECT_EQ(floorOwner.count(f), 0u) << "face " << f << " is the floor of two elements";
            floorOwner[f] = e.id;
        }
        walls.insert(e.contourFaces.begin(), e.contourFaces.end());
        for (auto& isl : e.islandFaces) walls.insert(isl.begin(), isl.end());
    }
    for (int f : walls) EXPECT_EQ(floorOwner.count(f), 0u) << "face " << f << " is both a floor and a wall";
    // One role per face, and the element that claims it lists it.
    ASSERT_EQ(t.faceRoles.size(), static_cast<std::size_t>(t.faceCount));
    for (std::size_t i = 0; i < t.faceRoles.size(); ++i) {
        const int el = t.faceElement[i];
        if (el < 0) continue;
        const DomainElement& e = t.elements[static_cast<std::size_t>(el)];
        const int f = static_cast<int>(i) + 1;
        bool listed = std::count(e.floorFaces.begin(), e.floorFaces.end(), f) ||
                      std::count(e.contourFaces.begin(), e.contourFaces.end(), f) ||
                      std::count(e.filletFaces.begin(), e.filletFaces.end(), f) ||
                      std::count(e.chamferFaces.begin(), e.chamferFaces.end(), f);
        for (auto& isl : e.islandFaces) listed |= std::count(isl.begin(), isl.end(), f) > 0;
        for (auto& a : e.attached) listed |= std::count(a.faces.begin(), a.faces.end(), f) > 0;
        EXPECT_TRUE(listed) << "face " << f << " claimed by element " << el << " that does not list it";
    }
    // Every face of every hole found is a cylinder wall of that hole's diameter.
    for (const DomainElement& e : t.elements)
        if (e.hole) EXPECT_GT(e.hole->diameter, 0);
    expectHolesFound(part, t);
}

TEST_P(NistPart, StableUnderRotation) {
    const TopoDS_Shape part = loadPart(GetParam());
    gp_Trsf rot;
    rot.SetRotation(gp_Ax1(gp_Pnt(10, -20, 5), gp_Dir(0.3, -0.5, 0.81)), 0.9);
    const DomainTree a = recognise(part);
    const DomainTree b = recognise(validatedSolid(part.Moved(TopLoc_Location(rot)), "rotated"));
    EXPECT_EQ(countTypes(a), countTypes(b));
    EXPECT_EQ(a.setups.size(), b.setups.size());
    std::map<std::string, int> ra, rb;
    for (FaceRole r : a.faceRoles) ra[toString(r)]++;
    for (FaceRole r : b.faceRoles) rb[toString(r)]++;
    EXPECT_EQ(ra, rb);
}

INSTANTIATE_TEST_SUITE_P(Nist, NistPart, ::testing::ValuesIn(nistParts()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                             return std::filesystem::path(i.param).stem().string();
                         });

class MilledPart : public ::testing::TestWithParam<std::string> {};

TEST_P(MilledPart, EveryHoleFound) {
    const TopoDS_Shape part = loadPart(GetParam());
    expectHolesFound(part, recognise(part));
}

INSTANTIATE_TEST_SUITE_P(Real, MilledPart, ::testing::ValuesIn(realParts()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                             return std::filesystem::path(i.param).stem().string();
                         });
