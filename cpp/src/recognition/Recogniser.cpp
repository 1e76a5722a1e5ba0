// Layered-slicing recognition (integral-panel seed §2.2; patent step 1): the order in
// which the algorithms run over the part's face catalogue.
#include <aeronc/core/Error.h>
#include <aeronc/recognition/Recogniser.h>

#include "AttachedFeatures.h"
#include "ChainHoles.h"
#include "HoleChains.h"
#include "EdgeChamfers.h"
#include "ElementMeasures.h"
#include "FaceCatalogue.h"
#include "FaceClaims.h"
#include "FaceRoles.h"
#include "HoleRecognition.h"
#include "LevelSlicing.h"
#include "MeshSection.h"
#include "PocketTree.h"
#include "SetupDirections.h"
#include "SetupView.h"
#include "Tolerances.h"
#include "UnclaimedFaces.h"

#include <Standard_Failure.hxx>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <thread>

namespace aeronc::recognition {
namespace {

// The same finding made twice (a level sliced again after trimming) is said once, in its first place.
void dropRepeatedWarnings(std::vector<std::string>& warnings) {
    std::vector<std::string> kept;
    for (std::string& w : warnings)
        if (std::find(kept.begin(), kept.end(), w) == kept.end()) kept.push_back(std::move(w));
    warnings = std::move(kept);
}

class Recogniser {
public:
    Recogniser(const TopoDS_Shape& solid, const RecogniseOptions& o)
        : opt_(o), tol_(o), faces_(solid), meshes_(faces_, o.chordTolerance) {
        tree_.faceCount = faces_.size();
        tree_.faceRoles.assign(static_cast<std::size_t>(faces_.size()), FaceRole::Unclaimed);
        tree_.faceElement.assign(static_cast<std::size_t>(faces_.size()), -1);
        claimed_.assign(static_cast<std::size_t>(faces_.size()), false);
        chamferOf_.assign(static_cast<std::size_t>(faces_.size()), -1);
    }

    DomainTree run() {
        const auto t0 = std::chrono::steady_clock::now();
        axes_ = principalAxes(faces_, tol_);
        EdgeCuts cuts = findEdgeChamfers(faces_, tol_, axes_);
        edgeChamfers_ = std::move(cuts.chamfers);
        edgeStepWalls_ = std::move(cuts.stepWalls);
        boxSides_ = std::move(cuts.boxSides);
        chains_ = findHoleChains(faces_, tol_);
        for (const HoleChain& c : chains_) chainTaken_.emplace_back(c.segments.size(), false);
        trace("axes, edge chamfers, hole chains", t0);
        if (opt_.directions.empty()) {
            reserveChainFaces({});
            runAuto();
        } else {
            std::vector<Vec3> dirs;
            for (std::size_t k = 0; k < opt_.directions.size(); ++k)
                dirs.push_back(checkedDirection(faces_, tol_, opt_.directions[k], k));
            reserveChainFaces(dirs);
            const std::size_t n = dirs.size();
            for (std::size_t k = 0; k < n; ++k) {
                progressBase_ = double(k) / n;
                progressSpan_ = 1.0 / n;
                runSetup(dirs[k]);
            }
        }
        const auto tr = std::chrono::steady_clock::now();
        assignFaceRoles(tree_, faces_, tol_);
        // The blank's edge chamfers no element took are chamfers of the part itself.
        std::vector<bool> accounted = onBlank_;
        accounted.resize(static_cast<std::size_t>(faces_.size()), false);
        for (std::size_t i = 0; i < edgeChamfers_.size(); ++i)
            if (edgeChamfers_[i] && tree_.faceElement[i] < 0) {
                tree_.faceRoles[i] = FaceRole::Chamfer;
                accounted[i] = true;
            }
        reportUnclaimedFaces(tree_, accounted);
        dropRepeatedWarnings(tree_.warnings);
        trace("face roles", tr);
        trace("recognition", t0);
        return std::move(tree_);
    }

private:
    RecogniseOptions opt_;
    Tolerances tol_;
    FaceCatalogue faces_;
    MeshSection meshes_;
    DomainTree tree_;
    std::vector<bool> claimed_;  // per face: some setup machines it
    std::vector<int> chamferOf_;  // per face: the element whose chamfer it is (not in claimed_), or -1
    std::vector<bool> onBlank_;  // per face: on the boundary of some setup's blank
    std::vector<Vec3> axes_;     // principal axes
    std::vector<bool> edgeChamfers_;  // per face: a chamfer on an edge of the blank
    std::vector<bool> edgeStepWalls_;  // per face: the slanted wall of a blind step across an edge
    std::vector<bool> boxSides_;  // per face: on a side of the part's box
    RegionWidths widths_;
    std::vector<HoleChain> chains_;  // holes over the face adjacency, found once
    std::vector<std::vector<bool>> chainTaken_;  // per chain and segment: a setup made it
    std::vector<std::vector<bool>> reservedSegment_;  // per chain and segment: a setup will take it
    double progressBase_ = 0, progressSpan_ = 1;
    int threads_ = opt_.threads > 0 ? opt_.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));

    // The chain segments some setup will take: all with an entry when the setups are found
    // (their axes propose setups), else those entered along a given direction.
    void reserveChainFaces(const std::vector<Vec3>& given) {
        for (const HoleChain& c : chains_) {
            std::vector<bool> r;
            for (const HoleSegment& s : c.segments) {
                bool some = false;
                for (int e : s.entries) {
                    if (given.empty()) some = true;
                    for (const Vec3& d : given) some |= e * dot(c.axis, d) >= tol_.parallelCos;
                }
                r.push_back(some);
            }
            reservedSegment_.push_back(r);
        }
    }

    // Per face: a wall of a reserved segment no setup has taken yet, or a step or cone of its
    // chain (a counterbore's floor is no other pocket's wall).
    std::vector<bool> pendingChainFaces() const {
        std::vector<bool> out(static_cast<std::size_t>(faces_.size()), false);
        for (std::size_t c = 0; c < chains_.size(); ++c) {
            bool any = false;
            for (std::size_t k = 0; k < chains_[c].segments.size(); ++k)
                if (reservedSegment_[c][k] && !chainTaken_[c][k]) {
                    for (int f : chains_[c].segments[k].faces) out[static_cast<std::size_t>(f)] = true;
                    any = true;
                }
            if (any) {
                for (int f : chains_[c].steps) out[static_cast<std::size_t>(f)] = true;
                for (int f : chains_[c].cones) out[static_cast<std::size_t>(f)] = true;
            }
        }
        return out;
    }

    static void trace(const char* what, std::chrono::steady_clock::time_point since) {
        if (std::getenv("AERONC_TRACE"))
            std::fprintf(stderr, "%s: %.3f s\n", what,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count());
    }

    void progress(double f, const std::string& stage) {
        if (opt_.progress && !opt_.progress(progressBase_ + progressSpan_ * f, stage))
            throw inputError("recognition cancelled");
    }

    // Directions by what is still to machine, then the principal axes.
    void runAuto() {
        SetupDirectionSearch search(faces_, tol_);
        search.setAside(edgeChamfers_);
        search.setAside(edgeStepWalls_);
        for (int round = 0; round < 12; ++round) {
            // A chamfer calls for no direction of its own.
            std::vector<bool> machined = claimed_;
            for (std::size_t i = 0; i < machined.size(); ++i) machined[i] = machined[i] || chamferOf_[i] >= 0;
            const std::optional<Vec3> d = search.next(machined);
            if (!d) break;
            progressBase_ = std::min(0.9, 0.45 * round);
            progressSpan_ = round == 0 ? 0.45 : 0.1;
            runSetup(*d);
        }
        // Holes along axes no setup took: each axis a setup of its own, for its holes.
        for (std::size_t c = 0; c < chains_.size(); ++c)
            for (std::size_t k = 0; k < chains_[c].segments.size(); ++k) {
                const HoleSegment& s = chains_[c].segments[k];
                if (chainTaken_[c][k] || s.entries.empty()) continue;
                const Vec3& d = chains_[c].axis;
                const int e = s.entries.front();
                const Vec3 tool{e * d[0], e * d[1], e * d[2]};
                if (search.markTried(tool)) runSetup(tool, true);
            }
        for (const Vec3& d : search.untriedPrincipalAxes()) runSetup(d);
        dropEmptySetups(tree_);
        if (tree_.setups.empty()) throw inputError("no machining feature found in any setup direction");
    }

    // holesOnly: a setup a hole's axis proposed, for the hole chains along it alone.
    void runSetup(const Vec3& d, bool holesOnly = false) {
        if (axes_.empty()) axes_ = principalAxes(faces_, tol_);
        SetupView view(faces_, tol_, d, axes_, opt_);
        view.meshes = &meshes_;
        markBlankBoundaryFaces(view, onBlank_);

        SetupDirection setup;
        setup.id = static_cast<int>(tree_.setups.size());
        setup.direction = view.frame.w;
        setup.name = directionName(view.frame.w);

        std::vector<ElementDraft> made;
        const std::size_t firstWarning = tree_.warnings.size();
        if (!holesOnly) {
            LevelSlicing slicing(view, widths_, tree_.warnings);
            const std::vector<double>& levels = slicing.levels();
            const auto t0 = std::chrono::steady_clock::now();
            slicing.sliceAll(
                setup.id, made, threads_,
                [&](double f) {
                    return !opt_.progress ||
                           opt_.progress(progressBase_ + progressSpan_ * f, "slicing " + setup.name);
                },
                claimed_);
            if (std::getenv("AERONC_TRACE"))
                std::fprintf(stderr, "setup %s: %zu levels, %zu elements, %.3f s\n", setup.name.c_str(),
                             levels.size(), made.size(),
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        // A level means nothing without its setup, and two setups may meet the same level.
        for (std::size_t i = firstWarning; i < tree_.warnings.size(); ++i)
            tree_.warnings[i] = "setup " + setup.name + ", " + tree_.warnings[i];
        progress(1.0, "linking " + setup.name);
        const auto tl = std::chrono::steady_clock::now();
        linkPocketTree(made, tol_.linear);
        attachElementFeatures(made, view, boxSides_);
        recogniseHoles(made, view);
        addChainHoles(made, view, chains_, chainTaken_, claimed_);
        recogniseCounterbores(made, view);
        measureWidths(made, claimed_, widths_, threads_);
        attachTreeFeatures(made);
        for (ElementDraft& in : made) in.el.setup = setup.id;
        std::vector<bool> reserved = pendingChainFaces();
        for (std::size_t i = 0; i < reserved.size(); ++i) reserved[i] = reserved[i] || edgeChamfers_[i];
        releaseReservedFaces(made, reserved);

        claimFaces(made, setup, claimed_, chamferOf_, tree_);
        trace(("  tree, attached features, holes, widths, claims " + setup.name).c_str(), tl);
        setup.blankTop = view.clampedBlankTop;
        tree_.setups.push_back(std::move(setup));
    }
};

}  // namespace

DomainTree recognise(const TopoDS_Shape& solid, const RecogniseOptions& options) {
    if (options.linearTolerance <= 0 || options.angularTolerance <= 0 || options.chordTolerance <= 0)
        throw inputError("tolerances must be positive");
    if (options.blankAllowance < 0) throw inputError("the blank allowance must not be negative");
    try {
        Recogniser r(solid, options);
        return r.run();
    } catch (const Error&) {
        throw;
    } catch (const Standard_Failure& f) {
        throw geometryError(std::string("OpenCASCADE failed during recognition: ") + f.GetMessageString());
    }
}

}  // namespace aeronc::recognition
