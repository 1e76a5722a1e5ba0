#pragma once
// APT cutter-location files (statements as in docs/post.md): GOTO/x,y,z,i,j,k, RAPID,
// FEDRAT/f,MMPM, SPINDL/n,CLW|CCLW|OFF, LOADTL/n[,LENGTH,l], CUTTER/d[,r], COOLNT/...,
// CIRCLE/xc,yc,zc,i,j,k,r + GOTO, CYCLE/DRILL|DEEP|BRKCHP,... + GOTO + CYCLE/OFF, DELAY/s,
// PPRINT/..., PARTNO/..., FINI. `$$` starts a comment, a trailing `$` continues a statement.
#include <aeronc/kinematics/ClProgram.h>

namespace aeronc::post {

// Writes the CL program; positions and vectors with `decimals` decimals. Moves that do not
// yet know every coordinate (FreeCAD's first clearance moves) have no GOTO form and are left
// as $$ comments.
std::string writeApt(const kinematics::ClProgram& program, int decimals = 10);

// Reads an APT CL file; errors name the line.
kinematics::ClProgram readApt(const std::string& text);

}  // namespace aeronc::post
