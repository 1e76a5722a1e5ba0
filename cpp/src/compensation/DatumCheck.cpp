#include <aeronc/compensation/DatumCheck.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace aeronc::compensation {

std::string datumUseName(DatumUse use) {
    switch (use) {
        case DatumUse::Used: return "used";
        case DatumUse::LeftOut: return "left out";
        case DatumUse::LeftOutByHand: return "left out by hand";
        case DatumUse::PutBack: return "put back";
    }
    return "?";
}

namespace {

std::string mm(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f mm", v);
    return buf;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    const size_t h = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h), v.end());
    const double upper = v[h];
    if (v.size() % 2) return upper;
    return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h)));
}

struct Miss {
    double miss = NAN;
    std::optional<Method> predictor;
    Vec3 predicted = Vec3::Zero();
};

// Per datum hole in use: its smallest leave-one-out miss over the methods.
std::vector<Miss> leaveOneOutMisses(size_t count, const std::vector<LeaveOneOut>& figures) {
    std::vector<Miss> out(count);
    for (const auto& f : figures) {
        if (!f.available) continue;
        for (size_t j = 0; j < count; ++j)
            if (!(f.errors[j] >= out[j].miss)) out[j] = {f.errors[j], f.method, f.predicted[j]};
    }
    return out;
}

// A datum hole not in `used`: how well the datum holes in use predict it.
Miss missFrom(const std::vector<Datum>& used, const Datum& d) {
    Miss best;
    for (Method m : allMethods()) {
        try {
            const Vec3 p = Compensator(m, used).correction(asHole(d));
            const double e = (p - d.deviation()).norm();
            if (!(e >= best.miss)) best.miss = e, best.predictor = m, best.predicted = p;
        } catch (const Error&) {
            // the datum holes in use do not support this method
        }
    }
    return best;
}

}  // namespace

DatumCheck checkDatums(const std::vector<Datum>& datums, const DatumCheckOptions& options,
                       const std::set<std::string>& keep, const std::set<std::string>& drop) {
    for (const auto& id : keep)
        if (drop.count(id))
            throw compensationError("datum hole " + id + " is both put back and left out by hand: choose one");
    if (!(options.factor > 0.0) || !(options.minimum >= 0.0) || !(options.maxShare >= 0.0 && options.maxShare < 1.0))
        throw compensationError("datum check: the factor must be positive, the minimum zero or more and the share "
                                "of datum holes left out below 1");
    DatumCheck out;
    out.datums.resize(datums.size());
    std::vector<size_t> inUse;  // indices into datums
    for (size_t i = 0; i < datums.size(); ++i) {
        out.datums[i].id = datums[i].id;
        if (drop.count(datums[i].id))
            out.datums[i].use = DatumUse::LeftOutByHand;
        else
            inUse.push_back(i);
    }
    auto usedDatums = [&] {
        std::vector<Datum> u;
        u.reserve(inUse.size());
        for (size_t i : inUse) u.push_back(datums[i]);
        return u;
    };

    out.used = usedDatums();
    out.leaveOneOut = leaveOneOut(out.used);
    std::vector<Miss> misses = leaveOneOutMisses(out.used.size(), out.leaveOneOut);
    auto measure = [&] {
        std::vector<double> finite;
        for (const auto& m : misses)
            if (std::isfinite(m.miss)) finite.push_back(m.miss);
        out.typicalMiss = median(finite);
        out.threshold = std::max(options.factor * out.typicalMiss, options.minimum);
    };
    measure();

    const size_t maxLeftOut = static_cast<size_t>(std::floor(options.maxShare * static_cast<double>(datums.size())));
    if (!options.enabled) {
        out.note = "datum check off";
    } else if (inUse.size() < options.minDatums) {
        std::ostringstream os;
        os << inUse.size() << " datum holes in use: too few to tell a misread reading (the check needs "
           << options.minDatums << ")";
        out.note = os.str();
    } else {
        out.checked = true;
        while (out.leftOut.size() < maxLeftOut && inUse.size() > options.minDatums) {
            // The reading most out of line that the user has not put back.
            size_t worst = misses.size();
            for (size_t j = 0; j < misses.size(); ++j) {
                if (keep.count(datums[inUse[j]].id) || !(misses[j].miss > out.threshold)) continue;
                if (worst == misses.size() || misses[j].miss > misses[worst].miss) worst = j;
            }
            if (worst == misses.size()) break;
            const size_t i = inUse[worst];
            out.datums[i].use = DatumUse::LeftOut;
            out.leftOut.push_back(datums[i].id);
            inUse.erase(inUse.begin() + static_cast<std::ptrdiff_t>(worst));
            out.used = usedDatums();
            out.leaveOneOut = leaveOneOut(out.used);
            misses = leaveOneOutMisses(out.used.size(), out.leaveOneOut);
            measure();
        }
    }

    // Every datum hole's verdict against the datum holes finally in use.
    for (size_t j = 0; j < inUse.size(); ++j) {
        auto& v = out.datums[inUse[j]];
        v.miss = misses[j].miss;
        v.predictor = misses[j].predictor;
        v.predicted = misses[j].predicted;
    }
    for (size_t i = 0; i < datums.size(); ++i) {
        auto& v = out.datums[i];
        if (v.use == DatumUse::LeftOut || v.use == DatumUse::LeftOutByHand) {
            const Miss m = missFrom(out.used, datums[i]);
            v.miss = m.miss, v.predictor = m.predictor, v.predicted = m.predicted;
        }
        v.outOfLine = out.checked && std::isfinite(v.miss) && v.miss > out.threshold;
        if (v.use == DatumUse::Used && v.outOfLine && keep.count(v.id)) v.use = DatumUse::PutBack;
        const std::string off = std::isfinite(v.miss)
                                    ? mm(v.miss) + " from where the other datum holes put it (" +
                                          methodName(*v.predictor) + ")"
                                    : "no method predicts it from the others";
        const std::string limit = "; beyond " + mm(out.threshold) + " (" + mm(out.typicalMiss) + " typical)";
        switch (v.use) {
            case DatumUse::LeftOut: v.reason = "left out: " + off + limit; break;
            case DatumUse::LeftOutByHand: v.reason = "left out by hand: " + off; break;
            case DatumUse::PutBack: v.reason = "put back by hand, used: " + off + limit; break;
            case DatumUse::Used:
                // Out of line but still used: the check left out as many as it may.
                if (v.outOfLine) v.reason = "out of line but used (no more may be left out): " + off + limit;
                break;
        }
    }
    return out;
}

}  // namespace aeronc::compensation
