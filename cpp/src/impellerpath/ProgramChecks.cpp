// A program read back, checked: its cutting positions against the blades and the hub, its
// rapids against the blank (see ImpellerToolpaths.h).
#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include "ChannelGeometry.h"
#include "PassChecks.h"
#include "StockEnvelope.h"

#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>

#include <exception>
#include <thread>

namespace aeronc::impellerpath {

CheckResult checkProgram(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                         const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    const std::vector<TopoDS_Face> obstacles = partObstacles(faces, f);
    const std::vector<Handle(Geom_Surface)> hub = hubSurfaces(faces, f);
    // The cutting positions in program order, measured on two threads, each half with distance
    // queries of its own (they keep state); the halves merge in order, as one thread would.
    std::vector<std::pair<const CutterShape*, const Move*>> cuts;
    for (const auto& [cutter, moves] : operations)
        for (const auto& m : moves)
            if (!m.rapid) cuts.push_back({&cutter, &m});
    CheckResult half[2];
    std::exception_ptr error[2];
    auto work = [&](int part) {
        try {
            const Obstacles o(obstacles, hub);
            CheckResult& r = half[part];
            const size_t from = part == 0 ? 0 : cuts.size() / 2, to = part == 0 ? cuts.size() / 2 : cuts.size();
            for (size_t i = from; i < to; ++i) {
                const Move& m = *cuts[i].second;
                const Clearance c = clearance(o, *cuts[i].first, m.centre, m.axis);
                ++r.positions;
                if (c.holder) ++r.holderCollisions;
                r.minHolderGap = std::min(r.minHolderGap, c.holderGap);
                if (c.gouge > r.maxGouge) {
                    r.maxGouge = c.gouge;
                    r.worstAt[0] = m.centre.x(), r.worstAt[1] = m.centre.y(), r.worstAt[2] = m.centre.z();
                }
            }
        } catch (...) {
            error[part] = std::current_exception();
        }
    };
    std::thread second(work, 1);
    work(0);
    second.join();
    CheckResult r;
    for (int i = 0; i < 2; ++i) {
        if (error[i]) std::rethrow_exception(error[i]);
        merge(r, half[i]);
    }
    return r;
}

CheckResult checkRapids(const impeller::BlankProfile& blank, const impeller::ImpellerFeatures& f,
                        const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations, double clearance) {
    const StockEnvelope stock(blank, Frame(f));
    CheckResult r;
    for (const auto& [cutter, moves] : operations)
        for (size_t i = 0; i < moves.size(); ++i) {
            if (!moves[i].rapid) continue;
            // The first move after a tool change starts from the tool change position: only its end counts.
            const Move& from = i > 0 ? moves[i - 1] : moves[i];
            ++r.links;
            r.linkCollisions += rapidClearance(stock, cutter, from, moves[i]) < clearance;
        }
    return r;
}

}  // namespace aeronc::impellerpath
