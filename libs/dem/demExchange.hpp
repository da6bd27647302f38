#pragma once
// What a decomposed DemModel asks of the other ranks (the MPI side: parallel/mpi/demExchange.hpp).
//
// A decomposed run gives each rank a DemModel of its own cells and their ghosts (the cells of
// other ranks within reach, in global id order), and every item among them is computed where
// it is listed: an interface or contact pair with a ghost is computed on both sides from the
// same state, so its force is the same bits on both and each rank's gather of its own cells
// sums exactly what the serial model sums, in the same order. An item is counted (energies,
// counters) only on the rank that owns its first cell. The model calls the exchange at its
// synchronisation points: ghosts refreshed before each force evaluation, the list-rebuild and
// step-split decisions taken over all ranks, the walls' reactions summed in the serial order.
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "dem/demState.hpp"

namespace rockfrac {

// One cell-wall item's share of its wall's reaction, keyed as the serial model orders its
// items (by cell, then wall).
struct WallItemTerm {
    std::int64_t cell = 0;  // global cell id
    int wall = 0;
    Vec3 force;   // on the cell
    Vec3 torque;  // on the wall about its origin is minus this: r x force + torque on the cell
    double power = 0.0;
};

class DemExchange {
public:
    virtual ~DemExchange() = default;
    virtual int rank() const = 0;
    // The ghosts' position, velocity, orientation and angular velocity from their owners.
    virtual void refreshGhosts(CellArrays& cells) = 0;
    // True on every rank when it is true on one.
    virtual bool anyRank(bool mine) = 0;
    // The largest of the ranks' values (exact whatever the order).
    virtual double maxOverRanks(double mine) = 0;
    // values[i] replaced by the sum over ranks of values[i], added in rank order (the same
    // bits on every rank).
    virtual void sumOverRanks(std::vector<double>& values) = 0;
    // Every rank's terms, merged in (cell, wall) order (the same list on every rank).
    virtual std::vector<WallItemTerm> mergeWallTerms(const std::vector<WallItemTerm>& mine) = 0;
    // At every neighbour-list build: the ghost layer still holds every cell a cell of this rank
    // can touch (else a UserError on every rank).
    virtual void checkGhostReach(const CellArrays& cells) = 0;
    // Global cell id of local cell c.
    virtual std::int64_t globalCell(int c) const = 0;
};

}  // namespace rockfrac
