#pragma once
// The machining-domain tree: root -> setup directions -> domain elements.
// Faces are identified by their 1-based index in TopExp::MapShapes(solid, TopAbs_FACE)
// order, which is FreeCAD's "FaceN".
#include <aeronc/core/Vec3.h>

#include <optional>
#include <string>
#include <limits>
#include <vector>

namespace aeronc::recognition {

enum class ElementType { ClosedPocket, OpenPocket, Opening, Hole };
const char* toString(ElementType t);

// What one face is, for the element that claims it (or for the part).
enum class FaceRole {
    Unclaimed,
    Floor,           // bottom constraint face of a pocket
    Wall,            // contour side-wall face
    IslandWall,      // island side-wall face
    HoleWall,        // cylindrical wall of a hole
    FloorFillet,     // blend between floor and wall
    CornerFillet,    // concave vertical blend between two walls
    Chamfer,         // small inclined face on a wall edge
    OpenBevel,       // inclined wall leaning away from the pocket (open corner)
    ClosedBevel,     // inclined wall leaning over the pocket (closed corner)
    RibTop,          // up-facing face whose edges all fall away: top of a rib or island
    CounterboreFloor,
    Countersink,
    Top,             // top constraint face of the part (stock side)
    Stock,           // other faces of the part that no element machines
};
const char* toString(FaceRole r);

struct AttachedFeature {
    std::string kind;        // rib, island_top, flange, open_corner, closed_corner, joggle, floor_fillet,
                             // corner_fillet, chamfer, countersink
    std::vector<int> faces;  // FaceN of the faces forming it
    double radius = 0;       // fillet radius
    double size = 0;         // chamfer width, rib thickness, joggle depth, bevel angle (deg)
    // A chamfer: the included angle of the mill that cuts it (twice its angle to the tool axis),
    // degrees; 0 when its faces differ or face away from the setup. `size` is then its widest
    // width across the axis.
    double angle = 0;
    // A chamfer: the height of its lower line (where it meets the walls) along the setup's axis,
    // and whether it runs at one width along every wall of the element's outer loop and on no
    // island: then one pass along the loop's walls cuts it. Or the islands (0-based) along every
    // wall of which it runs so, none of the outer loop's walls meeting it: a pass round each.
    double lower = 0;
    bool alongContour = false;
    std::vector<int> alongIslands;
    int element = -1;        // joggle: the child element forming it
};

struct HoleInfo {
    double diameter = 0;
    double depth = 0;
    bool through = false;
    Vec3 axis{0, 0, 1};      // points out of the hole, towards the tool
    Vec3 location{0, 0, 0};  // axis point at the hole's top
    double counterboreDiameter = 0;  // 0: none
    double counterboreDepth = 0;
    double countersinkDiameter = 0;  // 0: none
    double countersinkAngle = 0;     // included angle, degrees
    // Material stands within its mouth's circle along the axis beyond the mouth (a wall over
    // part of it): no tool as wide as the hole comes down to it from this side.
    bool overhung = false;
};

using Polyline = std::vector<Vec3>;

struct DomainElement {
    int id = -1;
    int setup = -1;
    int parent = -1;  // -1: directly under the setup direction
    std::vector<int> children;
    ElementType type = ElementType::ClosedPocket;

    double level = 0;  // floor height along the setup direction
    double top = 0;    // height of the top constraint
    double depth = 0;  // top - level
    double floorArea = 0;
    double area = 0;   // area of the pocket region at the slicing level
    double minWidth = 0;         // narrowest passage of the region
    double minCornerRadius = 0;  // smallest concave corner radius; 0 = sharp corner
    double floorFilletRadius = 0;

    std::vector<int> contourFaces;
    std::vector<std::vector<int>> islandFaces;  // one list per island loop
    std::vector<int> floorFaces;                // bottom constraint
    std::vector<int> topFaces;                  // top constraint
    std::vector<int> filletFaces;
    std::vector<int> chamferFaces;
    std::vector<std::pair<Vec3, Vec3>> openEdges;  // pieces of the contour open to the blank

    Polyline contour;               // corrected drive loop at the floor, world coordinates
    std::vector<Polyline> islands;  // island drive loops
    // Height of the material of each island (index as `islands`): below `top` for an island
    // that stops short of the pocket's top. Empty when not known (trees written before it).
    std::vector<double> islandTops;
    std::vector<AttachedFeature> attached;
    std::optional<HoleInfo> hole;
};

struct SetupDirection {
    int id = -1;
    Vec3 direction{0, 0, 1};  // tool axis, pointing from the part towards the spindle
    std::string name;         // "+Z", "-Z", or the vector
    std::vector<int> elements;  // roots of this setup's subtree
    // Height along `direction` of the blank's highest corner: what may stand over an element
    // before any cut. Not known (NaN) in trees written before it was kept.
    double blankTop = std::numeric_limits<double>::quiet_NaN();
};

struct DomainTree {
    int faceCount = 0;
    std::vector<SetupDirection> setups;
    std::vector<DomainElement> elements;
    std::vector<FaceRole> faceRoles;    // index FaceN-1
    std::vector<int> faceElement;       // index FaceN-1; -1 when no element claims it
    std::vector<int> unclaimedFaces;    // FaceN inside the blank that no element claims (also a warning)
    std::vector<int> leftOutFaces;      // FaceN of the shape's faces outside its solid (free faces, shells)
    std::vector<std::string> warnings;
};

}  // namespace aeronc::recognition
