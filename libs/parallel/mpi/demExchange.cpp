#include "parallel/mpi/demExchange.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/error.hpp"
#include "parallel/mpi/haloExchange.hpp"

namespace rockfrac::mpi {

namespace {

void check(int status, const char* what)
{
    if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI call failed: ") + what);
}

// What a ghost needs of its owner before a force evaluation: the kinematic state.
constexpr int doubles_per_cell = 13;
constexpr int ghost_tag = 3801;

void packCell(const CellArrays& c, int i, double* out)
{
    const Vec3 &x = c.position[i], &v = c.velocity[i], &w = c.angular_velocity[i];
    const Quat& q = c.orientation[i];
    const double values[doubles_per_cell] = {x.x, x.y, x.z, v.x, v.y, v.z, q.w, q.x, q.y, q.z, w.x, w.y, w.z};
    std::memcpy(out, values, sizeof(values));
}

void unpackCell(const double* in, CellArrays& c, int i)
{
    c.position[i] = {in[0], in[1], in[2]};
    c.velocity[i] = {in[3], in[4], in[5]};
    c.orientation[i].w = in[6];
    c.orientation[i].x = in[7];
    c.orientation[i].y = in[8];
    c.orientation[i].z = in[9];
    c.angular_velocity[i] = {in[10], in[11], in[12]};
}

}  // namespace

class MpiDemExchange::Timed {
public:
    explicit Timed(MpiDemExchange& e) : e_(e), start_(std::chrono::steady_clock::now())
    {
        ++e_.exchange_calls_;
    }
    ~Timed()
    {
        e_.exchange_seconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    MpiDemExchange& e_;
    std::chrono::steady_clock::time_point start_;
};

MpiDemExchange::MpiDemExchange(MPI_Comm comm, std::vector<std::int64_t> global_cell,
                               std::vector<int> global_interface, std::vector<char> owned,
                               std::vector<Neighbour> neighbours, std::vector<Vec3> start_position,
                               double allowance)
    : comm_(comm),
      global_cell_(std::move(global_cell)),
      global_interface_(std::move(global_interface)),
      owned_(std::move(owned)),
      neighbours_(std::move(neighbours)),
      start_position_(std::move(start_position)),
      allowance_(allowance)
{
    rank_ = mpi::rank(comm);
    size_ = mpi::size(comm);
    send_buffer_.resize(neighbours_.size());
    recv_buffer_.resize(neighbours_.size());
    owner_.assign(owned_.size(), rank_);
    for (const Neighbour& nb : neighbours_) {
        for (int c : nb.recv) owner_[c] = nb.rank;
        ghost_send_.push_back(nb.send);
        ghost_recv_.push_back(nb.recv);
    }
}

template <class CellOf>
void MpiDemExchange::sortItems(int n, CellOf&& first_and_second, std::vector<std::vector<int>>& send,
                               std::vector<std::vector<int>>& recv) const
{
    send.assign(neighbours_.size(), {});
    recv.assign(neighbours_.size(), {});
    std::vector<int> slot(size_, -1);
    for (std::size_t k = 0; k < neighbours_.size(); ++k) slot[neighbours_[k].rank] = static_cast<int>(k);
    for (int i = 0; i < n; ++i) {
        const auto [first, second] = first_and_second(i);
        const int a = owner_[first], b = owner_[second];
        if (a == rank_ && b != rank_) send[slot[b]].push_back(i);
        if (a != rank_ && b == rank_) recv[slot[a]].push_back(i);
    }
}

void MpiDemExchange::interfacesDecomposed(const InterfaceArrays& f)
{
    sortItems(
        f.size(),
        [&](int k) {
            return std::pair{f.cell_i[k], f.cell_j[k]};
        },
        interface_send_, interface_recv_);
}

void MpiDemExchange::pairListsBuilt(const ContactPairArrays& p)
{
    sortItems(
        p.size(),
        [&](int i) {
            return std::pair{p.cell_a[i], p.cell_b[i]};
        },
        pair_send_, pair_recv_);
}

template <class Pack, class Unpack>
void MpiDemExchange::exchangeItems(const std::vector<std::vector<int>>& send,
                                   const std::vector<std::vector<int>>& recv, int per_item, int tag,
                                   Pack&& pack, Unpack&& unpack)
{
    std::vector<MPI_Request> requests;
    requests.reserve(2 * neighbours_.size());
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        auto& in = recv_buffer_[k];
        in.resize(recv[k].size() * per_item);
        if (in.empty()) continue;
        requests.emplace_back();
        check(MPI_Irecv(in.data(), static_cast<int>(in.size()), MPI_DOUBLE, neighbours_[k].rank, tag, comm_,
                        &requests.back()),
              "MPI_Irecv (items)");
    }
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        auto& out = send_buffer_[k];
        out.resize(send[k].size() * per_item);
        if (out.empty()) continue;
        for (std::size_t i = 0; i < send[k].size(); ++i) pack(send[k][i], out.data() + i * per_item);
        requests.emplace_back();
        check(MPI_Isend(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, neighbours_[k].rank, tag, comm_,
                        &requests.back()),
              "MPI_Isend (items)");
    }
    check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
          "MPI_Waitall (items)");
    for (std::size_t k = 0; k < neighbours_.size(); ++k)
        for (std::size_t i = 0; i < recv[k].size(); ++i)
            unpack(recv[k][i], recv_buffer_[k].data() + i * per_item);
}

namespace {

void putVec(double* out, const Vec3& v)
{
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

Vec3 getVec(const double* in)
{
    return {in[0], in[1], in[2]};
}

}  // namespace

// Per interface: the force on cell i, the torques on i and j, the intact bonds.
void MpiDemExchange::returnInterfaceResults(InterfaceArrays& f)
{
    const Timed timed(*this);
    exchangeItems(
        interface_send_, interface_recv_, 10, ghost_tag + 1,
        [&](int k, double* out) {
            putVec(out, f.force_on_i[k]);
            putVec(out + 3, f.torque_on_i[k]);
            putVec(out + 6, f.torque_on_j[k]);
            out[9] = f.intact_bonds[k];
        },
        [&](int k, const double* in) {
            f.force_on_i[k] = getVec(in);
            f.torque_on_i[k] = getVec(in + 3);
            f.torque_on_j[k] = getVec(in + 6);
            f.intact_bonds[k] = static_cast<int>(in[9]);
        });
}

// Per pair: the force on b, the contact point or torque on b, the normal stiffness.
void MpiDemExchange::returnPairResults(ContactPairArrays& p)
{
    const Timed timed(*this);
    exchangeItems(
        pair_send_, pair_recv_, 7, ghost_tag + 2,
        [&](int i, double* out) {
            putVec(out, p.force_on_b[i]);
            putVec(out + 3, p.point_or_torque[i]);
            out[6] = p.stiffness[i];
        },
        [&](int i, const double* in) {
            p.force_on_b[i] = getVec(in);
            p.point_or_torque[i] = getVec(in + 3);
            p.stiffness[i] = static_cast<float>(in[6]);
        });
}

void MpiDemExchange::refreshGhosts(CellArrays& cells)
{
    const Timed timed(*this);
    exchangeItems(
        ghost_send_, ghost_recv_, doubles_per_cell, ghost_tag,
        [&](int c, double* out) { packCell(cells, c, out); },
        [&](int c, const double* in) { unpackCell(in, cells, c); });
}

bool MpiDemExchange::anyRank(bool mine)
{
    const Timed timed(*this);
    int value = mine ? 1 : 0;
    check(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT, MPI_LOR, comm_), "MPI_Allreduce (or)");
    return value != 0;
}

double MpiDemExchange::maxOverRanks(double mine)
{
    const Timed timed(*this);
    check(MPI_Allreduce(MPI_IN_PLACE, &mine, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce (max)");
    return mine;
}

// Gathered, then added in rank order on every rank: the same bits everywhere, whatever the
// MPI library's reduction tree.
void MpiDemExchange::sumOverRanks(std::vector<double>& values)
{
    const Timed timed(*this);
    const int n = static_cast<int>(values.size());
    std::vector<double> all(static_cast<std::size_t>(n) * size_);
    check(MPI_Allgather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, comm_),
          "MPI_Allgather (sums)");
    for (int i = 0; i < n; ++i) {
        double sum = all[i];
        for (int r = 1; r < size_; ++r) sum += all[static_cast<std::size_t>(r) * n + i];
        values[i] = sum;
    }
}

std::vector<WallItemTerm> MpiDemExchange::mergeWallTerms(const std::vector<WallItemTerm>& mine)
{
    const Timed timed(*this);
    const int bytes = static_cast<int>(mine.size() * sizeof(WallItemTerm));
    std::vector<int> counts(size_), offsets(size_ + 1, 0);
    check(MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_), "MPI_Allgather (wall items)");
    for (int r = 0; r < size_; ++r) offsets[r + 1] = offsets[r] + counts[r];
    std::vector<WallItemTerm> all(offsets[size_] / sizeof(WallItemTerm));
    check(MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                         comm_),
          "MPI_Allgatherv (wall items)");
    // Each rank's terms are in (cell, wall) order already; a cell's items are all on its owner.
    std::stable_sort(all.begin(), all.end(), [](const WallItemTerm& a, const WallItemTerm& b) {
        return a.cell != b.cell ? a.cell < b.cell : a.wall < b.wall;
    });
    return all;
}

void MpiDemExchange::checkGhostReach(const CellArrays& cells, double cost)
{
    double moved2 = 0.0;
    for (int c = 0; c < cells.size(); ++c)
        if (owned_[c]) moved2 = std::max(moved2, norm2(cells.position[c] - start_position_[c]));
    // The largest move, the largest and the total cost: the same figures on every rank.
    std::vector<double> costs = {cost};
    moved_ = std::sqrt(maxOverRanks(moved2));
    const double most = maxOverRanks(cost);
    sumOverRanks(costs);
    const double mean = costs[0] / size_;
    imbalance_ = mean > 0.0 ? most / mean - 1.0 : 0.0;
    if (baseline_imbalance_ < 0.0) baseline_imbalance_ = imbalance_;
    if (!(moved_ <= allowance_))
        throw UserError("bondedDemFoam -parallel: a cell has moved " + std::to_string(1e3 * moved_) +
                        " mm since the decomposition, beyond the ghost layer's allowance of " +
                        std::to_string(1e3 * allowance_) +
                        " mm between two list builds (the run decomposes again when a cell has moved half "
                        "of it); likely cause: a cell flying off at a speed the time step cannot follow; "
                        "reduce deltaT");
}

std::string MpiDemExchange::redistributionDue() const
{
    if (baseline_imbalance_ < 0.0) return {};  // no list built since the cut
    char why[200];
    if (moved_ > 0.5 * allowance_) {
        std::snprintf(why, sizeof(why), "a cell moved %.4g mm, half the ghost layer's allowance",
                      1e3 * moved_);
        return why;
    }
    if (imbalance_ > baseline_imbalance_ + imbalance_tolerance_) {
        std::snprintf(why, sizeof(why), "imbalance %.3g against %.3g after the last cut (tolerance %.3g)",
                      imbalance_, baseline_imbalance_, imbalance_tolerance_);
        return why;
    }
    return {};
}

int MpiDemExchange::ownedCells() const
{
    return static_cast<int>(std::count(owned_.begin(), owned_.end(), 1));
}

std::uint64_t MpiDemExchange::bytesPerStep() const
{
    std::uint64_t doubles = 0;
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        doubles += neighbours_[k].send.size() * doubles_per_cell;
        if (k < interface_send_.size()) doubles += interface_send_[k].size() * 10;
        if (k < pair_send_.size()) doubles += pair_send_[k].size() * 7;
    }
    return doubles * sizeof(double);
}

}  // namespace rockfrac::mpi
