// aeronc._core: the 5-axis kinematics and the posts. Every C++ exception stops here and becomes
// PostError (a RuntimeError) with the core's message; the posting itself runs without the GIL.
#include "Guarded.h"

#include <aeronc/core/JsonNesting.h>

#include <aeronc/post/Post.h>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace py = pybind11;
using namespace aeronc::kinematics;
using namespace aeronc::post;

namespace {

PyObject* g_postError = nullptr;

template <class F>
auto guardedPost(F f) -> decltype(f()) {
    return aeronc::python::guardedAs(g_postError, f);
}

template <class T>
T item(const py::dict& d, const char* key, T fallback) {
    return d.contains(key) ? d[key].cast<T>() : fallback;
}

// Sections come from aeronc.post.job as dicts: kind ("offset", "tool", "operation"), label,
// gcode, tool {number, name, diameter, corner_radius, length}, rpm, spindle_dir, coolant,
// has_tool_controller.
std::vector<PathSection> sectionsFrom(const py::list& list) {
    std::vector<PathSection> out;
    out.reserve(list.size());
    for (const auto& h : list) {
        const py::dict d = h.cast<py::dict>();
        PathSection s;
        const auto kind = item<std::string>(d, "kind", "operation");
        if (kind == "offset") s.kind = PathSection::Kind::WorkOffset;
        else if (kind == "tool") s.kind = PathSection::Kind::ToolChange;
        else if (kind == "operation") s.kind = PathSection::Kind::Operation;
        else throw aeronc::inputError("unknown section kind '" + kind + "'");
        s.label = item<std::string>(d, "label", "");
        s.gcode = item<std::string>(d, "gcode", "");
        if (d.contains("tool")) {
            const py::dict t = d["tool"].cast<py::dict>();
            s.tool.number = item<int>(t, "number", 0);
            s.tool.name = item<std::string>(t, "name", "");
            s.tool.diameter = item<double>(t, "diameter", 0.0);
            s.tool.cornerRadius = item<double>(t, "corner_radius", 0.0);
            s.tool.length = item<double>(t, "length", 0.0);
        }
        s.rpm = item<double>(d, "rpm", 0.0);
        s.spindleDir = item<int>(d, "spindle_dir", 0);
        s.coolant = item<std::string>(d, "coolant", "none");
        s.hasToolController = item<bool>(d, "has_tool_controller", true);
        out.push_back(std::move(s));
    }
    return out;
}

// Options as JSON text, keys as in docs/post.md.
// A whole-number option, refused rather than wrapped when it does not fit an int.
int wholeOption(const nlohmann::json& v, const std::string& key) {
    if (!v.is_number_integer() || v.get<long long>() < -1000000 || v.get<long long>() > 1000000)
        throw aeronc::inputError("post option '" + key + "' must be a whole number");
    return static_cast<int>(v.get<long long>());
}

std::pair<NcOptions, PlanOptions> optionsFrom(const std::string& text) {
    aeronc::checkJsonNesting(text, "post options");
    const auto j = text.empty() ? nlohmann::json::object() : nlohmann::json::parse(text);
    if (!j.is_object()) throw aeronc::inputError("post options must be a JSON object");
    NcOptions nc;
    PlanOptions plan;
    for (auto it = j.begin(); it != j.end(); ++it) {
        const std::string& k = it.key();
        const auto& v = it.value();
        if (k == "dialect") {
            const auto d = v.get<std::string>();
            if (d == "840d") nc.dialect = Dialect::Sinumerik840D;
            else if (d == "linuxcnc") nc.dialect = Dialect::LinuxCnc;
            else throw aeronc::inputError("unknown dialect '" + d + "' (840d, linuxcnc)");
        } else if (k == "vectors") nc.vectors = v.get<bool>();
        else if (k == "precision") nc.precision = wholeOption(v, k);
        else if (k == "angle_precision") nc.anglePrecision = wholeOption(v, k);
        else if (k == "vector_precision") nc.vectorPrecision = wholeOption(v, k);
        else if (k == "comments") nc.comments = v.get<bool>();
        else if (k == "line_numbers") nc.lineNumbers = v.get<bool>();
        else if (k == "inverse_time") nc.inverseTime = v.get<bool>();
        else if (k == "tool_by_name") nc.toolByName = v.get<bool>();
        else if (k == "smoothing") nc.smoothing = v.get<std::string>();
        else if (k == "smoothing_tolerance") nc.smoothingTolerance = v.get<double>();
        else if (k == "program_name") nc.programName = v.get<std::string>();
        else if (k == "part_zero") {
            const auto p = v.get<std::vector<double>>();
            if (p.size() != 3) throw aeronc::inputError("part_zero must be [x, y, z]");
            plan.partZero = Vec3(p[0], p[1], p[2]);
        } else if (k == "retract") plan.retractDistance = v.get<double>();
        else if (k == "chord") plan.chordTolerance = v.get<double>();
        else throw aeronc::inputError("unknown post option '" + k + "'");
    }
    return {nc, plan};
}

py::dict summaryOf(const PostSummary& s) {
    py::dict d;
    d["lines"] = s.lines;
    d["moves"] = s.moves;
    d["branch_changes"] = s.branchChanges;
    d["segments"] = s.segments;
    return d;
}

MachineModel machineOf(const std::string& jsonText, const std::string& source) { return machineFromJson(jsonText, source); }

}  // namespace

void bindKinematics(py::module_& m) {
    g_postError = PyErr_NewException("aeronc._core.PostError", PyExc_RuntimeError, nullptr);
    m.attr("PostError") = py::handle(g_postError);

    m.def(
        "post_nc",
        [](const py::list& sections, const std::string& machineJson, const std::string& machineSource,
           const std::string& options) {
            return guardedPost([&] {
                const auto secs = sectionsFrom(sections);
                const auto [nc, plan] = optionsFrom(options);
                const MachineModel machine = machineOf(machineJson, machineSource);
                PostSummary s;
                {
                    py::gil_scoped_release nogil;
                    s = postFreeCad(secs, machine, nc, plan);
                }
                return py::make_tuple(py::bytes(s.text), summaryOf(s));
            });
        },
        py::arg("sections"), py::arg("machine_json"), py::arg("machine_source"), py::arg("options_json") = std::string(),
        "Post FreeCAD Path sections for a machine: (NC text as UTF-8 bytes, summary dict).");

    m.def(
        "post_apt",
        [](const std::string& apt, const std::string& machineJson, const std::string& machineSource,
           const std::string& options) {
            return guardedPost([&] {
                const auto [nc, plan] = optionsFrom(options);
                const MachineModel machine = machineOf(machineJson, machineSource);
                PostSummary s;
                {
                    py::gil_scoped_release nogil;
                    s = postApt(apt, machine, nc, plan);
                }
                return py::make_tuple(py::bytes(s.text), summaryOf(s));
            });
        },
        py::arg("apt_text"), py::arg("machine_json"), py::arg("machine_source"), py::arg("options_json") = std::string(),
        "Post an APT CL file for a machine: (NC text as UTF-8 bytes, summary dict).");

    m.def(
        "write_apt",
        [](const py::list& sections, const std::string& name) {
            return guardedPost([&] {
                const auto secs = sectionsFrom(sections);
                py::gil_scoped_release nogil;
                return writeApt(readFreeCadPath(secs, name));
            });
        },
        py::arg("sections"), py::arg("program_name"), "FreeCAD Path sections -> APT CL text (workpiece frame).");

    m.def(
        "check_machine",
        [](const std::string& machineJson, const std::string& source) {
            return guardedPost([&] {
                const MachineModel mm = machineOf(machineJson, source);
                py::dict d;
                d["name"] = mm.name;
                d["kinematics"] = mm.kinematicsName();
                d["controller"] = mm.controller;
                py::list axes;
                for (const auto& a : mm.rotary) {
                    py::dict ad;
                    ad["name"] = a.name;
                    ad["carrier"] = a.carrier == Carrier::Table ? "table" : "head";
                    ad["min"] = a.min;
                    ad["max"] = a.max;
                    axes.append(ad);
                }
                d["rotary_axes"] = axes;
                return d;
            });
        },
        py::arg("machine_json"), py::arg("source"), "Validate a machine file; returns its summary.");

    m.def(
        "forward_kinematics",
        [](const std::string& machineJson, const std::array<double, 3>& linear, const std::array<double, 2>& rotary,
           const std::optional<std::array<double, 3>>& partZero, double toolLength) {
            return guardedPost([&] {
                MachineSetup setup;
                if (partZero) setup.partZero = Vec3((*partZero)[0], (*partZero)[1], (*partZero)[2]);
                setup.toolLength = toolLength;
                const Kinematics kin(machineOf(machineJson, "machine"), setup);
                Joints j;
                j.linear = Vec3(linear[0], linear[1], linear[2]);
                j.rotary = rotary;
                const ToolPose p = kin.forward(j);
                return py::make_tuple(std::array<double, 3>{p.tip.x(), p.tip.y(), p.tip.z()},
                                      std::array<double, 3>{p.axis.x(), p.axis.y(), p.axis.z()});
            });
        },
        py::arg("machine_json"), py::arg("linear"), py::arg("rotary"), py::arg("part_zero") = py::none(),
        py::arg("tool_length") = 0.0, "Machine axes -> (tool tip, tool axis) in the workpiece frame.");

    m.def(
        "forward_kinematics_many",
        [](const std::string& machineJson, const std::vector<std::array<double, 5>>& joints,
           const std::optional<std::array<double, 3>>& partZero, double toolLength) {
            return guardedPost([&] {
                MachineSetup setup;
                if (partZero) setup.partZero = Vec3((*partZero)[0], (*partZero)[1], (*partZero)[2]);
                setup.toolLength = toolLength;
                // The machine read once for a whole program: a call per move spent most of the
                // verification's time reading it again.
                const Kinematics kin(machineOf(machineJson, "machine"), setup);
                std::vector<std::array<double, 3>> tips(joints.size()), axes(joints.size());
                {
                    py::gil_scoped_release nogil;
                    for (std::size_t i = 0; i < joints.size(); ++i) {
                        Joints j;
                        j.linear = Vec3(joints[i][0], joints[i][1], joints[i][2]);
                        j.rotary = {joints[i][3], joints[i][4]};
                        const ToolPose p = kin.forward(j);
                        tips[i] = {p.tip.x(), p.tip.y(), p.tip.z()};
                        axes[i] = {p.axis.x(), p.axis.y(), p.axis.z()};
                    }
                }
                return py::make_tuple(tips, axes);
            });
        },
        py::arg("machine_json"), py::arg("joints"), py::arg("part_zero") = py::none(), py::arg("tool_length") = 0.0,
        "[[x, y, z, a, c], ...] machine axes -> ([tool tip], [tool axis]) in the workpiece frame, the machine "
        "read once.");

    m.def(
        "inverse_kinematics",
        [](const std::string& machineJson, const std::array<double, 3>& axis, const std::array<double, 2>& keep) {
            return guardedPost([&] {
                const Kinematics kin(machineOf(machineJson, "machine"));
                std::vector<std::array<double, 2>> out;
                for (const auto& s : kin.orientations(Vec3(axis[0], axis[1], axis[2]), keep)) out.push_back(s.angles);
                return out;
            });
        },
        py::arg("machine_json"), py::arg("axis"), py::arg("keep") = std::array<double, 2>{0.0, 0.0},
        "Both rotary solutions (degrees) for a tool axis; at the pole the free axis keeps `keep`.");
}
