#pragma once
// A feFractureSolver run: everything between reading the case and the last write.
//
// The solver application is a thin main over this class:
//   FeFractureRun run(app);   // reads and checks every input (UserError before any step)
//   return run.execute();     // time loop; returns the exit code
#include <memory>

#include "core/application.hpp"

namespace rockfrac {

class FeFractureRun {
public:
    explicit FeFractureRun(const Application& app);
    ~FeFractureRun();
    FeFractureRun(const FeFractureRun&) = delete;
    FeFractureRun& operator=(const FeFractureRun&) = delete;

    void printSetup() const;
    int execute();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rockfrac
