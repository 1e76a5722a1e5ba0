// Layered-slicing recognition (integral-panel seed §2.2; patent step 1): the order in
// which the algorithms run over the part's face catalogue.
#include <aeronc/core/Error.h>
#include <aeronc/recognition/Recogniser.h>

#include "AttachedFeatures.h"
#include "ElementMeasures.h"
#include "FaceCatalogue.h"
#include "FaceClaims.h"
#include "FaceRoles.h"
#include "HoleRecognition.h"
#include "LevelSlicing.h"
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

namespace aeronc::recognition {
namespace {

class Recogniser {
public:
    Recogniser(const TopoDS_Shape& solid, const RecogniseOptions& o) : opt_(o), tol_(o), faces_(solid) {
        tree_.faceCount = faces_.size();
        tree_.faceRoles.assign(static_cast<std::size_t>(faces_.size()), FaceRole::Unclaimed);
        tree_.faceElement.assign(static_cast<std::size_t>(faces_.size()), -1);
        claimed_.assign(static_cast<std::size_t>(faces_.size()), false);
    }

    DomainTree run() {
        if (opt_.directions.empty()) {
            runAuto();
        } else {
            const std::size_t n = opt_.directions.size();
            for (std::size_t k = 0; k < n; ++k) {
                const Vec3 d = checkedDirection(faces_, tol_, opt_.directions[k], k);
                progressBase_ = double(k) / n;
                progressSpan_ = 1.0 / n;
                runSetup(d);
            }
        }
        assignFaceRoles(tree_, faces_, tol_);
        reportUnclaimedFaces(tree_, onBlank_);
        return std::move(tree_);
    }

private:
    RecogniseOptions opt_;
    Tolerances tol_;
    FaceCatalogue faces_;
    DomainTree tree_;
    std::vector<bool> claimed_;  // per face: some setup machines it
    std::vector<bool> onBlank_;  // per face: on the boundary of some setup's blank
    std::vector<Vec3> axes_;     // principal axes, on first use
    RegionWidths widths_;
    double progressBase_ = 0, progressSpan_ = 1;

    void progress(double f, const std::string& stage) {
        if (opt_.progress && !opt_.progress(progressBase_ + progressSpan_ * f, stage))
            throw inputError("recognition cancelled");
    }

    // Directions by what is still to machine, then the principal axes.
    void runAuto() {
        SetupDirectionSearch search(faces_, tol_);
        for (int round = 0; round < 12; ++round) {
            const std::optional<Vec3> d = search.next(claimed_);
            if (!d) break;
            progressBase_ = std::min(0.9, 0.45 * round);
            progressSpan_ = round == 0 ? 0.45 : 0.1;
            runSetup(*d);
        }
        for (const Vec3& d : search.untriedPrincipalAxes()) runSetup(d);
        dropEmptySetups(tree_);
        if (tree_.setups.empty()) throw inputError("no machining feature found in any setup direction");
    }

    void runSetup(const Vec3& d) {
        if (axes_.empty()) axes_ = principalAxes(faces_, tol_);
        const SetupView view(faces_, tol_, d, axes_, opt_);
        markBlankBoundaryFaces(view, onBlank_);

        SetupDirection setup;
        setup.id = static_cast<int>(tree_.setups.size());
        setup.direction = view.frame.w;
        setup.name = directionName(view.frame.w);

        LevelSlicing slicing(view, widths_, tree_.warnings);
        const std::vector<double>& levels = slicing.levels();
        std::vector<ElementDraft> made;
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t k = 0; k < levels.size(); ++k) {
            progress(double(k) / levels.size(), "slicing " + setup.name);
            slicing.slice(k, setup.id, made);
        }
        if (std::getenv("AERONC_TRACE"))
            std::fprintf(stderr, "setup %s: %zu levels, %zu elements, %.3f s\n", setup.name.c_str(), levels.size(),
                         made.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        progress(1.0, "linking " + setup.name);
        linkPocketTree(made, tol_.linear);
        attachElementFeatures(made, view);
        recogniseHoles(made, view);
        attachTreeFeatures(made);

        claimFaces(made, setup, claimed_, tree_);
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
