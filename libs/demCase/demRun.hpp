#pragma once
// A bondedDemFoam run: everything between reading the case and the last write.
//
// The solver application is a thin main over this class:
//   BondedDemRun run(app);   // reads and checks every input (UserError before any step)
//   return run.execute();    // time loop; returns the exit code
#include <memory>

#include "core/application.hpp"

namespace rockfrac {

class BondedDemRun {
public:
    explicit BondedDemRun(const Application& app);
    ~BondedDemRun();
    BondedDemRun(const BondedDemRun&) = delete;
    BondedDemRun& operator=(const BondedDemRun&) = delete;

    void printSetup() const;
    int execute();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rockfrac
