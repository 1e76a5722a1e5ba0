#pragma once
// How much material is left on the faces the plan says are finished, after the program ran.
//
// Floors, and every face not standing near vertical, are measured at the ends of the part's
// dexels: the stock between that end and the next part span (above a face looking up, below
// one looking down), times |nz| so that it reads as a thickness along the face normal.
// Walls (faces whose normal is within about 11.5 degrees of horizontal) have no dexel ends: they
// are sampled every half cell along their length, in bands that split the face's height evenly
// (about wallBand each), and from each sample the cells are walked along the wall's normal while
// more than half of the band beside the wall is still stock; the thickness left is the distance
// walked, to within one cell. Material thinner than half a band (a floor's leftover at the foot
// of the wall) does not count as the wall's.
#include <aeronc/verify/PartDexels.h>
#include <aeronc/verify/StockDexels.h>
#include <aeronc/core/TriangleMesh.h>

#include <string>
#include <utility>
#include <vector>

namespace aeronc::verify {

struct CoverageOptions {
    double floorTolerance = 0.2;  // mm of material allowed on a finished floor
    double wallTolerance = 0.2;   // mm on a finished wall (found to within one cell)
    double wallSearch = 25;       // mm walked away from a wall at most
    double wallBand = 0;          // height of a wall band; 0: twice the cell size
};

struct FaceCoverage {
    int face = 0;
    double floorArea = 0, wallArea = 0;  // measured surface (mm^2)
    double uncoveredArea = 0;            // of which material is left beyond the tolerance
    double maxLeftover = 0;              // mm, the thickest left
    bool measured() const { return floorArea + wallArea > 0; }
};

struct ElementCoverage {
    std::string id;
    std::vector<int> faces;
    double area = 0, uncoveredArea = 0, maxLeftover = 0;
};

struct CoverageReport {
    CoverageOptions options;
    std::vector<FaceCoverage> faces;
    std::vector<ElementCoverage> elements;
};

// Coverage of `faces` (1-based) and of each element's faces.
CoverageReport measureCoverage(const TriangleMesh& mesh, const PartDexels& part, const StockDexels& stock,
                               const std::vector<int>& faces,
                               const std::vector<std::pair<std::string, std::vector<int>>>& elements,
                               const CoverageOptions& options);

}  // namespace aeronc::verify
