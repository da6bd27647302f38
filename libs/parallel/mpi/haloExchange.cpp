#include "parallel/mpi/haloExchange.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace rockfrac::mpi {

namespace {

void check(int status, const char* what)
{
    if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI call failed: ") + what);
}

}  // namespace

int rank(MPI_Comm comm)
{
    int r = 0;
    check(MPI_Comm_rank(comm, &r), "MPI_Comm_rank");
    return r;
}

int size(MPI_Comm comm)
{
    int n = 0;
    check(MPI_Comm_size(comm, &n), "MPI_Comm_size");
    return n;
}

std::vector<std::vector<unsigned char>> exchangeBytes(const std::vector<std::vector<unsigned char>>& to_rank,
                                                      MPI_Comm comm)
{
    const int n = size(comm);
    if (static_cast<int>(to_rank.size()) != n)
        throw std::logic_error("exchangeBytes: one buffer per rank expected");
    std::vector<long long> send_counts(n), recv_counts(n);
    for (int q = 0; q < n; ++q) send_counts[q] = static_cast<long long>(to_rank[q].size());
    check(MPI_Alltoall(send_counts.data(), 1, MPI_LONG_LONG, recv_counts.data(), 1, MPI_LONG_LONG, comm),
          "MPI_Alltoall");
    // One message per rank pair (MPI counts are int: a buffer over 2 GB is refused).
    std::vector<MPI_Request> requests;
    std::vector<std::vector<unsigned char>> from_rank(n);
    for (int q = 0; q < n; ++q) {
        if (recv_counts[q] > std::numeric_limits<int>::max() ||
            send_counts[q] > std::numeric_limits<int>::max())
            throw std::runtime_error("exchangeBytes: more than 2 GB between two ranks");
        from_rank[q].resize(static_cast<std::size_t>(recv_counts[q]));
        if (recv_counts[q] > 0) {
            requests.emplace_back();
            check(MPI_Irecv(from_rank[q].data(), static_cast<int>(recv_counts[q]), MPI_UNSIGNED_CHAR, q, 17,
                            comm, &requests.back()),
                  "MPI_Irecv");
        }
    }
    for (int q = 0; q < n; ++q)
        if (send_counts[q] > 0) {
            requests.emplace_back();
            check(MPI_Isend(to_rank[q].data(), static_cast<int>(send_counts[q]), MPI_UNSIGNED_CHAR, q, 17,
                            comm, &requests.back()),
                  "MPI_Isend");
        }
    check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
          "MPI_Waitall");
    return from_rank;
}

RankExtent extentOf(const std::vector<Vec3>& centroids, const std::vector<double>& reach)
{
    RankExtent e;
    for (std::size_t i = 0; i < centroids.size(); ++i) {
        for (int d = 0; d < 3; ++d) {
            e.lo[d] = std::min(e.lo[d], centroids[i][d]);
            e.hi[d] = std::max(e.hi[d], centroids[i][d]);
        }
        e.max_reach = std::max(e.max_reach, reach[i]);
    }
    return e;
}

std::vector<RankExtent> gatherExtents(const RankExtent& mine, MPI_Comm comm)
{
    const int n = size(comm);
    const std::array<double, 7> local{mine.lo.x, mine.lo.y, mine.lo.z,     mine.hi.x,
                                      mine.hi.y, mine.hi.z, mine.max_reach};
    std::vector<double> all(7 * static_cast<std::size_t>(n));
    check(MPI_Allgather(local.data(), 7, MPI_DOUBLE, all.data(), 7, MPI_DOUBLE, comm), "MPI_Allgather");
    std::vector<RankExtent> extents(n);
    for (int q = 0; q < n; ++q) {
        const double* v = all.data() + 7 * q;
        extents[q].lo = {v[0], v[1], v[2]};
        extents[q].hi = {v[3], v[4], v[5]};
        extents[q].max_reach = v[6];
    }
    return extents;
}

std::vector<std::vector<int>> ghostCandidates(const std::vector<Vec3>& centroids,
                                              const std::vector<double>& reach,
                                              const std::vector<RankExtent>& extents, int me, double margin)
{
    std::vector<std::vector<int>> out(extents.size());
    for (std::size_t q = 0; q < extents.size(); ++q) {
        if (static_cast<int>(q) == me || extents[q].empty()) continue;
        for (std::size_t i = 0; i < centroids.size(); ++i) {
            double d2 = 0.0;  // squared distance from the centroid to q's box
            for (int d = 0; d < 3; ++d) {
                const double below = extents[q].lo[d] - centroids[i][d];
                const double above = centroids[i][d] - extents[q].hi[d];
                const double gap = std::max({below, above, 0.0});
                d2 += gap * gap;
            }
            const double range = reach[i] + extents[q].max_reach + margin;
            if (d2 <= range * range) out[q].push_back(static_cast<int>(i));
        }
    }
    return out;
}

std::vector<bool> withinReach(const std::vector<Vec3>& my_centroids, const std::vector<double>& my_reach,
                              const std::vector<Vec3>& centroids, const std::vector<double>& reach,
                              double margin)
{
    std::vector<bool> keep(centroids.size(), false);
    if (my_centroids.empty() || centroids.empty()) return keep;
    // Bin my centroids in a grid of spacing 2 max(reach) + margin (haloReport's rule): a
    // candidate within reach of one of them lies in the same or a neighbouring bin.
    double max_reach = 0.0;
    for (double r : my_reach) max_reach = std::max(max_reach, r);
    for (double r : reach) max_reach = std::max(max_reach, r);
    const double h = 2.0 * max_reach + margin;
    const Vec3 lo = my_centroids[0];
    auto binOf = [&](const Vec3& c) {
        return std::array<long, 3>{static_cast<long>(std::floor((c.x - lo.x) / h)),
                                   static_cast<long>(std::floor((c.y - lo.y) / h)),
                                   static_cast<long>(std::floor((c.z - lo.z) / h))};
    };
    std::map<std::array<long, 3>, std::vector<int>> bins;
    for (int i = 0; i < static_cast<int>(my_centroids.size()); ++i) bins[binOf(my_centroids[i])].push_back(i);
    for (std::size_t k = 0; k < centroids.size(); ++k) {
        const auto key = binOf(centroids[k]);
        for (long dx = -1; dx <= 1 && !keep[k]; ++dx)
            for (long dy = -1; dy <= 1 && !keep[k]; ++dy)
                for (long dz = -1; dz <= 1 && !keep[k]; ++dz) {
                    const auto bin = bins.find({key[0] + dx, key[1] + dy, key[2] + dz});
                    if (bin == bins.end()) continue;
                    for (int i : bin->second) {
                        const Vec3 d = centroids[k] - my_centroids[i];
                        const double range = my_reach[i] + reach[k] + margin;
                        if (dot(d, d) <= range * range) {
                            keep[k] = true;
                            break;
                        }
                    }
                }
    }
    return keep;
}

}  // namespace rockfrac::mpi
