#pragma once
// Disjoint sets over 0..n-1 (union–find) with path compression (path halving)
// and union by rank: a sequence of m operations costs O(m alpha(n)), i.e. linear
// in practice. Which element ends up as a set's root depends on the order of the
// unions; callers that need deterministic labels renumber the sets afterwards
// (labelFragments numbers them by their smallest element).
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace rockfrac {

class UnionFind {
public:
    explicit UnionFind(int n) : parent_(n), rank_(n, 0), sets_(n)
    {
        std::iota(parent_.begin(), parent_.end(), 0);
    }

    int find(int a)
    {
        while (parent_[a] != a) {
            parent_[a] = parent_[parent_[a]];  // path halving
            a = parent_[a];
        }
        return a;
    }

    // Merge the sets of a and b; false when they were already one set.
    bool unite(int a, int b)
    {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (rank_[a] < rank_[b]) std::swap(a, b);
        parent_[b] = a;
        if (rank_[a] == rank_[b]) ++rank_[a];
        --sets_;
        return true;
    }

    int size() const { return static_cast<int>(parent_.size()); }
    int sets() const { return sets_; }

private:
    std::vector<int> parent_;
    std::vector<std::uint8_t> rank_;  // rank <= log2(n) < 256
    int sets_;
};

}  // namespace rockfrac
