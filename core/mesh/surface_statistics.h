// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_statistics.h
/// @brief Volume, area, Euler characteristic and shell count of an IncrementalMesher's surface,
///        kept current from per-block sums: the cost of an update follows the blocks it changed.
///
/// Each block is tallied once when the mesher re-meshes it: its signed volume (divergence
/// theorem: the blocks' triangles partition the closed surface, so the sums are exactly the
/// welded mesh's), its area, its triangles, and its vertices grouped into local components.
/// The totals are sums. Vertices and shells need the blocks joined: a vertex a block does not
/// own belongs to the block its edge starts in, found by key, so joining costs a union per such
/// vertex (those on block faces), never a pass over the whole mesh.

#include "core/mesh/incremental_mesher.h"
#include "core/mesh/surface_topology.h"

#include <cstdint>
#include <map>
#include <vector>

namespace sculpt {

class SurfaceStatistics {
public:
    /// Re-tallies the blocks the mesher changed since the last update (all of them the first time).
    void update(const IncrementalMesher& mesher);

    double volume() const { return mVolume; }
    double area() const { return mArea; }
    std::size_t triangles() const { return mTriangles; }

    /// Joins the blocks of the mesher this was last updated from.
    SurfaceTopology topology(const IncrementalMesher& mesher) const;

private:
    struct Tally {
        double volume = 0.0, area = 0.0;
        std::size_t triangles = 0;
        std::vector<std::uint32_t> component;  ///< local component of each vertex
        std::uint32_t components = 0;
    };
    static Tally tally(const BlockMesh& mesh);
    void add(const Tally& t, double sign);

    std::map<openvdb::Coord, Tally> mTallies;
    std::uint64_t mVersion = 0;
    bool mStarted = false;
    double mVolume = 0.0, mArea = 0.0;
    std::size_t mTriangles = 0;
};

}  // namespace sculpt
