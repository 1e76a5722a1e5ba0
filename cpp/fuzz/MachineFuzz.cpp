// Machine files: the reader, then a short program with a tilted tool axis, an arc and a
// drilling cycle posted for the machine read, in both dialects.
#include "NcProgramCheck.h"

#include <aeronc/post/Post.h>

using namespace aeronc;
using namespace aeronc::post;

namespace {
const char* kProgram = R"(LOADTL/1
SPINDL/6000,CLW
RAPID
GOTO/0,0,50,0,0,1
FEDRAT/800
GOTO/10,0,5,0.3420201433,0,0.9396926208
GOTO/20,5,5,0.3420201433,0,0.9396926208
RAPID
GOTO/0,0,50,0,0,1
CYCLE/DEEP,FEDTO,8,RAPTO,2,STEP,2,MMPM,300
GOTO/30,10,0
CYCLE/OFF
FINI
)";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const kinematics::ClProgram program = readApt(kProgram);
    kinematics::MachineModel m;
    if (!fuzz::expectingErrors([&] { m = kinematics::machineFromJson(fuzz::text(data, size), "fuzz.json"); })) return 0;
    for (const Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        NcOptions o;
        o.dialect = d;
        PostSummary s;
        if (fuzz::expectingErrors([&] { s = postProgram(program, m, o, {}); })) fuzz::checkNcProgram(s.text);
    }
    return 0;
}
