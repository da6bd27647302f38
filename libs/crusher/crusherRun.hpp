#pragma once
// A bondedDemFoam run of a cone crusher (constant/loading has a `machine` section):
// the gyrating mantle and the fixed concave as triangulated walls, the feed factory,
// the choke plane, the destructor below the discharge (docs/theory-crusher.md).
//
//   CrusherRun run(app);   // reads and checks every input (UserError before any step)
//   return run.execute();  // time loop; returns the exit code
//
// Writes postProcessing/machine/0/machine.dat (mantle force, torque about the pivot,
// power, masses inside, fed and discharged, energies), postProcessing/discharge/0/
// discharge.dat (one row per fragment that left) and VTK/cells_<step>.vtu.
#include <memory>

#include "core/application.hpp"

namespace rockfrac {

class CrusherRun {
public:
    explicit CrusherRun(const Application& app);
    ~CrusherRun();
    CrusherRun(const CrusherRun&) = delete;
    CrusherRun& operator=(const CrusherRun&) = delete;

    void printSetup() const;
    int execute();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rockfrac
