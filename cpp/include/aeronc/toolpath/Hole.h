#pragma once
// A round hole along the tool axis, in the setup frame.
#include <aeronc/toolpath/Toolpath.h>

namespace aeronc::toolpath {

struct Hole {
    Point centre;
    double diameter = 0;
    double top = 0, bottom = 0;  // bottom: where the full diameter ends
    bool through = false;        // the cutter breaks through below bottom
    // Blind holes: the fillet between wall and floor, which a milling cutter keeps out of.
    double floorFilletRadius = 0;
};

}  // namespace aeronc::toolpath
