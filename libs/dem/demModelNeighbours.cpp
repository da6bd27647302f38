// DemModel: neighbour lists (contact pair candidates and wall items) and when they are stale.
#include <algorithm>
#include <cmath>
#include <utility>

#include "dem/demExchange.hpp"
#include "dem/demModel.hpp"
#include "dem/demModelDetail.hpp"

namespace rockfrac {

using demDetail::buildCellIncidence;

namespace {

// Angle of the rotation between two orientations.
double rotationAngle(const Quat& a, const Quat& b)
{
    const double c = std::fabs(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z);
    return 2.0 * std::acos(std::min(1.0, c));
}

}  // namespace

bool DemModel::neighbourListsStale() const
{
    if (!lists_valid_ || wall_origin_at_build_.size() != walls_.size()) return true;
    double cell_move2 = 0.0;
    for (int c = 0; c < cells_.size(); ++c)
        cell_move2 = std::max(cell_move2, norm2(cells_.position[c] - position_at_build_[c]));
    return neighbourListsStale(std::sqrt(cell_move2));
}

// Stale when a cell has moved half the skin since the build, or a cell and a wall
// together a whole skin (cell_move: the largest cell displacement since the build).
bool DemModel::neighbourListsStale(double cell_move) const
{
    if (!lists_valid_ || wall_origin_at_build_.size() != walls_.size()) return true;
    double wall_move = 0.0;
    for (int w = 0; w < nWalls(); ++w)
        wall_move = std::max(wall_move, norm(walls_[w].origin - wall_origin_at_build_[w]) +
                                            wall_extent_[w] * rotationAngle(walls_[w].orientation,
                                                                            wall_orientation_at_build_[w]));
    return cell_move > 0.5 * skin_ || cell_move + wall_move > skin_ || !(cell_move == cell_move);
}

void DemModel::rebuildNeighbourLists()
{
    const int n = cells_.size();
    const std::vector<std::pair<int, int>> near =
        findNearPairs(cells_.position, cells_.bounding_radius, skin_);
    ContactPairArrays next;
    for (auto* list : {&next.cell_a, &next.cell_b, &next.interface}) list->reserve(near.size());
    next.tangential_spring.reserve(near.size());
    next.last_normal.reserve(near.size());
    // Seats only for patch contacts (8 bytes per pair the point contact never reads).
    const bool seats = parameters_.cell_contact_patch;
    if (seats) next.seat.reserve(near.size());
    std::size_t old = 0;
    for (const auto& [a, b] : near) {
        // The interface of the pair, if it shares a bonded face. Pairs whose every bond
        // is intact are left out: when their first bond breaks the lists are rebuilt.
        const auto neighbour = [&](int k) {
            return interfaces_.cell_i[k] == a ? interfaces_.cell_j[k] : interfaces_.cell_i[k];
        };
        const auto begin = neighbour_interface_.begin() + cell_interface_offset_[a];
        const auto end = neighbour_interface_.begin() + cell_interface_offset_[a + 1];
        const auto found =
            std::lower_bound(begin, end, b, [&](int k, int cell) { return neighbour(k) < cell; });
        const int iface = found != end && neighbour(*found) == b ? *found : -1;
        if (iface >= 0 && interfaces_.intact_bonds[iface] ==
                              interfaces_.bond_offset[iface + 1] - interfaces_.bond_offset[iface])
            continue;
        next.cell_a.push_back(a);
        next.cell_b.push_back(b);
        next.interface.push_back(iface);
        // Carry the contact history by key (both lists sorted by (a, b)).
        while (old < pairs_.cell_a.size() &&
               std::make_pair(pairs_.cell_a[old], pairs_.cell_b[old]) < std::make_pair(a, b))
            ++old;
        const bool kept = old < pairs_.cell_a.size() && pairs_.cell_a[old] == a && pairs_.cell_b[old] == b;
        next.tangential_spring.push_back(kept ? pairs_.tangential_spring[old] : Vec3{});
        next.last_normal.push_back(kept ? pairs_.last_normal[old] : Vec3{});
        if (seats) next.seat.push_back(kept && old < pairs_.seat.size() ? pairs_.seat[old] : -1.0);
    }
    // Most near pairs are still bonded and left out: give back what was reserved for them
    // (about half the contact pairs' memory in an intact specimen).
    shrinkFields(next);
    resizeFields(next, next.cell_a.size());  // the rest: margins, forces, status and stiffness zero
    pairs_ = std::move(next);
    buildCellIncidence(n, pairs_.cell_a, pairs_.cell_b, cell_pair_offset_, cell_pairs_);
    counters_.contact_pairs_listed = pairs_.size();
    if (exchange_) {
        countPairs();
        exchange_->pairListsBuilt(pairs_);
    }
    buildWallItems();
    if (exchange_) exchange_->checkGhostReach(cells_, ownedCost());
    position_at_build_ = cells_.position;
    wall_origin_at_build_.clear();
    wall_orientation_at_build_.clear();
    for (const WallState& w : walls_) {
        wall_origin_at_build_.push_back(w.origin);
        wall_orientation_at_build_.push_back(w.orientation);
    }
    interfaces_cracked_at_build_ = counters_.interfaces_cracked;
    lists_valid_ = true;
    ++counters_.neighbour_rebuilds;
}

void DemModel::buildWallItems()
{
    const int n = cells_.size();
    WallContactArrays next;
    next.triangle_offset.assign(1, 0);
    cell_wall_item_offset_.assign(n + 1, 0);
    std::vector<int> found;
    std::size_t old = 0;
    for (int c = 0; c < n; ++c) {
        for (int w = 0; w < nWalls(); ++w) {
            const WallState& wall = walls_[w];
            const double reach = cells_.bounding_radius[c] + skin_;
            found.clear();
            Vec3 local;
            double clearance = 0.0;  // a plate's items are evaluated every step
            if (wall.kind == wallPlate) {
                if (dot(cells_.position[c] - wall.origin, wall.normal) > reach) continue;
            } else {
                local = transposeTimes(rotationMatrix(wall.orientation), cells_.position[c] - wall.origin);
                triangle_grids_[w].query(local, reach, found);
                if (found.empty()) continue;
                // Kept: the triangles within reach plus a skin, each relative move until the
                // next build being less than a skin (neighbourListsStale); the grid's cells
                // hold many more, which every step would search (docs/theory-dem.md §7, "Cost").
                clearance = 1e300;
                std::size_t kept = 0;
                for (int t : found) {
                    const Vec3* p = &triangle_vertices_[3 * (wall.first_triangle + t)];
                    const double d = norm(local - closestPointOnTriangle(local, p[0], p[1], p[2]));
                    clearance = std::min(clearance, d);
                    if (d <= (reach + skin_) * (1.0 + 1e-9)) found[kept++] = t;
                }
                found.resize(kept);
            }
            next.cell.push_back(c);
            next.wall.push_back(w);
            next.centre_at_build.push_back(local);
            next.clearance_at_build.push_back(clearance);
            for (int t : found) next.triangles.push_back(wall.first_triangle + t);
            next.triangle_offset.push_back(static_cast<int>(next.triangles.size()));
            while (old < wall_items_.cell.size() &&
                   std::make_pair(wall_items_.cell[old], wall_items_.wall[old]) < std::make_pair(c, w))
                ++old;
            const bool kept =
                old < wall_items_.cell.size() && wall_items_.cell[old] == c && wall_items_.wall[old] == w;
            next.tangential_spring.push_back(kept ? wall_items_.tangential_spring[old] : Vec3{});
            next.last_normal.push_back(kept ? wall_items_.last_normal[old] : Vec3{});
        }
        cell_wall_item_offset_[c + 1] = static_cast<int>(next.cell.size());
    }
    resizeFields(next, next.cell.size());  // the rest: forces, energies, status and stiffness zero
    wall_items_ = std::move(next);
}

// Per cell: 1 + the items it takes part in (bond ends, listed contact pairs, wall triangles
// within reach; a plate counts 1), the work of a step that goes with it.
std::vector<double> DemModel::cellCosts() const
{
    std::vector<double> cost(cells_.size(), 1.0);
    for (int k = 0; k < interfaces_.size(); ++k) {
        const int bonds = interfaces_.bond_offset[k + 1] - interfaces_.bond_offset[k];
        cost[interfaces_.cell_i[k]] += bonds;
        cost[interfaces_.cell_j[k]] += bonds;
    }
    for (int p = 0; p < pairs_.size(); ++p) {
        cost[pairs_.cell_a[p]] += 1.0;
        cost[pairs_.cell_b[p]] += 1.0;
    }
    // Restored or gathered wall items carry their keys only (their triangles come with the next
    // build): one each then. The cost must be the same on every rank that computes it.
    const bool triangles =
        wall_items_.triangle_offset.size() == static_cast<std::size_t>(wall_items_.size()) + 1;
    for (int i = 0; i < wall_items_.size(); ++i)
        cost[wall_items_.cell[i]] +=
            triangles ? std::max(1, wall_items_.triangle_offset[i + 1] - wall_items_.triangle_offset[i]) : 1;
    return cost;
}

double DemModel::ownedCost() const
{
    const std::vector<double> cost = cellCosts();
    double sum = 0.0;
    for (int c = 0; c < cells_.size(); ++c)
        if (ownsCell(c)) sum += cost[c];
    return sum;
}

}  // namespace rockfrac
