#pragma once
// Fault injection for the interruption tests (tests/case/reliability).
//
// ROCKFRAC_KILL_AT="<point>:<n>" makes the process kill itself with SIGKILL the
// n-th time it passes `faultPoint("<point>")` (n counts from 1). Without the
// variable a fault point costs one cached comparison. The points:
//   staged        a time directory's staging directory was just created
//   beforeCommit  the time directory's files and its VTK frames are written, not yet published
//   beforeRename  an atomically written file is complete under its temporary name
// A malformed variable is a UserError naming it.

namespace rockfrac {

void faultPoint(const char* point);

}  // namespace rockfrac
