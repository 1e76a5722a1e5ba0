// Names of element types and face roles, as the JSON and the FreeCAD side spell them.
#include <aeronc/recognition/DomainTree.h>

namespace aeronc::recognition {

const char* toString(ElementType t) {
    switch (t) {
        case ElementType::ClosedPocket: return "closed_pocket";
        case ElementType::OpenPocket: return "open_pocket";
        case ElementType::Opening: return "opening";
        case ElementType::Hole: return "hole";
    }
    return "?";
}

const char* toString(FaceRole r) {
    switch (r) {
        case FaceRole::Unclaimed: return "unclaimed";
        case FaceRole::Floor: return "floor";
        case FaceRole::Wall: return "wall";
        case FaceRole::IslandWall: return "island_wall";
        case FaceRole::HoleWall: return "hole_wall";
        case FaceRole::FloorFillet: return "floor_fillet";
        case FaceRole::CornerFillet: return "corner_fillet";
        case FaceRole::Chamfer: return "chamfer";
        case FaceRole::OpenBevel: return "open_bevel";
        case FaceRole::ClosedBevel: return "closed_bevel";
        case FaceRole::RibTop: return "rib_top";
        case FaceRole::CounterboreFloor: return "counterbore_floor";
        case FaceRole::Countersink: return "countersink";
        case FaceRole::Top: return "top";
        case FaceRole::Stock: return "stock";
    }
    return "?";
}

}  // namespace aeronc::recognition
