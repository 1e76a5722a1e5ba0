#pragma once
// The part as Z-dexels: for each cell centre, the intervals of Z inside the part along the
// vertical line, each end tagged with the face it lies on.
#include <aeronc/verify/Grid.h>
#include <aeronc/core/TriangleMesh.h>

#include <cstdint>
#include <vector>

namespace aeronc::verify {

// One interval of material along a cell's vertical line. At each end: the 1-based face it lies
// on and |nz|, the vertical component of that face's unit normal there (1 on a floor).
struct PartSpan {
    double z0 = 0, z1 = 0;
    int face0 = 0, face1 = 0;
    float nz0 = 1, nz1 = 1;
};

class PartDexels {
public:
    Grid grid;
    std::vector<std::uint32_t> offsets;  // cells + 1 entries: spans of cell c are [offsets[c], offsets[c + 1])
    std::vector<PartSpan> spans;         // ascending z in each cell
    // Cells whose line met the mesh inconsistently (an exit before an entry, or an entry never
    // closed): a mesh that is not closed. Their spans are the best pairing found.
    std::size_t inconsistentColumns = 0;

    const PartSpan* begin(std::size_t c) const { return spans.data() + offsets[c]; }
    const PartSpan* end(std::size_t c) const { return spans.data() + offsets[c + 1]; }
    bool empty(std::size_t c) const { return offsets[c] == offsets[c + 1]; }
    // The volume of the dexels: the lengths of all spans times the cell area.
    double volume() const;
};

// Casts a vertical line through every cell centre of `grid` and pairs the crossings by the
// triangles' facing (a triangle facing down starts material going up, one facing up ends it),
// so touching or overlapping shells merge. A line through a shared edge or vertex counts it
// once: the test is exact for edges given by the same two vertices, with a fixed tie rule
// (a point on an edge belongs to the triangle on one side only). Triangles standing vertical
// are never crossed.
PartDexels rasterise(const TriangleMesh& mesh, const Grid& grid);

}  // namespace aeronc::verify
