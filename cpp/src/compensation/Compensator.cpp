#include <aeronc/compensation/Compensator.h>
#include <aeronc/compensation/ResidualField.h>
#include <aeronc/compensation/RowInterpolation.h>

#include <algorithm>
#include <cmath>

namespace aeronc::compensation {

const std::vector<Method>& allMethods() {
    static const std::vector<Method> methods{Method::Seed,          Method::Rigid,    Method::Similarity,
                                             Method::RigidIdw,      Method::SimilarityIdw, Method::RigidTps,
                                             Method::SimilarityTps};
    return methods;
}

std::string methodName(Method m) {
    switch (m) {
        case Method::Seed: return "seed";
        case Method::Rigid: return "rigid";
        case Method::Similarity: return "similarity";
        case Method::RigidIdw: return "rigid+idw";
        case Method::SimilarityIdw: return "similarity+idw";
        case Method::RigidTps: return "rigid+tps";
        case Method::SimilarityTps: return "similarity+tps";
    }
    return "?";
}

std::optional<Method> methodFromName(const std::string& name) {
    for (Method m : allMethods())
        if (methodName(m) == name) return m;
    return std::nullopt;
}

namespace {

bool similarityBased(Method m) {
    return m == Method::Similarity || m == Method::SimilarityIdw || m == Method::SimilarityTps;
}
bool idw(Method m) { return m == Method::RigidIdw || m == Method::SimilarityIdw; }
bool tps(Method m) { return m == Method::RigidTps || m == Method::SimilarityTps; }

}  // namespace

struct Compensator::Fields {
    std::optional<InverseDistanceField> idw;
    std::optional<ThinPlateSpline> tps;
};

Compensator::Compensator(Method method, std::vector<Datum> datums) : method_(method), datums_(std::move(datums)) {
    if (datums_.empty()) throw compensationError("no datum holes to compensate from");
    if (method_ == Method::Seed) {
        for (size_t i = 0; i < datums_.size(); ++i) {
            if (datums_[i].row < 0) throw compensationError("the seed's method needs the rows of the datum holes");
            rowDatums_[datums_[i].row].push_back(static_cast<int>(i));
        }
        for (auto& [row, members] : rowDatums_)
            std::sort(members.begin(), members.end(), [&](int a, int b) {
                return datums_[static_cast<size_t>(a)].station < datums_[static_cast<size_t>(b)].station;
            });
        return;
    }
    std::vector<Vec3> nominal, measured;
    for (const auto& d : datums_) nominal.push_back(d.nominal), measured.push_back(d.measured);
    fit_ = similarityBased(method_) ? fitSimilarity(nominal, measured) : fitRigid(nominal, measured);
    for (const auto& d : datums_) residuals_.push_back(d.measured - fit_.apply(d.nominal));
    auto fields = std::make_shared<Fields>();
    if (idw(method_)) fields->idw.emplace(nominal, residuals_);
    if (tps(method_)) fields->tps.emplace(nominal, residuals_);
    fields_ = fields;
}

Vec3 Compensator::correction(const NominalHole& hole, std::string* note) const {
    if (method_ == Method::Seed) return seedCorrection(hole, note);
    Vec3 c = fit_.apply(hole.position) - hole.position;
    if (fields_->idw) c += fields_->idw->at(hole.position);
    if (fields_->tps) c += fields_->tps->at(hole.position);
    return c;
}

std::vector<Vec3> Compensator::corrections(const std::vector<NominalHole>& holes, std::vector<std::string>* notes) const {
    std::vector<Vec3> out(holes.size());
    if (notes) notes->assign(holes.size(), std::string());
    if (method_ == Method::Seed) {
        for (size_t i = 0; i < holes.size(); ++i) out[i] = seedCorrection(holes[i], notes ? &(*notes)[i] : nullptr);
        return out;
    }
    for (size_t i = 0; i < holes.size(); ++i) {
        out[i] = fit_.apply(holes[i].position) - holes[i].position;
        if (fields_->idw) out[i] += fields_->idw->at(holes[i].position);
    }
    if (fields_->tps) {
        std::vector<Vec3> points;
        points.reserve(holes.size());
        for (const auto& h : holes) points.push_back(h.position);
        fields_->tps->addAt(points, out);
    }
    return out;
}

Vec3 Compensator::seedCorrection(const NominalHole& hole, std::string* note) const {
    auto say = [&](const std::string& text) {
        if (note) *note = text;
    };
    const auto it = rowDatums_.find(hole.row);
    if (hole.row < 0 || it == rowDatums_.end()) {
        // Nothing to interpolate between: the nearest datum hole's deviation, and say so.
        size_t best = 0;
        for (size_t i = 1; i < datums_.size(); ++i)
            if ((datums_[i].nominal - hole.position).squaredNorm() < (datums_[best].nominal - hole.position).squaredNorm())
                best = i;
        say("no datum hole in its row: deviation of the nearest datum hole " + datums_[best].id);
        return datums_[best].deviation();
    }
    const auto& members = it->second;
    const Datum& first = datums_[static_cast<size_t>(members.front())];
    const Datum& last = datums_[static_cast<size_t>(members.back())];
    if (hole.station < first.station) {
        say("before the first datum hole of its row: deviation of " + first.id);
        return first.deviation();
    }
    if (hole.station > last.station) {
        say("beyond the last datum hole of its row: deviation of " + last.id);
        return last.deviation();
    }
    for (size_t k = 0; k + 1 < members.size(); ++k) {
        const Datum& a = datums_[static_cast<size_t>(members[k])];
        const Datum& b = datums_[static_cast<size_t>(members[k + 1])];
        if (hole.station <= b.station && b.station > a.station)
            return rowCorrection(a.deviation(), b.deviation(), b.station - a.station, hole.station - a.station);
    }
    return first.deviation();  // every datum hole of the row at the hole's station
}

std::vector<LeaveOneOut> leaveOneOut(const std::vector<Datum>& datums) {
    std::vector<LeaveOneOut> out;
    for (Method m : allMethods()) {
        LeaveOneOut f;
        f.method = m;
        f.available = true;
        for (size_t j = 0; j < datums.size() && f.available; ++j) {
            std::vector<Datum> others;
            others.reserve(datums.size() - 1);
            for (size_t k = 0; k < datums.size(); ++k)
                if (k != j) others.push_back(datums[k]);
            try {
                const Compensator c(m, std::move(others));
                f.predicted.push_back(c.correction(asHole(datums[j])));
                f.errors.push_back((f.predicted.back() - datums[j].deviation()).norm());
            } catch (const Error& e) {
                f.available = false;
                f.reason = "without " + datums[j].id + ": " + e.what();
            }
        }
        if (datums.size() < 2) f.available = false, f.reason = "needs at least two datum holes";
        if (f.available) {
            double sum = 0.0;
            for (double e : f.errors) sum += e * e, f.max = std::max(f.max, e);
            f.rms = std::sqrt(sum / static_cast<double>(f.errors.size()));
        } else {
            f.errors.clear();
            f.predicted.clear();
        }
        out.push_back(std::move(f));
    }
    return out;
}

std::optional<Method> proposedMethod(const std::vector<LeaveOneOut>& figures) {
    double best = INFINITY;
    for (const auto& f : figures)
        if (f.available) best = std::min(best, f.rms);
    if (!std::isfinite(best)) return std::nullopt;
    const double within = best + std::max(1e-9, 0.005 * best);
    for (Method m : allMethods())
        for (const auto& f : figures)
            if (f.method == m && f.available && f.rms <= within) return m;
    return std::nullopt;
}

}  // namespace aeronc::compensation
