// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file incremental_mesher.h
/// @brief The surface of a field image as cached block meshes, re-meshed only where it changed.
///
/// Space is cut into blocks of B^3 voxels aligned to OpenVDB leaves (B = 16 by default, chosen by
/// measurement: see tests/bench/mesher_bench.cpp). Each block caches the marching-cubes mesh of
/// its cells (BlockMesher) with the version at which it was made. After an edit, update() maps
/// the edit's dirty leaves to the blocks that read them and re-meshes just those, in parallel;
/// cost follows the edit, not the model. Blocks that become empty are dropped. changesSince()
/// tells a viewer which blocks to upload or discard. weldedMesh() joins the blocks into one
/// closed mesh by their exact global edge keys (Ferley et al., "Practical volumetric sculpting").

#include "core/base/progress.h"
#include "core/base/unique_id.h"
#include "core/field/dirty_region.h"
#include "core/field/field_image.h"
#include "core/mesh/block_mesh.h"
#include "core/mesh/triangle_mesh.h"

#include <map>

namespace sculpt {

class IncrementalMesher {
public:
    static constexpr int kDefaultBlockVoxels = 16;

    /// @param blockVoxels B: a multiple of 8 from 8 to 64.
    explicit IncrementalMesher(int blockVoxels = kDefaultBlockVoxels);

    /// Meshes the whole field, replacing every cached block. Cost: linear in the band.
    /// Cancelled (by `progress`) leaves the mesher to be rebuilt again before use.
    void rebuild(const FieldImage& field, const Progress& progress = {});
    /// Re-meshes the blocks whose cells or normals read a voxel of a dirty leaf.
    /// @return the number of blocks re-meshed. Cost: linear in the dirty region.
    std::size_t update(const FieldImage& field, const DirtyRegion& dirty);

    /// Incremented by every rebuild() and by every update() of a non-empty region.
    std::uint64_t version() const { return mVersion; }
    /// Never the same for two meshers of this process (an address is: a freed mesher's is reused),
    /// so (id, version) names what a viewer shows.
    std::uint64_t id() const { return mId.value(); }

    /// Blocks changed after `version`: re-meshed ones (present) and dropped ones (gone).
    struct Changes {
        std::vector<openvdb::Coord> updated;
        std::vector<openvdb::Coord> removed;
    };
    /// Cost: the blocks changed since `version`, not the model.
    Changes changesSince(std::uint64_t version) const;

    /// The cached blocks, by origin (index space).
    const std::map<openvdb::Coord, BlockMesh>& blocks() const { return mBlocks; }
    int blockVoxels() const { return mBlockVoxels; }
    std::size_t triangleCount() const;
    /// Heap bytes of all cached block meshes.
    std::size_t memoryBytes() const;

    /// All blocks welded into one shared-vertex mesh; deterministic (block order, key order).
    TriangleMesh weldedMesh() const;

private:
    void remesh(const FieldImage& field, const std::vector<openvdb::Coord>& origins, const Progress& progress = {});
    void logChanges(std::vector<openvdb::Coord> origins);

    int mBlockVoxels;
    UniqueId mId;
    std::uint64_t mVersion = 0;
    std::map<openvdb::Coord, BlockMesh> mBlocks;
    // Version -> the blocks it re-meshed or dropped, so that changesSince() costs what changed
    // since, not the model. Old entries are merged (into the newest version among them) once
    // the log outgrows the blocks: a viewer that far behind is told a superset, never less.
    std::map<std::uint64_t, std::vector<openvdb::Coord>> mChangeLog;
    std::size_t mLoggedOrigins = 0, mCompactAbove = 4096;
};

/// One-shot: the welded zero iso-surface of a field image. Cost: linear in the band.
TriangleMesh meshLevelSet(const FieldImage& field, int blockVoxels = IncrementalMesher::kDefaultBlockVoxels);

}  // namespace sculpt
