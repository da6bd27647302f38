// bondedDemFoam: the bonded Voronoi DEM solver (physics.md §3).
//
// Rigid Voronoi cells (dilated polyhedra) glued at their face vertices by
// cohesive bonds that soften and break (Eqs. 5-20, Algorithm 1), then touching
// by Hertz-Mindlin contact, loaded by rigid plates.
//
// Reads  system/controlDict, constant/rockProperties, constant/loading,
//        constant/voronoiMesh/ (voronoiMesh)
// A `machine` section in constant/loading instead of `plates` runs a cone crusher
// (libs/crusher, docs/user-guide-crusher.md): mantle and concave from meshCrusher,
// the feed factory, the choke plane and the destructor; it writes
// postProcessing/machine/0/machine.dat and postProcessing/discharge/0/discharge.dat.
// Writes <time>/demState (restart), postProcessing/plateForce/0/plateForce.dat,
//        VTK/cells_<step>.vtu, VTK/bonds_<step>.vtp and their .series files
// `mpirun -np N bondedDemFoam -parallel` decomposes the case over N ranks
// (system/decomposeParDict, libs/parallel/mpi): the same forces as the serial run.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/application.hpp"
#include "core/dictionary.hpp"
#include "core/timeLoop.hpp"
#include "crusher/crusherRun.hpp"
#include "crusher/machineLoading.hpp"
#include "demCase/demCase.hpp"
#include "demCase/demRun.hpp"
#include "demCuda/cudaDemModel.hpp"
#ifdef ROCKFRAC_HAVE_MPI
#include <mpi.h>

#include "parallel/mpi/demExchange.hpp"
#include "parallel/mpi/haloExchange.hpp"
#include "parallel/mpi/parallelSession.hpp"
#endif

using namespace rockfrac;

namespace {
const AppInfo info{
    "bondedDemFoam",
    "Bonded Voronoi DEM: cells glued at their face vertices by softening bonds, Hertz-Mindlin contact\n"
    "after breakage, rigid plates with prescribed velocity. Writes the plate force, broken bonds and\n"
    "the energy balance to postProcessing/plateForce, the whole state at write times (restart with\n"
    "startFrom latestTime) and cells/bonds for ParaView. SIGINT/SIGTERM write the state and exit\n"
    "with 130/143.\n"
    "Backends (controlDict 'backend cpu|cuda;', default cpu): cpu (OpenMP); " +
        cudaBackendSummary() + ".",
    "[options]",
    {"bondedDemFoam -case tutorials/BDT/granite", "bondedDemFoam -case tutorials/BDT/granite -dry-run",
     "bondedDemFoam -case tutorials/CH660/tiny",
     "mpirun -np 2 bondedDemFoam -parallel -case tutorials/BDT/granite"},
    {{"-parallel", "", "run decomposed over mpirun's ranks (system/decomposeParDict)"}},
};

#ifdef ROCKFRAC_HAVE_MPI
// The MPI side of -parallel: system/decomposeParDict read by every rank, the model cut by
// parallel/mpi/demExchange.hpp; rank 0 writes.
class MpiDecomposer final : public DemDecomposer {
public:
    explicit MpiDecomposer(const Application& app) : parameters_(readDecomposeParDict(app.casePath()))
    {
        const int ranks = mpi::size(MPI_COMM_WORLD);
        if (parameters_.n_subdomains != ranks)
            throw UserError(app.path("system/decomposeParDict").string() + ": numberOfSubdomains is " +
                            std::to_string(parameters_.n_subdomains) + " but mpirun started " +
                            std::to_string(ranks) + " ranks; run mpirun -np " +
                            std::to_string(parameters_.n_subdomains) + " or change numberOfSubdomains");
    }
    void decompose(DemModel& model) override
    {
        exchange_ = mpi::decomposeDemModel(model, parameters_, MPI_COMM_WORLD, &whole_);
    }
    const DemModel* gather(const DemModel& local) override
    {
        mpi::gatherModel(local, *exchange_, whole_.get());
        return whole_.get();
    }
    DemModel& gatherEverywhere(const DemModel& local) override
    {
        const auto start = std::chrono::steady_clock::now();
        bytes_ += static_cast<double>(mpi::gatherModel(local, *exchange_, whole_.get(), true));
        ++gathers_;
        seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return *whole_;
    }
    void redistribute(DemModel& local) override
    {
        const auto start = std::chrono::steady_clock::now();
        local = *whole_;
        exchange_ = mpi::decomposeDemModel(local, parameters_, MPI_COMM_WORLD);
        ++redistributions_;
        seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    std::string redistributionDue() const override { return exchange_->redistributionDue(); }
    long redistributions() const override { return redistributions_; }
    double redistributionSeconds() const override { return seconds_; }
    double redistributionBytes() const override { return bytes_; }
    long wholeGathers() const override { return gathers_; }
    bool writes() const override { return mpi::rank(MPI_COMM_WORLD) == 0; }
    bool anyRank(bool mine) override { return exchange_->anyRank(mine); }
    std::string describe() const override
    {
        return mpi::describeDecomposition(*exchange_, parameters_, MPI_COMM_WORLD);
    }

private:
    DecomposeParameters parameters_;
    std::unique_ptr<mpi::MpiDemExchange> exchange_;
    std::unique_ptr<DemModel> whole_;  // the whole model, gathered into at write times (rank 0) and
                                       // before a redistribution (every rank)
    long redistributions_ = 0, gathers_ = 0;
    double seconds_ = 0.0, bytes_ = 0.0;
};

bool parallelRequested(int argc, char** argv)
{
    return std::any_of(argv + 1, argv + argc, [](const char* a) { return std::string(a) == "-parallel"; });
}
#endif
}  // namespace

int main(int argc, char** argv)
{
#ifdef ROCKFRAC_HAVE_MPI
    // MPI, one log and one error message (parallel/mpi/parallelSession.hpp).
    std::unique_ptr<mpi::ParallelSession> session;
    if (parallelRequested(argc, argv)) session = std::make_unique<mpi::ParallelSession>(argc, argv);
#endif
    const int code = runApplication(info, argc, argv, [](Application& app) {
        const auto loading = app.path("constant/loading");
        const bool crusher =
            std::filesystem::exists(loading) && isMachineLoading(Dictionary::readFile(loading));
        std::unique_ptr<DemDecomposer> decomposer;
        if (app.has("-parallel")) {
#ifdef ROCKFRAC_HAVE_MPI
            decomposer = std::make_unique<MpiDecomposer>(app);
#else
            throw UserError("-parallel: this build has no MPI; install OpenMPI (utilities/installDependencies) "
                            "and build again");
#endif
        }
        // system/controlDict: time and write control, the DEM step, the run's function.
        TimeLoop loop(app, {demControlEntries(), {crusher ? "machine" : "plateForce"}});
        // Reads and checks every input: plates on a specimen, or a cone crusher.
        const std::unique_ptr<TimedRun> run = crusher ? newCrusherRun(app, loop, decomposer.get())
                                                      : newBondedDemRun(app, loop, decomposer.get());
        run->printSetup();
        // Until endTime or the stop criterion: per step the stage, the step, the rows and
        // the write rules; SIGINT/SIGTERM write the state (libs/core/timeLoop.hpp).
        return loop.run(*run);
    });
#ifdef ROCKFRAC_HAVE_MPI
    if (session) return session->finish(code);
#endif
    return code;
}
