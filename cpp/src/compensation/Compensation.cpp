#include <aeronc/compensation/Compensation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

namespace aeronc::compensation {

namespace {

std::string mm(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f mm", v);
    return buf;
}

}  // namespace

void assignRows(std::vector<Datum>& datums, std::vector<NominalHole>& holes, const RowOptions& options) {
    const bool missing = std::any_of(datums.begin(), datums.end(), [](const Datum& d) { return d.row < 0; }) ||
                         std::any_of(holes.begin(), holes.end(), [](const NominalHole& h) { return h.row < 0; });
    if (!missing) return;
    std::vector<Vec3> points;
    points.reserve(datums.size() + holes.size());
    for (const auto& d : datums) points.push_back(d.nominal);
    for (const auto& h : holes) points.push_back(h.position);
    const HoleRows rows = findRows(points, options);
    for (size_t i = 0; i < datums.size(); ++i) datums[i].row = rows.row[i], datums[i].station = rows.station[i];
    for (size_t i = 0; i < holes.size(); ++i)
        holes[i].row = rows.row[datums.size() + i], holes[i].station = rows.station[datums.size() + i];
}

CompensationResult compensate(CompensationInput input, std::optional<Method> method) {
    auto& datums = input.datums;
    auto& holes = input.holes;
    if (datums.size() < 2) {
        std::ostringstream os;
        os << "fewer than two datum holes (" << datums.size()
           << "): compensation needs at least two measured datum holes";
        throw compensationError(os.str());
    }
    std::set<std::string> ids;
    for (const auto& d : datums) {
        if (!ids.insert(d.id).second) throw compensationError("datum hole " + d.id + " is given twice");
        if (!finite(d.nominal) || !finite(d.measured))
            throw compensationError("datum hole " + d.id + ": nominal or measured position is not a finite number");
    }
    for (auto& h : holes) {
        if (!finite(h.position) || !finite(h.normal) || h.normal.norm() < 1e-12)
            throw compensationError("hole " + h.id + ": position or normal is not a finite point and direction");
        h.normal.normalize();
    }
    if (!(input.tolerance >= 0.0)) throw compensationError("the correction tolerance must be zero or positive");
    if (!(input.neighbourTolerance >= 0.0))
        throw compensationError("the neighbour tolerance must be zero or positive");
    assignRows(datums, holes, input.rows);

    CompensationResult r;
    r.check = checkDatums(datums, input.check, input.keep, input.drop);
    const std::vector<Datum>& used = r.check.used;
    if (used.size() < 2) {
        std::ostringstream os;
        os << "fewer than two datum holes in use (" << used.size() << " of " << datums.size()
           << "): put back datum holes left out by hand";
        throw compensationError(os.str());
    }
    r.leaveOneOut = r.check.leaveOneOut;
    r.proposed = proposedMethod(r.leaveOneOut);
    if (!method && !r.proposed) {
        std::string why;
        for (const auto& f : r.leaveOneOut) why += "\n  " + methodName(f.method) + ": " + f.reason;
        throw compensationError("no method can be proposed from these datum holes:" + why);
    }
    r.method = method ? *method : *r.proposed;
    const Compensator c(r.method, used);
    r.fit = c.fit();
    for (size_t i = 0; i < datums.size(); ++i) {
        const auto& d = datums[i];
        r.datums.push_back({d.id, d.deviation(), d.measured - c.fit().apply(d.nominal), r.check.datums[i]});
    }
    r.holes = correctHoles(c, holes, input.tolerance, input.neighbourTolerance);

    for (const auto& d : r.datums) {
        const auto& v = d.verdict;
        const double off = v.miss, limit = std::isfinite(v.limit) ? v.limit : r.check.threshold;
        if (v.use == DatumUse::LeftOut) r.flags.push_back({FlagKind::DatumLeftOut, d.id, off, limit, v.reason});
        if (v.use == DatumUse::LeftOutByHand)
            r.flags.push_back({FlagKind::DatumLeftOutByHand, d.id, off, limit, v.reason});
        if (v.use == DatumUse::PutBack) r.flags.push_back({FlagKind::DatumPutBack, d.id, off, limit, v.reason});
        if (v.use == DatumUse::Used && v.outOfLine)
            r.flags.push_back({FlagKind::DatumOutOfLineUsed, d.id, off, limit, v.reason});
    }
    for (const auto& h : r.holes) {
        if (h.againstNeighbours)
            r.flags.push_back({FlagKind::AgainstNeighbours, h.id, h.neighbourDeparture, input.neighbourTolerance,
                               "correction departs " + mm(h.neighbourDeparture) + " from its neighbours' (beyond " +
                                   mm(input.neighbourTolerance) + ")"});
        if (h.exceedsTolerance)
            r.flags.push_back({FlagKind::BeyondTolerance, h.id, h.correction.norm(), input.tolerance,
                               "correction " + mm(h.correction.norm()) + " beyond the " + mm(input.tolerance) +
                                   " tolerance"});
        r.flaggedHoles += (h.againstNeighbours || h.exceedsTolerance) ? 1 : 0;
    }
    return r;
}

std::vector<HoleCorrection> correctHoles(const Compensator& c, const std::vector<NominalHole>& holes, double tolerance,
                                         double neighbourTolerance) {
    std::vector<std::string> notes;
    const std::vector<Vec3> corrections = c.corrections(holes, &notes);
    std::vector<double> departures(holes.size(), 0.0);
    if (std::isfinite(neighbourTolerance)) {
        std::vector<Vec3> positions;
        positions.reserve(holes.size());
        for (const auto& h : holes) positions.push_back(h.position);
        departures = neighbourDepartures(positions, corrections);
    }
    std::vector<HoleCorrection> out;
    out.reserve(holes.size());
    for (size_t i = 0; i < holes.size(); ++i) {
        const auto& h = holes[i];
        HoleCorrection hc;
        hc.id = h.id;
        hc.nominal = h.position;
        hc.correction = corrections[i];
        hc.note = std::move(notes[i]);
        hc.compensated = h.position + hc.correction;
        hc.normal = c.usesFit() ? Vec3((c.fit().rotation * h.normal).normalized()) : h.normal;
        hc.exceedsTolerance = hc.correction.norm() > tolerance;
        hc.neighbourDeparture = departures[i];
        hc.againstNeighbours = departures[i] > neighbourTolerance;
        out.push_back(std::move(hc));
    }
    return out;
}

}  // namespace aeronc::compensation
