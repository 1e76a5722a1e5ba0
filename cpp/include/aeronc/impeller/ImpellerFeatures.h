#pragma once
// Rule-based recognition of a centrifugal impeller (impeller paper §1, DESIGN.md §3).
// Faces are numbered 1-based in TopExp::MapShapes(shape, TopAbs_FACE) order (FreeCAD's FaceN).
#include <aeronc/core/Vec3.h>

#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace aeronc::impeller {

// One blade: its walls (pressure and suction sides, the leading and trailing edge rounds when
// the section has them), the root fillets round its foot and its shroud (blade tip) face.
struct Blade {
    bool splitter = false;
    int pressure = 0, suction = 0;    // the two largest walls; pressure faces the turning direction
    int leading = 0, trailing = 0;    // the other walls nearest to and farthest from the axis (0: none)
    std::vector<int> walls;           // every wall face, pressure and suction included
    std::vector<int> fillets;
    int shroud = 0;                   // the largest shroud face
    std::vector<int> shroudFaces;     // every shroud face (an exporter may give the tip several)
    double angleDeg = 0;              // angle of the shroud face's centroid about the axis
};

struct ImpellerFeatures {
    Vec3 axisPoint{0, 0, 0};
    Vec3 axisDirection{0, 0, 1};      // from the back of the hub towards the blade tips
    int bladeCount = 0;               // m: main blades (as many splitters, or none)
    int splitterCount = 0;
    int hub = 0;                      // the largest hub face
    std::vector<int> hubFaces;        // every hub face: one face of revolution, or a piece per channel
    int bore = 0;                     // the hole on the axis (0: none)
    std::vector<int> holes;           // other concave cylinders
    std::vector<int> planes;
    std::vector<int> turned;          // other single faces of revolution (rim, nose cones)
    std::vector<Blade> blades;        // in angular order about the axis (counter-clockwise)
    // Blades i and i + 1 (mod the blade total) are adjacent; closestPair is the pair whose shroud
    // faces are closest together, the first adjacent pair found (indices into blades).
    int closestPair[2] = {0, 1};
    double closestShroudDistance = 0;
    int faceCount = 0;
};

// Recognises the impeller in `shape` (one solid). The turning direction is counter-clockwise
// about axisDirection. Throws aeronc::inputError when the part is not an impeller (no face
// pattern repeated about an axis), when its blade groups are unequal (a blade missing or
// different), or when there is no hub (no face of revolution that every blade stands on).
ImpellerFeatures recogniseImpeller(const TopoDS_Shape& shape);

}  // namespace aeronc::impeller
