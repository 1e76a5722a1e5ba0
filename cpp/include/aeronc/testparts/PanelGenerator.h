#pragma once
// Generator of integral-panel test parts with the ground truth it knows by construction.
#include <aeronc/core/Vec3.h>

#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace aeronc::testparts {

struct PanelSpec {
    int pocketsX = 3, pocketsY = 2;   // grid of pockets on the +Z side
    double pitch = 60;                // cell size, mm
    double ribThickness = 4;
    double border = 12;               // frame around the grid
    double thickness = 20;            // panel height (z from 0 to thickness)
    double webZ = 8;                  // floor height of +Z pockets
    double cornerRadius = 6;          // vertical corner fillet of pockets
    double floorFillet = 0;           // floor fillet radius of +Z pockets (0: none)
    bool lowerRibs = true;            // lower some ribs (differing rib heights)
    double lowerRibBy = 5;
    bool islands = true;              // boss in some pockets
    bool openings = true;             // rectangular through windows in some floors
    bool lighteningHoles = true;      // round through holes in some floors
    double lighteningDiameter = 0;    // their diameter; 0: min(20, 0.4 x pocket width)
    bool boltHoles = true;            // holes in the border, some counterbored / countersunk
    bool joggles = true;              // a shallow step in some floors
    bool flange = true;               // the border lowered along one edge: an open pocket
    bool bottomPockets = true;        // pockets on the -Z side
    double bottomDepth = 6;           // depth of -Z pockets from z = 0
};

// One expected domain element.
struct TruthElement {
    int id = -1;
    std::string type;     // closed_pocket | open_pocket | opening | hole
    int setup = 0;        // 0: +Z, 1: -Z
    Vec3 point{0, 0, 0};  // a point inside the element's region, just above its floor
    double level = 0;     // floor height along the setup direction (opening/through hole:
                          // the part bottom along it)
    int parent = -1;      // truth id, -1 for root
    int islands = 0;
    double diameter = 0;  // holes
    bool through = false;
    double counterboreDiameter = 0;
    double countersinkDiameter = 0;
    std::string note;     // what it is in the panel (pocket, rib-top region, bolt hole...)
};

struct Panel {
    TopoDS_Shape shape;
    std::vector<TruthElement> truth;
};

Panel makePanel(const PanelSpec& spec);

// Ground truth as JSON text, for files written next to a generated STEP.
std::string truthToJson(const Panel& panel);

}  // namespace aeronc::testparts
