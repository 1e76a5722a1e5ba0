// aeronc._core: compensation of drilling holes from measured datum holes. Every C++ exception
// stops here and becomes CompensationError (a RuntimeError) with the core's message.
#include "Guarded.h"

#include <aeronc/compensation/Compensation.h>
#include <aeronc/compensation/MeasurementCsv.h>
#include <aeronc/compensation/RowInterpolation.h>
#include <aeronc/compensation/TransformChain.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;
using namespace aeronc::compensation;

namespace {

PyObject* g_compensationError = nullptr;

template <class F>
auto guardedCompensation(F f) -> decltype(f()) {
    return aeronc::python::guardedAs(g_compensationError, f);
}

using Triple = std::array<double, 3>;
using Rows4 = std::array<std::array<double, 4>, 4>;

Vec3 vec(const Triple& a) { return {a[0], a[1], a[2]}; }
Triple triple(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

Vec3 vecOf(const py::dict& d, const char* key) {
    if (!d.contains(key)) throw compensationError(std::string("missing '") + key + "'");
    return vec(d[key].cast<Triple>());
}

Mat4 matrix(const Rows4& r) {
    Mat4 m;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m(i, j) = r[static_cast<size_t>(i)][static_cast<size_t>(j)];
    return m;
}

Rows4 rows4(const Mat4& m) {
    Rows4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[static_cast<size_t>(i)][static_cast<size_t>(j)] = m(i, j);
    return r;
}

// A chain as a dict of four 4x4s (row-major lists); a missing link is the identity.
TransformChain chainOf(const py::dict& d) {
    TransformChain c;
    auto get = [&](const char* key, Mat4& m) {
        if (d.contains(key)) m = matrix(d[key].cast<Rows4>());
    };
    get("mount_from_camera", c.mountFromCamera);
    get("machine_from_mount", c.machineFromMount);
    get("assembly_from_machine", c.assemblyFromMachine);
    get("part_from_assembly", c.partFromAssembly);
    return c;
}

template <class T>
void rowOf(const py::dict& d, T& x) {
    if (d.contains("row") && !d["row"].is_none()) x.row = d["row"].cast<int>();
    if (d.contains("station") && !d["station"].is_none()) x.station = d["station"].cast<double>();
}

std::vector<Datum> datumsOf(const py::list& list) {
    std::vector<Datum> out;
    for (const auto& h : list) {
        const auto d = h.cast<py::dict>();
        Datum x;
        x.id = d["id"].cast<std::string>();
        x.nominal = vecOf(d, "nominal");
        x.measured = vecOf(d, "measured");
        if (d.contains("normal") && !d["normal"].is_none()) x.normal = vecOf(d, "normal");
        rowOf(d, x);
        out.push_back(x);
    }
    return out;
}

std::vector<NominalHole> holesOf(const py::list& list) {
    std::vector<NominalHole> out;
    out.reserve(list.size());
    for (const auto& h : list) {
        const auto d = h.cast<py::dict>();
        NominalHole x;
        x.id = d["id"].cast<std::string>();
        x.position = vecOf(d, "position");
        x.normal = vecOf(d, "normal");
        rowOf(d, x);
        out.push_back(x);
    }
    return out;
}

py::dict resultDict(const CompensationResult& r) {
    py::dict out;
    out["method"] = methodName(r.method);
    out["proposed"] = r.proposed ? py::object(py::str(methodName(*r.proposed))) : py::object(py::none());
    py::dict fit;
    std::array<Triple, 3> rotation{};
    for (int i = 0; i < 3; ++i) rotation[static_cast<size_t>(i)] = triple(r.fit.rotation.row(i).transpose());
    fit["rotation"] = rotation;
    fit["scale"] = r.fit.scale;
    fit["translation"] = triple(r.fit.translation);
    out["fit"] = fit;
    py::list loo;
    for (const auto& l : r.leaveOneOut) {
        py::dict d;
        d["method"] = methodName(l.method);
        d["available"] = l.available;
        d["reason"] = l.reason;
        d["rms"] = l.rms;
        d["max"] = l.max;
        d["errors"] = l.errors;
        loo.append(d);
    }
    out["leave_one_out"] = loo;
    py::list datums;
    for (const auto& d : r.datums) {
        py::dict x;
        x["id"] = d.id;
        x["deviation"] = triple(d.deviation);
        x["residual"] = triple(d.residual);
        const auto& v = d.verdict;
        x["use"] = datumUseName(v.use);
        x["used"] = v.use == DatumUse::Used || v.use == DatumUse::PutBack;
        x["miss"] = std::isfinite(v.miss) ? py::object(py::float_(v.miss)) : py::object(py::none());
        x["predictor"] = v.predictor ? py::object(py::str(methodName(*v.predictor))) : py::object(py::none());
        x["predicted"] = triple(v.predicted);
        x["typical"] = std::isfinite(v.typical) ? py::object(py::float_(v.typical)) : py::object(py::none());
        x["limit"] = std::isfinite(v.limit) ? py::object(py::float_(v.limit)) : py::object(py::none());
        x["out_of_line"] = v.outOfLine;
        x["reason"] = v.reason;
        datums.append(x);
    }
    out["datums"] = datums;
    py::dict check;
    check["checked"] = r.check.checked;
    check["note"] = r.check.note;
    check["typical_miss"] = r.check.typicalMiss;
    check["threshold"] = r.check.threshold;
    check["factor"] = r.check.options.factor;
    check["minimum"] = r.check.options.minimum;
    check["left_out"] = r.check.leftOut;
    out["check"] = check;
    py::list holes;
    for (const auto& h : r.holes) {
        py::dict x;
        x["id"] = h.id;
        x["nominal"] = triple(h.nominal);
        x["correction"] = triple(h.correction);
        x["compensated"] = triple(h.compensated);
        x["normal"] = triple(h.normal);
        x["exceeds_tolerance"] = h.exceedsTolerance;
        x["neighbour_departure"] = h.neighbourDeparture;
        x["against_neighbours"] = h.againstNeighbours;
        x["note"] = h.note;
        holes.append(x);
    }
    out["holes"] = holes;
    py::list flags;
    for (const auto& f : r.flags) {
        py::dict x;
        x["kind"] = flagKindName(f.kind);
        x["id"] = f.id;
        x["value"] = f.value;
        x["limit"] = f.limit;
        x["reason"] = f.reason;
        flags.append(x);
    }
    out["flags"] = flags;
    out["flagged_holes"] = r.flaggedHoles;
    return out;
}

py::dict readingDict(const CameraReading& r) {
    py::dict d;
    d["id"] = r.id;
    d["u"] = r.u;
    d["v"] = r.v;
    d["height"] = r.height;
    d["quality"] = r.quality ? py::object(py::float_(*r.quality)) : py::object(py::none());
    d["line"] = r.line;
    return d;
}

}  // namespace

void bindCompensation(py::module_& m) {
    g_compensationError = PyErr_NewException("aeronc._core.CompensationError", PyExc_RuntimeError, nullptr);
    m.attr("CompensationError") = py::handle(g_compensationError);

    m.def("compensation_methods", [] {
        std::vector<std::string> names;
        for (Method x : allMethods()) names.push_back(methodName(x));
        return names;
    }, "Names of the compensation methods, simplest first.");

    m.def(
        "compensate",
        [](const py::list& datums, const py::list& holes, const std::string& method, double tolerance,
           double neighbourTolerance, const std::vector<std::string>& keep, const std::vector<std::string>& drop,
           const py::dict& check) {
            return guardedCompensation([&] {
                CompensationInput in;
                in.datums = datumsOf(datums);
                in.holes = holesOf(holes);
                in.tolerance = tolerance;
                in.neighbourTolerance = neighbourTolerance;
                in.keep = {keep.begin(), keep.end()};
                in.drop = {drop.begin(), drop.end()};
                for (const auto& [key, value] : check) {
                    const auto k = key.cast<std::string>();
                    if (k == "enabled") in.check.enabled = value.cast<bool>();
                    else if (k == "factor") in.check.factor = value.cast<double>();
                    else if (k == "minimum") in.check.minimum = value.cast<double>();
                    else if (k == "max_share") in.check.maxShare = value.cast<double>();
                    else if (k == "min_datums") in.check.minDatums = value.cast<size_t>();
                    else throw compensationError("datum check: unknown option '" + k +
                                                 "' (enabled, factor, minimum, max_share, min_datums)");
                }
                std::optional<Method> chosen;
                if (!method.empty() && method != "proposed") {
                    chosen = methodFromName(method);
                    if (!chosen) {
                        std::string known;
                        for (Method x : allMethods()) known += (known.empty() ? "" : ", ") + methodName(x);
                        throw compensationError("unknown compensation method '" + method + "' (" + known + ", proposed)");
                    }
                }
                CompensationResult r;
                {
                    py::gil_scoped_release nogil;
                    r = compensate(std::move(in), chosen);
                }
                return resultDict(r);
            });
        },
        py::arg("datums"), py::arg("holes"), py::arg("method") = std::string(), py::arg("tolerance") = 0.5,
        py::arg("neighbour_tolerance") = 0.05, py::arg("keep") = std::vector<std::string>(),
        py::arg("drop") = std::vector<std::string>(), py::arg("check") = py::dict(),
        "Compensate holes from measured datum holes. datums: [{id, nominal, measured[, row, station]}], holes: "
        "[{id, position, normal[, row, station]}], method: a name of compensation_methods() or '' / 'proposed' "
        "(lowest leave-one-out error); keep: datum ids put back (never left out), drop: datum ids left out by "
        "hand; check: {enabled, factor, minimum, max_share, min_datums} of the datum check. Returns {method, "
        "proposed, fit, leave_one_out (over the datum holes used), check, datums (every one, with use, miss, "
        "reason), holes, flags [{kind, id, value, limit, reason}], flagged_holes}.");

    m.def(
        "find_rows",
        [](const std::vector<Triple>& points, double maxTurnDegrees, double maxGapFactor) {
            return guardedCompensation([&] {
                std::vector<Vec3> p;
                for (const auto& t : points) p.push_back(vec(t));
                RowOptions o;
                o.maxTurnDegrees = maxTurnDegrees;
                o.maxGapFactor = maxGapFactor;
                const HoleRows r = findRows(p, o);
                return py::make_tuple(r.row, r.station, r.members);
            });
        },
        py::arg("points"), py::arg("max_turn_degrees") = 30.0, py::arg("max_gap_factor") = 2.5,
        "Rows of holes: (row per point, station per point, members per row).");

    m.def(
        "row_correction",
        [](const Triple& first, const Triple& last, double S, double Si) {
            return guardedCompensation([&] { return triple(rowCorrection(vec(first), vec(last), S, Si)); });
        },
        py::arg("deviation_first"), py::arg("deviation_last"), py::arg("S"), py::arg("S_i"),
        "The seed's formula: dP_1 (S - S_i)/S + dP_n S_i/S.");

    m.def(
        "read_measurements",
        [](const std::string& text) {
            return guardedCompensation([&] {
                py::list out;
                for (const auto& r : readMeasurementCsv(text)) out.append(readingDict(r));
                return out;
            });
        },
        py::arg("text"), "Parse the camera's measurement file (hole,u,v,height[,quality]); refuses bad input.");

    m.def(
        "import_measurements",
        [](const std::string& text, const py::list& datums, double maxDeviation, double minQuality) {
            return guardedCompensation([&] {
                std::vector<DatumFrame> frames;
                for (const auto& h : datums) {
                    const auto d = h.cast<py::dict>();
                    DatumFrame f;
                    f.id = d["id"].cast<std::string>();
                    f.nominal = vecOf(d, "nominal");
                    if (d.contains("normal")) f.normal = vecOf(d, "normal");
                    f.chain = chainOf(d["chain"].cast<py::dict>());
                    frames.push_back(f);
                }
                ImportOptions o;
                o.maxDeviation = maxDeviation;
                o.minQuality = minQuality;
                std::vector<ImportedDatum> imported;
                {
                    py::gil_scoped_release nogil;
                    imported = importMeasurements(readMeasurementCsv(text), frames, o);
                }
                py::list out;
                for (const auto& x : imported) {
                    py::dict d = readingDict(x.reading);
                    d["nominal"] = triple(x.datum.nominal);
                    d["measured"] = triple(x.datum.measured);
                    d["deviation"] = triple(x.datum.deviation());
                    out.append(d);
                }
                return out;
            });
        },
        py::arg("text"), py::arg("datums"), py::arg("max_deviation") = 5.0, py::arg("min_quality") = 0.0,
        "Import the camera's measurement file for the datum holes [{id, nominal, normal, chain}] (chain: "
        "{mount_from_camera, machine_from_mount, assembly_from_machine, part_from_assembly} as 4x4 row lists): "
        "[{id, u, v, height, quality, line, nominal, measured, deviation}] in the datums' order.");

    m.def(
        "camera_to_part",
        [](const py::dict& chain, const Triple& uvh) {
            return guardedCompensation([&] {
                const TransformChain c = chainOf(chain);
                requireRigid(c);
                return triple(c.toPart(vec(uvh)));
            });
        },
        py::arg("chain"), py::arg("uvh"), "(U, V, height) in the camera frame -> the part frame.");

    m.def(
        "part_to_camera",
        [](const py::dict& chain, const Triple& p) {
            return guardedCompensation([&] {
                const TransformChain c = chainOf(chain);
                requireRigid(c);
                return triple(c.toCamera(vec(p)));
            });
        },
        py::arg("chain"), py::arg("point"), "A point of the part frame -> (U, V, height) in the camera frame.");

    m.def(
        "frame_at",
        [](const Triple& origin, const Triple& axis, const Triple& x) {
            return guardedCompensation([&] { return rows4(frameAt(vec(origin), vec(axis), vec(x))); });
        },
        py::arg("origin"), py::arg("axis"), py::arg("x_direction"),
        "A 4x4 frame at origin with z = axis and x = x_direction made perpendicular to it.");

    m.def(
        "check_rigid",
        [](const Rows4& m4, const std::string& name) {
            guardedCompensation([&] { requireRigid(matrix(m4), name); });
        },
        py::arg("matrix"), py::arg("name"), "Raise CompensationError unless the 4x4 is a rigid transform.");
}
