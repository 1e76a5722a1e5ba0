#pragma once
// Sections the part with the plane h = const of a setup frame and joins the section
// edges into closed loops, each segment labelled with the face it came from.
#include <aeronc/recognition/SetupFrame.h>

#include "FaceCatalogue.h"
#include "MeshSection.h"

#include <string>
#include <vector>

namespace aeronc::recognition {

struct SectionLoop {
    std::vector<P2> pts;     // closed: last point != first; segment k = pts[k] -> pts[k+1]
    std::vector<int> faces;  // face (0-based) of segment k
    double area = 0;         // signed (CCW > 0)
    P2 lo, hi;               // bounding box
    int depth = 0;           // nesting depth: even = material inside, odd = void inside
    int parent = -1;
};

// meshes: the section of faces the fast one does not handle (null: OCCT's general section).
std::vector<SectionLoop> sliceLoops(const FaceCatalogue& faces, const std::vector<int>& candidates,
                                    const SetupFrame& frame, double h, double chordTol, double linTol,
                                    std::vector<std::string>& warnings, MeshSection* meshes = nullptr);

bool pointInLoop(const SectionLoop& loop, const P2& p);

}  // namespace aeronc::recognition
