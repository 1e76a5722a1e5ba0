#pragma once
// Faults inside OpenCASCADE as errors. A damaged STEP file or B-rep can make OCCT dereference a
// null handle or divide by zero; left alone, the signal kills the program (and, inside FreeCAD,
// the user's session). Here OCCT's own signal handlers turn such a fault into an exception at
// the nearest jump point, and the caller gets an aeronc::Error instead.
#include <functional>
#include <string>

namespace aeronc {

// Runs f with OCCT's signal handlers (OSD::SetSignal, no floating-point traps) and a jump
// point (OCC_CATCH_SIGNALS) around it; the process's previous handlers and floating-point
// environment are put back afterwards, so a host such as FreeCAD keeps its own. A fault in f
// (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS) throws inputError("<what>: OpenCASCADE failed (...)").
// Memory held by the frames the fault jumped over is not freed. Only the calling thread's
// faults are caught.
void runCatchingOcctFaults(const std::function<void()>& f, const std::string& what);

}  // namespace aeronc
