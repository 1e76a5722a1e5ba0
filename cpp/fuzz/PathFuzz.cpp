// The Path (G-code) reader of the posts: the input is one operation's Path.toGCode() text
// behind a work offset and a tool controller; then the posts in both dialects, and the APT
// written from it read back.
#include "NcProgramCheck.h"

#include <aeronc/post/Post.h>

using namespace aeronc;
using namespace aeronc::post;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const kinematics::MachineModel machine = kinematics::loadMachineFile(AERONC_MACHINES "/AC-5AX.json");
    std::vector<PathSection> sections(3);
    sections[0].kind = PathSection::Kind::WorkOffset;
    sections[0].label = "Fixture";
    sections[0].gcode = "G54\n";
    sections[1].kind = PathSection::Kind::ToolChange;
    sections[1].label = "TC";
    sections[1].tool.number = 3;
    sections[1].tool.diameter = 10;
    sections[1].rpm = 8000;
    sections[1].spindleDir = 1;
    sections[2].label = "Op";
    sections[2].gcode = fuzz::text(data, size);
    sections[2].coolant = "flood";
    kinematics::ClProgram program;
    if (!fuzz::expectingErrors([&] { program = readFreeCadPath(sections, "FUZZ"); })) return 0;
    fuzz::expectingErrors([&] { readApt(writeApt(program)); });
    for (const Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        NcOptions o;
        o.dialect = d;
        PostSummary s;
        if (fuzz::expectingErrors([&] { s = postProgram(program, machine, o, {}); })) fuzz::checkNcProgram(s.text);
    }
    return 0;
}
