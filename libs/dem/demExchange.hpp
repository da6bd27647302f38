#pragma once
// What a decomposed DemModel asks of the other ranks (the MPI side: parallel/mpi/demExchange.hpp).
//
// A decomposed run gives each rank a DemModel of its own cells and their ghosts (the cells of
// other ranks within reach, in global id order). Every item (interface, contact pair, wall
// item) is computed by exactly one rank, the one owning its first cell (a wall item: its cell),
// and counted there (energies, counters); the rank owning the second cell receives the item's
// results (forces, torques, stiffness, intact bonds) before its gather, so each rank's gather
// of its own cells sums exactly what the serial model sums, in the same order. The model calls
// the exchange at its synchronisation points: ghosts refreshed before each force evaluation,
// item results returned, the list-rebuild and step-split decisions taken over all ranks, the
// walls' reactions summed in the serial order.
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
    // The results of the interfaces and contact pairs another rank computed (their first cell
    // is a ghost here, their second one of this rank's), into this rank's arrays: after the
    // bond kernel and after the contact kernels respectively.
    virtual void returnInterfaceResults(InterfaceArrays& interfaces) = 0;
    virtual void returnPairResults(ContactPairArrays& pairs) = 0;
    // After each neighbour-list build: which pairs go where.
    virtual void pairListsBuilt(const ContactPairArrays& pairs) = 0;
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
    // can touch (else a UserError on every rank), and the ranks' costs (`cost`: this rank's,
    // DemModel::ownedCost) are compared: a redistribution falls due when a cell has moved half
    // the ghost layer's allowance or the imbalance has grown past the tolerance (the same
    // decision on every rank).
    virtual void checkGhostReach(const CellArrays& cells, double cost) = 0;
    // Global cell id of local cell c.
    virtual std::int64_t globalCell(int c) const = 0;
};

}  // namespace rockfrac
