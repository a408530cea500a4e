// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file union_find.h
/// @brief Disjoint sets over 0..n-1 (path halving): the shells of a mesh, the pieces of a field.

#include <cstdint>
#include <numeric>
#include <vector>

namespace sculpt {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : mParent(n) { std::iota(mParent.begin(), mParent.end(), std::uint32_t(0)); }

    std::uint32_t find(std::uint32_t a)
    {
        while (mParent[a] != a) a = mParent[a] = mParent[mParent[a]];
        return a;
    }
    void join(std::uint32_t a, std::uint32_t b) { mParent[find(a)] = find(b); }
    /// The number of sets.
    std::size_t count()
    {
        std::size_t roots = 0;
        for (std::uint32_t a = 0; a < mParent.size(); ++a) roots += find(a) == a ? 1 : 0;
        return roots;
    }

private:
    std::vector<std::uint32_t> mParent;
};

}  // namespace sculpt
