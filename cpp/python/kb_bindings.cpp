// aeronc._core.KnowledgeBase: the knowledge base for FreeCAD's Python side (the editor
// panel, the tool bridge and the Select tools command).
#include <aeronc/kb/FreeCadToolLibrary.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <pybind11/stl.h>

#include "Guarded.h"

namespace py = pybind11;

namespace aeronc::python {

namespace {

py::dict toolDict(const toolselect::Tool& t) {
    py::dict d;
    d["id"] = t.id;
    d["type"] = t.type;
    d["material"] = t.material;
    d["diameter"] = t.diameter;
    d["cornerRadius"] = t.cornerRadius;
    d["fluteLength"] = t.fluteLength;
    d["reach"] = t.reach;
    d["neckDiameter"] = t.neckDiameter;
    d["flutes"] = t.flutes;
    return d;
}

}  // namespace

void bindKnowledgeBase(py::module_& m) {
    using kb::KnowledgeBase;
    py::class_<KnowledgeBase>(m, "KnowledgeBase",
                              "The machining knowledge base (SQLite). Opening a missing file builds it from "
                              "sql_folder's schema.sql and default_data.sql; an older file is migrated.")
        .def(py::init([](const std::string& path, const std::string& sqlFolder) {
                 return guarded([&] { return KnowledgeBase::openWithSqlFolder(path, [&] { return sqlFolder; }); });
             }),
             py::arg("path"), py::arg("sql_folder"))
        .def_property_readonly("path", &KnowledgeBase::path)
        .def_property_readonly("schema_version", [](const KnowledgeBase& k) { return guarded([&] { return k.schemaVersion(); }); })
        .def("tools", [](const KnowledgeBase& k) {
            return guarded([&] {
                py::list out;
                for (const auto& t : k.tools()) out.append(toolDict(t));
                return out;
            });
        })
        .def("workpiece_materials", [](const KnowledgeBase& k) { return guarded([&] { return k.workpieceMaterials(); }); })
        .def("machine_names", [](const KnowledgeBase& k) { return guarded([&] { return k.machineNames(); }); })
        .def("threshold", [](const KnowledgeBase& k, const std::string& n) { return guarded([&] { return k.threshold(n); }); })
        .def("cutting_condition",
             [](const KnowledgeBase& k, const std::string& material, const std::string& toolMaterial,
                const std::string& op, std::optional<double> diameter) {
                 return guarded([&] {
                     const auto c = k.cuttingCondition(material, toolMaterial, op, diameter);
                     py::dict d;
                     d["vc"] = c.vc, d["fz"] = c.fz, d["ap"] = c.ap, d["aeRatio"] = c.aeRatio;
                     d["cF"] = c.cF, d["xF"] = c.xF, d["yF"] = c.yF, d["uF"] = c.uF, d["qF"] = c.qF;
                     d["wF"] = c.wF, d["kFc"] = c.kFc, d["taylorC"] = c.taylorC, d["taylorM"] = c.taylorM;
                     d["dMin"] = c.dMin, d["dMax"] = c.dMax;
                     return d;
                 });
             },
             py::arg("material"), py::arg("tool_material"), py::arg("operation"), py::arg("diameter") = py::none())
        .def_static("editable_tables", &KnowledgeBase::editableTables)
        .def("table",
             [](const KnowledgeBase& k, const std::string& name) {
                 return guarded([&] {
                     const kb::Table t = k.table(name);
                     py::list cols;
                     for (const auto& c : t.columns) {
                         py::dict d;
                         d["name"] = c.name, d["type"] = c.type, d["notNull"] = c.notNull, d["primaryKey"] = c.primaryKey;
                         cols.append(d);
                     }
                     py::dict d;
                     d["name"] = t.name, d["columns"] = cols, d["rowIds"] = t.rowIds, d["rows"] = t.rows;
                     return d;
                 });
             })
        .def("edit_table",
             [](KnowledgeBase& k, const std::string& name,
                const std::vector<std::tuple<long long, std::string, kb::Cell>>& edits,
                const std::vector<std::vector<kb::Cell>>& inserts, const std::vector<long long>& deletes) {
                 guarded([&] {
                     std::vector<kb::CellEdit> e;
                     for (const auto& [row, col, value] : edits) e.push_back({row, col, value});
                     k.editTable(name, e, inserts, deletes);
                     return 0;
                 });
             },
             py::arg("table"), py::arg("edits") = std::vector<std::tuple<long long, std::string, kb::Cell>>{},
             py::arg("inserts") = std::vector<std::vector<kb::Cell>>{}, py::arg("deletes") = std::vector<long long>{},
             "Apply (row_id, column, text-or-None) edits, then inserts, then deletes, in one transaction.")
        .def("import_freecad_library",
             [](KnowledgeBase& k, const std::string& fctl, const std::string& toolMaterial, int flutes) {
                 return guarded([&] { return k.importFreeCadLibrary(kb::readFreeCadLibrary(fctl), {toolMaterial, flutes}); });
             },
             py::arg("fctl_path"), py::arg("tool_material") = "carbide", py::arg("flutes") = 2,
             "Import a FreeCAD .fctl library and its .fctb bits, all or nothing; returns the number of tools.")
        .def("freecad_library_names", [](const KnowledgeBase& k) { return guarded([&] { return k.freeCadLibraryNames(); }); })
        .def("export_freecad_library",
             [](const KnowledgeBase& k, const std::string& name, const std::string& folder) {
                 return guarded([&] { return kb::writeFreeCadLibrary(k.freeCadLibrary(name), folder); });
             },
             py::arg("name"), py::arg("folder"),
             "Write <folder>/Library/<name>.fctl and its bits in <folder>/Bit; returns the paths.")
        .def("export_tools",
             [](const KnowledgeBase& k, const std::string& name, const std::vector<std::string>& ids,
                const std::string& folder) {
                 return guarded([&] { return kb::writeFreeCadLibrary(k.freeCadLibraryOf(name, ids), folder); });
             },
             py::arg("name"), py::arg("tool_ids"), py::arg("folder"),
             "Write the given tools as a FreeCAD library numbered 1, 2, ...; returns the paths.")
        .def("bit_document",
             [](const KnowledgeBase& k, const std::string& toolId) {
                 return guarded([&] {
                     const auto lib = k.freeCadLibraryOf("", {toolId});
                     return py::make_tuple(lib.bits.at(0).fileName, lib.bits.at(0).document);
                 });
             },
             py::arg("tool_id"), "(file name, .fctb JSON text) of one tool.");
}

}  // namespace aeronc::python
