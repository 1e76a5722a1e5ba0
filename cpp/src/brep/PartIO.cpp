#include <aeronc/core/Error.h>
#include <aeronc/brep/PartIO.h>

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <BRepClass3d_SolidClassifier.hxx>

#include <StepRepr_RepresentationItem.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <BRep_Tool.hxx>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace aeronc {
namespace {

std::string head(const std::string& path, std::size_t n) {
    std::ifstream in(path, std::ios::binary);
    std::string s(n, '\0');
    in.read(&s[0], static_cast<std::streamsize>(n));
    s.resize(static_cast<std::size_t>(in.gcount()));
    return s;
}

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum t) {
    int n = 0;
    for (TopExp_Explorer e(s, t); e.More(); e.Next()) ++n;
    return n;
}

}  // namespace

TopoDS_Shape validatedSolid(const TopoDS_Shape& shape, const std::string& origin) {
    if (shape.IsNull()) throw inputError(origin + ": holds no shape");
    const int solids = count(shape, TopAbs_SOLID);
    if (solids > 1)
        throw inputError(origin + ": holds " + std::to_string(solids) +
                         " solids; recognition needs one part (fuse or pick one solid)");
    TopoDS_Shape solid;
    if (solids == 1) {
        TopExp_Explorer e(shape, TopAbs_SOLID);
        solid = e.Current();
    } else {
        const int shells = count(shape, TopAbs_SHELL);
        if (shells == 0) throw inputError(origin + ": holds no solid and no shell, only loose geometry");
        throw inputError(origin + ": holds a shell, not a closed solid; close the shell and make a solid first");
    }
    if (count(solid, TopAbs_FACE) == 0) throw inputError(origin + ": the solid has no faces");
    for (TopExp_Explorer e(solid, TopAbs_SHELL); e.More(); e.Next()) {
        if (!BRep_Tool::IsClosed(e.Current()))
            throw inputError(origin + ": the solid's shell is open (free edges); it is not a closed solid");
    }
    BRepCheck_Analyzer check(solid);
    if (!check.IsValid())
        throw inputError(origin + ": the B-rep is invalid (degenerate or self-intersecting faces or edges); "
                                  "repair it, e.g. with Part > Check geometry and Refine/Fix");
    return solid;
}

TopoDS_Shape partFromBrepText(const std::string& text) { return validatedSolid(shapeFromBrepText(text), "BREP text"); }

TopoDS_Shape shapeFromBrepText(const std::string& text) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw inputError("BREP text is empty");
    std::istringstream in(text);
    TopoDS_Shape shape;
    BRep_Builder builder;
    try {
        BRepTools::Read(shape, in, builder);
    } catch (const Standard_Failure& f) {
        throw inputError(std::string("BREP text could not be read: ") + f.GetMessageString());
    }
    if (shape.IsNull()) throw inputError("BREP text could not be read: not an OpenCASCADE BREP shape");
    return shape;
}

TopoDS_Shape loadPart(const std::string& path) { return validatedSolid(loadShape(path), path); }

TopoDS_Shape loadShape(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw inputError(path + ": no such file");
    if (fs::is_directory(path, ec)) throw inputError(path + ": is a folder, not a part file");
    if (fs::file_size(path, ec) == 0) throw inputError(path + ": the file is empty");
    const std::string start = head(path, 4096);
    TopoDS_Shape shape;
    try {
        if (start.find("ISO-10303-21") != std::string::npos) {
            STEPControl_Reader reader;
            if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
                throw inputError(path + ": the STEP file could not be parsed");
            if (reader.TransferRoots() == 0) throw inputError(path + ": the STEP file holds no shape");
            shape = reader.OneShape();
        } else if (start.find("CASCADE Topology") != std::string::npos) {
            BRep_Builder builder;
            if (!BRepTools::Read(shape, path.c_str(), builder))
                throw inputError(path + ": the BREP file could not be read");
        } else {
            throw inputError(path + ": not a STEP (ISO-10303-21) or OpenCASCADE BREP file");
        }
    } catch (const Standard_Failure& f) {
        throw inputError(path + ": reading failed: " + f.GetMessageString());
    }
    if (shape.IsNull()) throw inputError(path + ": holds no shape");
    return shape;
}

TopoDS_Shape loadStepWithFaceNames(const std::string& path, std::vector<std::string>& faceNames) {
    if (head(path, 4096).find("ISO-10303-21") == std::string::npos) throw inputError(path + ": not a STEP file");
    STEPControl_Reader reader;
    TopoDS_Shape solid;
    try {
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw inputError(path + ": the STEP file could not be parsed");
        if (reader.TransferRoots() == 0) throw inputError(path + ": the STEP file holds no shape");
        solid = validatedSolid(reader.OneShape(), path);
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(solid, TopAbs_FACE, faces);
        const Handle(XSControl_TransferReader) tr = reader.WS()->TransferReader();
        faceNames.assign(static_cast<std::size_t>(faces.Extent()), std::string());
        for (int i = 1; i <= faces.Extent(); ++i) {
            Handle(StepRepr_RepresentationItem) item =
                Handle(StepRepr_RepresentationItem)::DownCast(tr->EntityFromShapeResult(faces(i), 1));
            if (!item.IsNull() && !item->Name().IsNull()) faceNames[static_cast<std::size_t>(i - 1)] = item->Name()->ToCString();
        }
    } catch (const Standard_Failure& f) {
        throw inputError(path + ": reading failed: " + f.GetMessageString());
    }
    return solid;
}

namespace {
// Written beside the target and renamed, so a failed write never leaves a partial file.
template <class Write>
void atomicWrite(const std::string& path, Write write) {
    const std::string tmp = path + ".part";
    if (!write(tmp)) {
        std::remove(tmp.c_str());
        throw inputError(path + ": could not be written");
    }
    std::filesystem::rename(tmp, path);
}
}  // namespace

void writeStep(const TopoDS_Shape& shape, const std::string& path) {
    atomicWrite(path, [&](const std::string& tmp) {
        STEPControl_Writer writer;
        if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone) return false;
        return writer.Write(tmp.c_str()) == IFSelect_RetDone;
    });
}

void writeBrep(const TopoDS_Shape& shape, const std::string& path) {
    atomicWrite(path, [&](const std::string& tmp) { return BRepTools::Write(shape, tmp.c_str()); });
}

}  // namespace aeronc
