// The APT reader, and the posts from what it reads, for both machines in both dialects.
#include "NcProgramCheck.h"

#include <aeronc/post/Post.h>

using namespace aeronc;
using namespace aeronc::post;

namespace {
const kinematics::MachineModel& machine(int i) {
    static const kinematics::MachineModel m[2] = {kinematics::loadMachineFile(AERONC_MACHINES "/AC-5AX.json"),
                                                  kinematics::loadMachineFile(AERONC_MACHINES "/AC-HEAD.json")};
    return m[i];
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string apt = fuzz::text(data, size);
    kinematics::ClProgram program;
    if (!fuzz::expectingErrors([&] { program = readApt(apt); })) return 0;
    fuzz::expectingErrors([&] { readApt(writeApt(program)); });
    for (int m = 0; m < 2; ++m)
        for (const Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
            NcOptions o;
            o.dialect = d;
            PostSummary s;
            if (fuzz::expectingErrors([&] { s = postProgram(program, machine(m), o, {}); })) fuzz::checkNcProgram(s.text);
        }
    return 0;
}
