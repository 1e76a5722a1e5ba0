#include <aeronc/compensation/DatumCheck.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
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

const char* const kAxis[3] = {"X", "Y", "Z"};

struct Miss {
    double miss = NAN;   // the smallest miss over the methods (across the normal when known)
    double whole = NAN;  // the smallest whole distance over the methods
    std::optional<Method> predictor;
    Vec3 predicted = Vec3::Zero();
};

// How far a prediction misses a datum hole's deviation, across its normal when the normal is
// known. The camera finds a hole's centre in its picture, across its axis (the hole's normal):
// a burr, a chip or a reflection moves that centre sideways. A skin bends and sags along its
// normal, and there a sparse set of datum holes is the worst predicted; judged along it, a real
// sag between datum holes far apart would look like a misread reading.
double missOf(const Vec3& predicted, const Datum& d) {
    Vec3 e = predicted - d.deviation();
    const double n = d.normal.norm();
    if (n > 0.0) e -= e.dot(d.normal / n) * (d.normal / n);
    return e.norm();
}

void take(Miss& m, Method method, const Vec3& predicted, const Datum& d) {
    const double w = (predicted - d.deviation()).norm();
    if (!(w >= m.whole)) m.whole = w;
    const double e = missOf(predicted, d);
    if (!(e >= m.miss)) m.miss = e, m.predictor = method, m.predicted = predicted;
}

// The datum holes in use, their leave-one-out and each one's smallest miss over the methods.
struct Survey {
    std::vector<size_t> inUse;  // indices into the datums given
    std::vector<Datum> used;
    std::vector<LeaveOneOut> figures;
    std::vector<Miss> misses;
    double typical = 0.0;
    double typicalWhole = 0.0;  // of the whole distances
};

Survey survey(const std::vector<Datum>& datums, std::vector<size_t> inUse) {
    Survey s;
    s.inUse = std::move(inUse);
    for (size_t i : s.inUse) s.used.push_back(datums[i]);
    s.figures = leaveOneOut(s.used);
    s.misses.resize(s.used.size());
    for (const auto& f : s.figures) {
        if (!f.available) continue;
        for (size_t j = 0; j < s.used.size(); ++j) take(s.misses[j], f.method, f.predicted[j], s.used[j]);
    }
    std::vector<double> finite;
    for (const auto& m : s.misses)
        if (std::isfinite(m.miss)) finite.push_back(m.miss);
    s.typical = median(finite);
    finite.clear();
    for (const auto& m : s.misses)
        if (std::isfinite(m.whole)) finite.push_back(m.whole);
    s.typicalWhole = median(finite);
    return s;
}

std::vector<size_t> without(const std::vector<size_t>& v, size_t i) {
    std::vector<size_t> out;
    for (size_t x : v)
        if (x != i) out.push_back(x);
    return out;
}

// A datum hole not in use: how well the datum holes in use predict it.
Miss missFrom(const std::vector<Datum>& used, const Datum& d) {
    Miss best;
    for (Method m : allMethods()) {
        try {
            take(best, m, Compensator(m, used).correction(asHole(d)), d);
        } catch (const Error&) {
            // the datum holes in use do not support this method
        }
    }
    return best;
}

// The axis the miss mostly lies along, for the message.
int mainAxis(const Miss& m, const Datum& d) {
    Vec3 e = m.predicted - d.deviation();
    const double n = d.normal.norm();
    if (n > 0.0) e -= e.dot(d.normal / n) * (d.normal / n);
    e = e.cwiseAbs();
    int axis = 0;
    for (int c = 1; c < 3; ++c)
        if (e[c] > e[axis]) axis = c;
    return axis;
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
    out.options = options;
    out.datums.resize(datums.size());
    std::vector<size_t> inUse;  // indices into datums
    for (size_t i = 0; i < datums.size(); ++i) {
        out.datums[i].id = datums[i].id;
        if (drop.count(datums[i].id))
            out.datums[i].use = DatumUse::LeftOutByHand;
        else
            inUse.push_back(i);
    }
    const Survey full = survey(datums, inUse);
    Survey s = full;
    // The typical miss of the others, surveyed without datum hole i (once per step).
    std::map<size_t, Survey> others;
    auto withoutIt = [&](size_t i) -> const Survey& {
        auto it = others.find(i);
        if (it == others.end()) it = others.emplace(i, survey(datums, without(s.inUse, i))).first;
        return it->second;
    };
    auto limitOf = [&](double typical) { return std::max(options.factor * typical, options.minimum); };
    // Out of line against the others: across the normal, and by the whole distance too. Across
    // alone, a bend across a sparse pattern can stand out where the whole distances of the
    // others, raised by a sag along the normal, show that the methods do not follow it closely.
    auto beyond = [&](const Miss& m, double typical, double typicalWhole) {
        return m.miss > limitOf(typical) && m.whole > limitOf(typicalWhole);
    };
    // Out of line among all the datum holes in use at first. Required at every step: once a
    // reading is left out, the distortion that only it and a neighbour showed can make the
    // neighbour look out of line in its turn (three datum holes a row, a bend between them).
    std::map<size_t, bool> outAtFirst;
    auto outOfLineAtFirst = [&](size_t i) {
        auto it = outAtFirst.find(i);
        if (it != outAtFirst.end()) return it->second;
        const size_t j = static_cast<size_t>(std::find(full.inUse.begin(), full.inUse.end(), i) - full.inUse.begin());
        const Survey rest = out.leftOut.empty() ? withoutIt(i) : survey(datums, without(full.inUse, i));
        return outAtFirst[i] = beyond(full.misses[j], rest.typical, rest.typicalWhole);
    };
    // Datum holes in use (positions in s) missed beyond the minimum, most missed first.
    auto suspects = [&](bool keptToo) {
        std::vector<size_t> v;
        for (size_t j = 0; j < s.used.size(); ++j)
            if (s.misses[j].miss > options.minimum && (keptToo || !keep.count(s.used[j].id))) v.push_back(j);
        std::stable_sort(v.begin(), v.end(), [&](size_t a, size_t b) { return s.misses[a].miss > s.misses[b].miss; });
        return v;
    };

    // Left out: its miss and the others' typical misses, as it was found.
    std::map<size_t, std::tuple<Miss, double, double>> decided;
    const size_t maxLeftOut = static_cast<size_t>(std::floor(options.maxShare * static_cast<double>(datums.size())));
    if (!options.enabled) {
        out.note = "datum check off";
    } else if (s.used.size() < options.minDatums) {
        std::ostringstream os;
        os << s.used.size() << " datum holes in use: too few to tell a misread reading (the check needs "
           << options.minDatums << ")";
        out.note = os.str();
    } else {
        out.checked = true;
        bool found = true;
        while (found && out.leftOut.size() < maxLeftOut && s.used.size() > options.minDatums) {
            found = false;
            std::vector<size_t> tried = suspects(false);
            if (tried.size() > options.candidates) tried.resize(options.candidates);
            for (size_t j : tried) {
                const size_t i = s.inUse[j];
                if (!outOfLineAtFirst(i)) continue;
                const Survey& rest = withoutIt(i);
                if (!beyond(s.misses[j], rest.typical, rest.typicalWhole)) continue;
                out.datums[i].use = DatumUse::LeftOut;
                out.leftOut.push_back(datums[i].id);
                decided[i] = {s.misses[j], rest.typical, rest.typicalWhole};
                Survey next = rest;
                s = std::move(next);
                others.clear();
                found = true;
                break;
            }
        }
    }
    out.used = s.used;
    out.leaveOneOut = s.figures;
    out.typicalMiss = s.typical;
    out.threshold = limitOf(s.typical);

    // Every datum hole's verdict against the datum holes finally in use.
    std::vector<Miss> final(datums.size());
    std::vector<double> typicalWhole(datums.size(), NAN);
    for (size_t j = 0; j < s.inUse.size(); ++j) final[s.inUse[j]] = s.misses[j];
    for (size_t i = 0; i < datums.size(); ++i) {
        if (decided.count(i)) {
            std::tie(final[i], out.datums[i].typical, typicalWhole[i]) = decided[i];
        } else if (out.datums[i].use == DatumUse::LeftOutByHand) {
            final[i] = missFrom(s.used, datums[i]);
            out.datums[i].typical = s.typical;
            typicalWhole[i] = s.typicalWhole;
        }
    }
    if (out.checked) {
        // Those in use that might be out of line: the ones put back, and the most missed
        // others (those the check could not leave out any more).
        std::vector<size_t> look = suspects(true);
        if (look.size() > options.candidates) {
            std::vector<size_t> kept;
            for (size_t k = 0; k < look.size(); ++k)
                if (k < options.candidates || keep.count(s.used[look[k]].id)) kept.push_back(look[k]);
            look = kept;
        }
        // Out of line now and at first, as the check requires of a reading it leaves out.
        for (size_t j : look) {
            const size_t i = s.inUse[j];
            if (!outOfLineAtFirst(i)) continue;
            out.datums[i].typical = withoutIt(i).typical;
            typicalWhole[i] = withoutIt(i).typicalWhole;
        }
    }
    for (size_t i = 0; i < datums.size(); ++i) {
        auto& v = out.datums[i];
        const Miss& m = final[i];
        v.miss = m.miss, v.predictor = m.predictor, v.predicted = m.predicted;
        if (std::isfinite(v.typical)) v.limit = limitOf(v.typical);
        v.outOfLine = out.checked && std::isfinite(v.limit) && beyond(m, v.typical, typicalWhole[i]);
        if (v.use == DatumUse::Used && v.outOfLine && keep.count(v.id)) v.use = DatumUse::PutBack;
        if (!std::isfinite(m.miss)) {
            v.reason = "no method predicts it from the others";
        } else {
            v.reason = mm(m.miss) + " (mostly along " + kAxis[mainAxis(m, datums[i])] +
                       ") from where the other datum holes put it (" + methodName(*m.predictor) + ")";
            if (out.checked && std::isfinite(v.limit))
                v.reason += "; they are missed by " + mm(v.typical) + " typically, out of line beyond " + mm(v.limit);
        }
        switch (v.use) {
            case DatumUse::LeftOut: v.reason = "left out: " + v.reason; break;
            case DatumUse::LeftOutByHand: v.reason = "left out by hand: " + v.reason; break;
            case DatumUse::PutBack: v.reason = "put back by hand, used: " + v.reason; break;
            case DatumUse::Used:
                // Out of line but still used: the check left out as many as it may.
                v.reason = v.outOfLine ? "out of line but used (no more may be left out): " + v.reason : "";
                break;
        }
    }
    return out;
}

}  // namespace aeronc::compensation
