// SPDX-License-Identifier: Apache-2.0
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
///
/// Opening a large document, a coarse preview (previewMesh) stands in for the model: whole, until
/// the new mesher comes, then cut into the chunks' coarse actors, each drawn until its chunk's
/// first full upload. Those uploads fill in at most fillBudget() triangles a sync, so that no
/// frame carries the whole model's upload (2.8 s of Mesa for 8 M triangles) and the window stays
/// responsive while the detail fills in.

#include "core/mesh/incremental_mesher.h"
#include "ui/view/detail_view.h"
#include "ui/view/surface_tint.h"

#include <vtkSmartPointer.h>

#include <map>
#include <memory>

class vtkActor;
class vtkMatrix4x4;
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
    /// `tint` colours the chunks uploaded (the mask, a print check); a change of the mask marks
    /// its leaves dirty, so the mesher's changes bring those chunks here again, and a change of
    /// the check re-uploads every chunk.
    void sync(const IncrementalMesher& mesher, double voxelSize, const DetailView& view = {},
              const SurfaceTint& tint = {});
    /// Waits for the coarse twin of every chunk and takes them (for tests: a frame never waits).
    void finishTwins(double voxelSize);
    /// Shows `preview` (world coordinates, of a grid on `xform`) instead of the mesher shown now,
    /// until sync() is given another mesher (see above).
    void showPreview(const TriangleMesh& preview, const openvdb::math::Transform& xform);
    /// Drops a preview still whole (its document did not come): the mesher shown before returns.
    void dropPreview();
    bool showsPreview() const { return mPreview != nullptr; }
    /// Chunks waiting for their first full upload, drawn from their part of the preview meanwhile.
    std::size_t pendingChunks() const { return mPendingChunks; }
    /// Triangles of first uploads a sync makes at most, for chunks that have a preview to draw.
    std::size_t fillBudget() const { return mFillBudget; }
    void setFillBudget(std::size_t triangles) { mFillBudget = triangles; }
    /// Hides every actor (another view of the model, the scales, is shown instead).
    void setHidden(bool hidden);
    /// Where the model is drawn: world from its field's world (its piece's placement).
    void setPlacement(const openvdb::Mat4d& placement);

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
    struct Preview;
    openvdb::Coord chunkOf(const openvdb::Coord& block) const;
    void clear();
    void layOut(const IncrementalMesher& mesher);
    /// Gives each chunk its part of the preview as its coarse actor, and drops the whole one.
    void cutPreview();
    /// Re-joins and uploads the chunks whose blocks changed, first uploads within the budget.
    void uploadStale(const IncrementalMesher& mesher);
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
    vtkSmartPointer<vtkMatrix4x4> mPlacement;  // every actor's
    const int mFixedChunkBlocks;
    std::map<openvdb::Coord, Chunk> mChunks;
    int mBlockVoxels = IncrementalMesher::kDefaultBlockVoxels;
    int mChunkBlocks = kMinChunkBlocks;
    std::uint64_t mSourceId = 0;  // IncrementalMesher::id of the mesher shown
    std::uint64_t mVersion = 0;
    std::uint64_t mGenerations = 0;  // chunk meshes made
    std::unique_ptr<TwinBuilder> mTwins;
    std::unique_ptr<Preview> mPreview;
    SurfaceTint mTint;  // of the last sync, for its uploads
    std::size_t mFillBudget = 1'000'000, mPendingChunks = 0;
    bool mHidden = false;
    std::size_t mBlockCount = 0, mTrianglesDrawn = 0, mCoarseChunks = 0, mMeshBytes = 0, mTwinBytes = 0;
    std::size_t mLastUploads = 0, mLastRemovals = 0, mLastChunkUploads = 0, mLastBytes = 0;
};

}  // namespace sculpt::ui
