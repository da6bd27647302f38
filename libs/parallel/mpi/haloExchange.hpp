#pragma once
// The MPI half of domain decomposition (issue: bondedDemFoam across processes): entities
// sent to the ranks that own them, and the ghost layer each rank needs, moved as the bytes
// of the array groups' migrate fields (dem/demFields.hpp packEntity/unpackEntity), so that
// everything a cell carries crosses with it and nothing is listed twice.
//
// A cell j owned by another rank is a ghost of rank p when some cell i of p lies within
// reach_i + reach_j + margin of it (centroid distance): the rule of haloReport
// (parallel/decomposition.hpp), which the serial decomposeCells reports and the tests
// compare with. Finding them takes two rounds: every rank publishes the box of its
// centroids and its largest reach (an all-gather of 7 numbers); an owner sends each rank the
// cells that could be within reach of that box; the receiver keeps the ones within reach
// of one of its own cells. Ghosts are ordered by global id, whatever the number of ranks.
//
// Built when CMake finds MPI (ROCKFRAC_HAVE_MPI); the serial build never includes it.
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/vec3.hpp"
#include "dem/demFields.hpp"

namespace rockfrac::mpi {

int rank(MPI_Comm comm);
int size(MPI_Comm comm);

// to_rank[q]: the bytes for rank q (to_rank.size() == size). Returns the bytes each rank
// sent here, indexed by the sender. Counts travel first (all-to-all), then the bytes.
std::vector<std::vector<unsigned char>> exchangeBytes(const std::vector<std::vector<unsigned char>>& to_rank,
                                                      MPI_Comm comm);

// Where a rank's cells are: the box of their centroids and their largest reach.
struct RankExtent {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    double max_reach = 0.0;
    bool empty() const { return lo.x > hi.x; }
};
RankExtent extentOf(const std::vector<Vec3>& centroids, const std::vector<double>& reach);
std::vector<RankExtent> gatherExtents(const RankExtent& mine, MPI_Comm comm);

// For each rank q != me: my cells that could be within reach of a cell of q (distance from the
// centroid to q's box at most reach_i + q's largest reach + margin), in my order.
std::vector<std::vector<int>> ghostCandidates(const std::vector<Vec3>& centroids,
                                              const std::vector<double>& reach,
                                              const std::vector<RankExtent>& extents, int me, double margin);

// Which of the candidates (centroid, reach) lie within reach of one of my cells.
std::vector<bool> withinReach(const std::vector<Vec3>& my_centroids, const std::vector<double>& my_reach,
                              const std::vector<Vec3>& centroids, const std::vector<double>& reach,
                              double margin);

// ---- Entities of an array group -----------------------------------------------------------

// Rank `root` holds every entity and part_of (the decomposition); each rank receives its own
// entities in global id order, and their global ids. Collective.
template <class Group>
void scatterEntities(const Group& all, const std::vector<int>& part_of, Group& mine,
                     std::vector<std::int64_t>& ids, MPI_Comm comm, int root = 0)
{
    const int n_ranks = size(comm), me = rank(comm);
    std::vector<std::vector<unsigned char>> to_rank(n_ranks);
    if (me == root)
        for (int i = 0; i < static_cast<int>(part_of.size()); ++i) {
            fieldDetail::put(to_rank[part_of[i]], static_cast<std::int64_t>(i));
            packEntity(all, i, to_rank[part_of[i]]);
        }
    const auto received = exchangeBytes(to_rank, comm);
    mine = Group{};
    ids.clear();
    const auto& in = received[root];
    for (std::size_t at = 0; at < in.size();) {
        ids.push_back(fieldDetail::take<std::int64_t>(in, at));
        at = unpackEntity(mine, in, at);
    }
}

// The ghost layer of my entities (ids, centroids and reach given per entity): the ghosts'
// entities appended to `ghosts` in global id order, their ids and owning ranks. Collective.
struct GhostLayer {
    std::vector<std::int64_t> ids;
    std::vector<int> owner;
    std::uint64_t bytes_received = 0;  // the exchange's payload into this rank
};

template <class Group>
GhostLayer exchangeGhosts(const Group& mine, const std::vector<std::int64_t>& ids,
                          const std::vector<Vec3>& centroids, const std::vector<double>& reach, double margin,
                          Group& ghosts, MPI_Comm comm)
{
    const int n_ranks = size(comm), me = rank(comm);
    const auto extents = gatherExtents(extentOf(centroids, reach), comm);
    const auto candidates = ghostCandidates(centroids, reach, extents, me, margin);
    // Per candidate: id, centroid, reach, the entity's byte count, its bytes (the count lets
    // the receiver skip a candidate it does not keep without unpacking it).
    std::vector<std::vector<unsigned char>> to_rank(n_ranks);
    for (int q = 0; q < n_ranks; ++q)
        for (int i : candidates[q]) {
            auto& out = to_rank[q];
            fieldDetail::put(out, ids[i]);
            fieldDetail::put(out, centroids[i]);
            fieldDetail::put(out, reach[i]);
            const std::size_t count_at = out.size();
            fieldDetail::put(out, std::uint64_t{0});
            packEntity(mine, i, out);
            const std::uint64_t count = out.size() - count_at - sizeof(std::uint64_t);
            std::memcpy(out.data() + count_at, &count, sizeof(count));
        }
    const auto received = exchangeBytes(to_rank, comm);

    // Read every candidate's header, keep those within reach, unpack them in global id order.
    struct Candidate {
        std::int64_t id;
        int owner;
        std::size_t at;  // its entity's bytes in received[owner]
    };
    std::vector<Candidate> all;
    std::vector<Vec3> cc;
    std::vector<double> cr;
    GhostLayer layer;
    for (int q = 0; q < n_ranks; ++q) {
        const auto& in = received[q];
        layer.bytes_received += in.size();
        for (std::size_t at = 0; at < in.size();) {
            Candidate c{};
            c.owner = q;
            c.id = fieldDetail::take<std::int64_t>(in, at);
            cc.push_back(fieldDetail::take<Vec3>(in, at));
            cr.push_back(fieldDetail::take<double>(in, at));
            const auto count = fieldDetail::take<std::uint64_t>(in, at);
            c.at = at;
            at += count;
            all.push_back(c);
        }
    }
    const std::vector<bool> keep = withinReach(centroids, reach, cc, cr, margin);
    std::vector<std::size_t> order;
    for (std::size_t k = 0; k < all.size(); ++k)
        if (keep[k]) order.push_back(k);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return all[a].id < all[b].id; });
    for (std::size_t k : order) {
        unpackEntity(ghosts, received[all[k].owner], all[k].at);
        layer.ids.push_back(all[k].id);
        layer.owner.push_back(all[k].owner);
    }
    return layer;
}

}  // namespace rockfrac::mpi
