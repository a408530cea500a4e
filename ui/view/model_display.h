#pragma once
/// @file model_display.h
/// @brief The sculpt on screen: the mesher's blocks grouped into display chunks, one VTK actor
///        per chunk (and one for its coarse twin), so the actors stay a few hundred whatever the
///        model's size.
///
/// Each actor costs Mesa ~30 us a frame, and VTK's bookkeeping of actors and buffers is linear
/// in their number: one actor per 16^3 block made a stroke on an 8 M-triangle scan cost O(15,000)
/// per changed block. A chunk is a cube of C^3 blocks; C starts at 4 (about 10^4 triangles on a
/// surface, as Blender's PBVH leaves) and doubles until there are at most kMaxChunks. A chunk is
/// re-joined and re-uploaded, into the actor it already has, once per sync when one of its
/// blocks changed; its coarse twin (the chunk's mesh clustered, about 9x fewer triangles) is
/// clustered on a worker thread (TwinBuilder) once the chunk has rested a frame, so that a
/// camera move finds it ready; until it is back the chunk draws full detail. Which of the two a
/// chunk draws is the DetailView's rule. Every actor shares the SurfaceLook's property and shader.

#include "core/mesh/incremental_mesher.h"
#include "ui/view/detail_view.h"

#include <vtkSmartPointer.h>

#include <map>
#include <memory>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class SurfaceLook;
class TwinBuilder;

class ModelDisplay {
public:
    /// Chunks at most, unless a chunk of kMaxChunkBlocks^3 blocks cannot get there.
    static constexpr std::size_t kMaxChunks = 512;
    static constexpr int kMinChunkBlocks = 4, kMaxChunkBlocks = 32;

    /// @param chunkBlocks C, blocks per chunk edge; 0 chooses it from the model (see above).
    ModelDisplay(vtkRenderer* renderer, const SurfaceLook& look, int chunkBlocks = 0);
    ~ModelDisplay();

    /// Uploads the chunks whose blocks the mesher changed since the last sync (all of them for a
    /// new mesher), then gives each chunk the detail `view` asks. `voxelSize` sizes the coarse
    /// twins' clusters. Once per frame.
    void sync(const IncrementalMesher& mesher, double voxelSize, const DetailView& view = {});
    /// Waits for the coarse twin of every chunk and takes them (for tests: a frame never waits).
    void finishTwins(double voxelSize);
    /// Hides every actor (another view of the model, the scales, is shown instead).
    void setHidden(bool hidden);

    /// Of the last sync: blocks changed and dropped, chunks re-uploaded, bytes handed to VTK.
    std::size_t lastUploads() const { return mLastUploads; }
    std::size_t lastRemovals() const { return mLastRemovals; }
    std::size_t lastChunkUploads() const { return mLastChunkUploads; }
    std::size_t lastUploadBytes() const { return mLastBytes; }
    std::size_t blockCount() const { return mBlockCount; }
    std::size_t chunkCount() const { return mChunks.size(); }
    int chunkBlocks() const { return mChunkBlocks; }
    /// Actors of the model the renderer holds, and those drawn this frame.
    std::size_t actorCount() const;
    std::size_t actorsDrawn() const { return mHidden ? 0 : mChunks.size(); }
    /// Triangles drawn this frame, and how many chunks draw their coarse twin.
    std::size_t trianglesDrawn() const { return mHidden ? 0 : mTrianglesDrawn; }
    std::size_t coarseChunks() const { return mCoarseChunks; }
    /// Bytes of every full-detail chunk as handed to VTK: what one upload of the whole mesh costs.
    std::size_t meshBytes() const { return mMeshBytes; }
    /// Bytes of VTK geometry held, full chunks and twins (the GL driver keeps a copy as large).
    std::size_t heldBytes() const { return mMeshBytes + mTwinBytes; }

private:
    struct Chunk;
    openvdb::Coord chunkOf(const openvdb::Coord& block) const;
    void clear();
    void layOut(const IncrementalMesher& mesher);
    BlockMesh joined(const IncrementalMesher& mesher, const openvdb::Coord& origin) const;
    void uploadFull(const IncrementalMesher& mesher, const openvdb::Coord& origin, Chunk& chunk);
    /// Takes the twins the worker finished, for the chunks that have not changed since.
    void collectTwins();
    void chooseDetail(double voxelSize, const DetailView& view);
    /// Asks the worker for the twins left stale, of chunks that did not change this sync; ends
    /// every chunk's fresh mark.
    void askTwins(double voxelSize);
    void show(Chunk& chunk, bool coarse);

    vtkRenderer* mRenderer;
    const SurfaceLook& mLook;
    const int mFixedChunkBlocks;
    std::map<openvdb::Coord, Chunk> mChunks;
    int mBlockVoxels = IncrementalMesher::kDefaultBlockVoxels;
    int mChunkBlocks = kMinChunkBlocks;
    std::uint64_t mSourceId = 0;  // IncrementalMesher::id of the mesher shown
    std::uint64_t mVersion = 0;
    std::uint64_t mGenerations = 0;  // chunk meshes made
    std::unique_ptr<TwinBuilder> mTwins;
    bool mHidden = false;
    std::size_t mBlockCount = 0, mTrianglesDrawn = 0, mCoarseChunks = 0, mMeshBytes = 0, mTwinBytes = 0;
    std::size_t mLastUploads = 0, mLastRemovals = 0, mLastChunkUploads = 0, mLastBytes = 0;
};

}  // namespace sculpt::ui
