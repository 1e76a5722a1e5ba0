// Hole recall and precision per part against holes by geometry (testparts::holeWallsByGeometry:
// concave cylinders whose coaxial faces cover more than half the circle). A face counts as
// found when recognition gives it the role hole_wall.
// Usage: aeronc_hole_eval PART.step... (automatic setup directions)
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/HoleTruth.h>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    std::printf("# hole walls: truth by geometry vs role hole_wall (automatic setups)\n");
    std::printf("# %-28s %6s %6s %6s %6s %8s %9s\n", "part", "faces", "truth", "found", "right", "recall", "precision");
    long truthAll = 0, foundAll = 0, rightAll = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string path = argv[i];
        try {
            const TopoDS_Shape solid = aeronc::loadPart(path);
            const std::vector<bool> truth = aeronc::testparts::holeWallsByGeometry(solid);
            const auto tree = aeronc::recognition::recognise(solid);
            long t = 0, f = 0, r = 0;
            for (std::size_t k = 0; k < truth.size(); ++k) {
                const bool found = tree.faceRoles[k] == aeronc::recognition::FaceRole::HoleWall;
                t += truth[k], f += found, r += truth[k] && found;
            }
            truthAll += t, foundAll += f, rightAll += r;
            if (std::getenv("AERONC_HOLE_MISSES"))
                for (std::size_t k = 0; k < truth.size(); ++k)
                    if (truth[k] != (tree.faceRoles[k] == aeronc::recognition::FaceRole::HoleWall))
                        std::printf("    Face%zu %s: %s\n", k + 1, truth[k] ? "missed" : "not a hole",
                                    aeronc::recognition::toString(tree.faceRoles[k]));
            std::printf("  %-28s %6zu %6ld %6ld %6ld %8.3f %9.3f\n",
                        std::filesystem::path(path).filename().string().c_str(), truth.size(), t, f, r,
                        t ? double(r) / t : 1.0, f ? double(r) / f : 1.0);
        } catch (const std::exception& e) {
            std::printf("  %-28s error: %s\n", path.c_str(), e.what());
        }
        std::fflush(stdout);
    }
    std::printf("  %-28s %6s %6ld %6ld %6ld %8.3f %9.3f\n", "all", "", truthAll, foundAll, rightAll,
                truthAll ? double(rightAll) / truthAll : 1.0, foundAll ? double(rightAll) / foundAll : 1.0);
    return 0;
}
