#pragma once
/// @file model_display.h
/// @brief The sculpt on screen: one VTK actor per mesher block, re-uploaded only when the
///        mesher re-meshed that block, and a coarse display shown while the camera moves (the
///        display's level of detail).
///
/// Every actor shares the SurfaceLook's property and shader. vtkCompositePolyDataMapper2 is not
/// used: in VTK 9.1 it re-uploads every block when any block changes. The coarse display is
/// each block's mesh with vertices clustered (about 9x fewer triangles), joined into chunks of
/// 4^3 blocks: on Mesa each actor costs ~30 us a frame, so a million triangles in 1,800 block
/// actors would stay slow however few triangles each had. A chunk is rebuilt from its blocks'
/// cached coarse meshes only when shown after one of them changed.

#include "core/mesh/incremental_mesher.h"

#include <vtkSmartPointer.h>

#include <map>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class SurfaceLook;

class ModelDisplay {
public:
    ModelDisplay(vtkRenderer* renderer, const SurfaceLook& look);
    ~ModelDisplay();

    /// Uploads the blocks the mesher changed since the last sync (all of them for a new mesher).
    /// `voxelSize` sizes the coarse twins' clusters.
    void sync(const IncrementalMesher& mesher, double voxelSize);
    /// Shows the coarse twins (true) or the full blocks.
    void setCoarse(bool coarse);
    bool coarse() const { return mCoarse; }
    /// Hides every actor (another view of the model, the scales, is shown instead).
    void setHidden(bool hidden);

    /// Of the last sync: blocks uploaded, blocks dropped, and the bytes handed to VTK.
    std::size_t lastUploads() const { return mLastUploads; }
    std::size_t lastRemovals() const { return mLastRemovals; }
    std::size_t lastUploadBytes() const { return mLastBytes; }
    std::size_t blockCount() const { return mBlocks.size(); }
    std::size_t coarseTriangles() const { return mCoarseTriangles; }
    /// Bytes of every full-detail block as handed to VTK: what one upload of the whole mesh costs.
    std::size_t meshBytes() const { return mMeshBytes; }

private:
    struct Block;
    struct Chunk;
    void remove(const openvdb::Coord& origin);
    void upload(const openvdb::Coord& origin, const BlockMesh& mesh, double voxelSize);
    openvdb::Coord chunkOf(const openvdb::Coord& block) const;
    void rebuildChunk(const openvdb::Coord& origin, Chunk& chunk);
    void rebuildDirtyChunks();

    vtkRenderer* mRenderer;
    const SurfaceLook& mLook;
    std::map<openvdb::Coord, Block> mBlocks;
    std::map<openvdb::Coord, Chunk> mChunks;
    int mBlockVoxels = IncrementalMesher::kDefaultBlockVoxels;
    std::uint64_t mSourceId = 0;  // IncrementalMesher::id of the mesher shown
    std::uint64_t mVersion = 0;
    bool mCoarse = false;
    bool mHidden = false;
    std::size_t mLastUploads = 0, mLastRemovals = 0, mLastBytes = 0, mCoarseTriangles = 0, mMeshBytes = 0;
};

/// A block's mesh with its vertices merged into clusters of `cellWorld` (a cube grid fixed in
/// world space, so neighbouring blocks cluster alike): about (cell / voxel)^2 times fewer
/// triangles. Degenerate triangles are dropped.
BlockMesh clusterBlockMesh(const BlockMesh& mesh, double cellWorld);

}  // namespace sculpt::ui
