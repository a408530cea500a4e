// SPDX-License-Identifier: Apache-2.0
#include "ui/view/model_display.h"

#include "ui/view/block_cluster.h"
#include "ui/view/block_polydata.h"
#include "ui/view/placement_matrix.h"
#include "ui/view/surface_look.h"
#include "ui/view/twin_builder.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

namespace sculpt::ui {

namespace {

constexpr double kCoarseCellVoxels = 3.0;

/// An actor in the look, placed by `placement` (shared: changing it moves every actor).
vtkSmartPointer<vtkActor> newActor(const SurfaceLook& look, vtkMatrix4x4* placement)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    // A tint, where a chunk has one, is its points' colours (tintPoints).
    mapper->SetColorModeToDirectScalars();
    mapper->SetScalarModeToUsePointData();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->SetUserMatrix(placement);
    look.apply(actor);
    return actor;
}

/// Hands `mesh` to the actor's mapper: its buffers are re-uploaded at the next render.
void setMesh(vtkActor* actor, vtkPolyData* mesh)
{
    vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(mesh);
}

std::size_t bytesOf(const BlockMesh& mesh)
{
    return mesh.positions.size() * 24 + mesh.triangles.size() * 3 * sizeof(std::int32_t);
}

constexpr std::uint32_t kUnnumbered = ~std::uint32_t(0);

/// The `triangles` of `whole` as a mesh of their own, its vertices numbered anew. `scratch`
/// (one entry per vertex of `whole`, all kUnnumbered) is left as it was given.
BlockMesh subMesh(const BlockMesh& whole, const std::vector<std::uint32_t>& triangles,
                  std::vector<std::uint32_t>& scratch)
{
    BlockMesh part;
    std::vector<std::uint32_t> taken;
    for (const std::uint32_t t : triangles) {
        std::array<std::uint32_t, 3> triangle{};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = whole.triangles[t][k];
            if (scratch[v] == kUnnumbered) {
                scratch[v] = std::uint32_t(part.positions.size());
                taken.push_back(v);
                part.positions.push_back(whole.positions[v]);
                part.normals.push_back(whole.normals[v]);
            }
            triangle[k] = scratch[v];
        }
        part.triangles.push_back(triangle);
    }
    for (const std::uint32_t v : taken) scratch[v] = kUnnumbered;
    return part;
}

}  // namespace

struct ModelDisplay::Chunk {
    vtkSmartPointer<vtkActor> full, coarse;  // coarse: made when its first twin comes back
    vtkSmartPointer<vtkPolyData> mesh;       // what `full` draws, never changed once made
    std::size_t fullTriangles = 0, coarseTriangles = 0, bytes = 0, twinBytes = 0;
    glm::dvec3 lo{0.0}, hi{0.0};   // world bounds of its vertices
    std::uint64_t generation = 0;  // of `mesh`: a twin of an older one is dropped
    bool fullStale = true, coarseStale = true, twinAsked = false, drawsCoarse = false;
    bool fresh = false;  // changed by this sync: drawn full, its twin asked for at a later one
};

struct ModelDisplay::Preview {
    BlockMesh mesh;
    openvdb::math::Transform::Ptr xform;
    vtkSmartPointer<vtkActor> actor;
    std::uint64_t replaces = 0;  // the id of the mesher it stands in for
};

ModelDisplay::ModelDisplay(vtkRenderer* renderer, const SurfaceLook& look, int chunkBlocks)
    : mRenderer(renderer), mLook(look), mFixedChunkBlocks(chunkBlocks), mTwins(std::make_unique<TwinBuilder>())
{
    mPlacement = vtkSmartPointer<vtkMatrix4x4>::New();
}

void ModelDisplay::setPlacement(const openvdb::Mat4d& placement)
{
    setPlacementMatrix(*mPlacement, placement);
    mPlacement->Modified();  // the actors sharing it see its time
}

ModelDisplay::~ModelDisplay() { clear(); }

std::size_t ModelDisplay::actorCount() const
{
    std::size_t count = 0;
    for (const auto& [origin, chunk] : mChunks) count += (chunk.full ? 1 : 0) + (chunk.coarse ? 1 : 0);
    return count;
}

openvdb::Coord ModelDisplay::chunkOf(const openvdb::Coord& block) const
{
    const int size = mChunkBlocks * mBlockVoxels;
    return {floorToMultiple(block.x(), size), floorToMultiple(block.y(), size), floorToMultiple(block.z(), size)};
}

void ModelDisplay::clear()
{
    for (auto& [origin, chunk] : mChunks) {
        if (chunk.full) mRenderer->RemoveActor(chunk.full);
        if (chunk.coarse) mRenderer->RemoveActor(chunk.coarse);
    }
    mChunks.clear();
    mMeshBytes = mTwinBytes = 0;
}

void ModelDisplay::layOut(const IncrementalMesher& mesher)
{
    mBlockVoxels = mesher.blockVoxels();
    mChunkBlocks = mFixedChunkBlocks > 0 ? mFixedChunkBlocks : kMinChunkBlocks;
    std::set<openvdb::Coord> origins;
    for (;;) {
        origins.clear();
        for (const auto& [block, mesh] : mesher.blocks()) origins.insert(chunkOf(block));
        if (mFixedChunkBlocks > 0 || origins.size() <= kMaxChunks || mChunkBlocks >= kMaxChunkBlocks) break;
        mChunkBlocks *= 2;
    }
    for (const openvdb::Coord& origin : origins) mChunks.emplace(origin, Chunk{});
}

BlockMesh ModelDisplay::joined(const IncrementalMesher& mesher, const openvdb::Coord& origin) const
{
    const int size = mChunkBlocks * mBlockVoxels;
    BlockMesh whole;
    // Blocks are ordered by x, then y, then z: one range per column of the chunk.
    for (int x = origin.x(); x < origin.x() + size; x += mBlockVoxels) {
        for (int y = origin.y(); y < origin.y() + size; y += mBlockVoxels) {
            for (auto it = mesher.blocks().lower_bound(openvdb::Coord(x, y, origin.z()));
                 it != mesher.blocks().end() && it->first.x() == x && it->first.y() == y &&
                 it->first.z() < origin.z() + size;
                 ++it) {
                append(whole, it->second);
            }
        }
    }
    return whole;
}

void ModelDisplay::uploadFull(const IncrementalMesher& mesher, const openvdb::Coord& origin, Chunk& chunk)
{
    const BlockMesh mesh = joined(mesher, origin);
    if (!chunk.full) {
        chunk.full = newActor(mLook, mPlacement);
        chunk.full->SetVisibility(!mHidden);
        mRenderer->AddActor(chunk.full);
    }
    chunk.mesh = polyDataOf(mesh);
    if (mTint.any()) tintPoints(*chunk.mesh, mesh, mTint);
    setMesh(chunk.full, chunk.mesh);
    mMeshBytes += bytesOf(mesh) - chunk.bytes;
    chunk.bytes = bytesOf(mesh);
    mLastBytes += chunk.bytes;
    chunk.fullTriangles = mesh.triangles.size();
    std::tie(chunk.lo, chunk.hi) = boundsOf(mesh.positions.data(), mesh.positions.size());
    chunk.fresh = chunk.generation != 0;  // changed, not new: a new one's twin is asked at once
    chunk.generation = ++mGenerations;
    chunk.fullStale = false;
    chunk.coarseStale = true;
    chunk.twinAsked = false;
    ++mLastChunkUploads;
}

void ModelDisplay::collectTwins()
{
    for (TwinBuilder::Twin& twin : mTwins->collect()) {
        const auto it = mChunks.find(twin.origin);
        if (it == mChunks.end() || it->second.generation != twin.generation) continue;  // changed since
        Chunk& chunk = it->second;
        if (!chunk.coarse) {
            chunk.coarse = newActor(mLook, mPlacement);
            chunk.coarse->SetVisibility(false);
            mRenderer->AddActor(chunk.coarse);
        }
        vtkSmartPointer<vtkPolyData> coarse = polyDataOf(twin.mesh);
        if (mTint.any()) tintPoints(*coarse, twin.mesh, mTint);  // the grids as they are now, as a new chunk's
        setMesh(chunk.coarse, coarse);
        mLastBytes += bytesOf(twin.mesh);
        chunk.coarseTriangles = twin.mesh.triangles.size();
        mTwinBytes += bytesOf(twin.mesh) - chunk.twinBytes;
        chunk.twinBytes = bytesOf(twin.mesh);
        chunk.coarseStale = false;
    }
}

void ModelDisplay::askTwins(double voxelSize)
{
    for (auto& [origin, chunk] : mChunks) {
        if (std::exchange(chunk.fresh, false) || !chunk.coarseStale || chunk.twinAsked) continue;
        mTwins->request(origin, chunk.generation, chunk.mesh, kCoarseCellVoxels * voxelSize);
        chunk.twinAsked = true;
    }
}

void ModelDisplay::finishTwins(double voxelSize)
{
    for (auto& [origin, chunk] : mChunks) chunk.fresh = false;
    askTwins(voxelSize);
    mTwins->wait();
    collectTwins();
}

void ModelDisplay::show(Chunk& chunk, bool coarse)
{
    chunk.drawsCoarse = coarse;
    if (chunk.full) chunk.full->SetVisibility(!mHidden && !coarse);
    if (chunk.coarse) chunk.coarse->SetVisibility(!mHidden && coarse);
}

void ModelDisplay::chooseDetail(double voxelSize, const DetailView& view)
{
    const double twinShrink = kCoarseCellVoxels * kCoarseCellVoxels;  // a twin not yet back, estimated
    std::vector<ChunkDetail> details;
    details.reserve(mChunks.size());
    for (const auto& [origin, chunk] : mChunks) {
        const std::size_t twin =
            chunk.coarseStale ? std::size_t(double(chunk.fullTriangles) / twinShrink) : chunk.coarseTriangles;
        details.push_back({chunk.lo, chunk.hi, chunk.fullTriangles, twin, chunk.fresh});
    }
    const std::vector<bool> wanted = chooseCoarse(details, voxelSize, view);
    mTrianglesDrawn = mCoarseChunks = 0;
    std::size_t i = 0;
    for (auto& [origin, chunk] : mChunks) {
        // Full detail until its twin is back; its preview part until its first upload.
        const bool coarse = !chunk.full || (wanted[i] && !chunk.coarseStale);
        ++i;
        if (coarse != chunk.drawsCoarse) show(chunk, coarse);
        mTrianglesDrawn += coarse ? chunk.coarseTriangles : chunk.fullTriangles;
        mCoarseChunks += coarse ? 1 : 0;
    }
}

void ModelDisplay::sync(const IncrementalMesher& mesher, double voxelSize, const DetailView& view,
                        const SurfaceTint& tint)
{
    if (!tint.sameSettings(mTint))
        for (auto& [origin, chunk] : mChunks) chunk.fullStale = true;  // every chunk coloured anew
    mTint = tint;
    mLastUploads = mLastRemovals = mLastChunkUploads = mLastBytes = 0;
    if (mPreview && mesher.id() == mPreview->replaces) return;  // the preview alone is shown
    if (mesher.id() != mSourceId) {
        clear();
        layOut(mesher);
        cutPreview();
        mSourceId = mesher.id();
        mLastUploads = mesher.blocks().size();
    } else if (mesher.version() != mVersion) {
        const IncrementalMesher::Changes changes = mesher.changesSince(mVersion);
        for (const auto* list : {&changes.updated, &changes.removed}) {
            for (const openvdb::Coord& block : *list) mChunks[chunkOf(block)].fullStale = true;
        }
        mLastUploads = changes.updated.size();
        mLastRemovals = changes.removed.size();
        if (mFixedChunkBlocks == 0 && mChunks.size() > 2 * kMaxChunks && mChunkBlocks < kMaxChunkBlocks) {
            clear();  // the model outgrew its chunks: lay them out again
            layOut(mesher);
        }
    }
    mVersion = mesher.version();
    mBlockCount = mesher.blocks().size();
    uploadStale(mesher);
    collectTwins();
    chooseDetail(voxelSize, view);
    askTwins(voxelSize);
}

void ModelDisplay::uploadStale(const IncrementalMesher& mesher)
{
    std::size_t filled = 0;
    mPendingChunks = 0;
    for (auto it = mChunks.begin(); it != mChunks.end();) {
        Chunk& chunk = it->second;
        const bool first = !chunk.full;
        if (chunk.fullStale && first && chunk.coarse && filled >= mFillBudget) {
            ++mPendingChunks;  // its preview part stands in for it a sync longer
            ++it;
            continue;
        }
        if (chunk.fullStale) uploadFull(mesher, it->first, chunk);
        if (first) filled += chunk.fullTriangles;
        if (chunk.fullTriangles > 0) {
            ++it;
            continue;
        }
        mRenderer->RemoveActor(chunk.full);  // every block of it is gone
        if (chunk.coarse) mRenderer->RemoveActor(chunk.coarse);
        mMeshBytes -= chunk.bytes;
        mTwinBytes -= chunk.twinBytes;
        it = mChunks.erase(it);
    }
}

void ModelDisplay::showPreview(const TriangleMesh& preview, const openvdb::math::Transform& xform)
{
    dropPreview();
    clear();
    mPreview = std::make_unique<Preview>();
    mPreview->mesh.positions.assign(preview.positions.begin(), preview.positions.end());
    mPreview->mesh.normals.assign(preview.normals.begin(), preview.normals.end());
    mPreview->mesh.triangles.assign(preview.triangles.begin(), preview.triangles.end());
    mPreview->xform = xform.copy();
    mPreview->actor = newActor(mLook, mPlacement);
    mPreview->actor->SetVisibility(!mHidden);
    setMesh(mPreview->actor, polyDataOf(mPreview->mesh));
    mPreview->replaces = mSourceId;
    mRenderer->AddActor(mPreview->actor);
    mTrianglesDrawn = preview.triangles.size();
}

void ModelDisplay::dropPreview()
{
    if (!mPreview) return;
    mRenderer->RemoveActor(mPreview->actor);
    mPreview.reset();
    mSourceId = 0;  // lay the mesher shown before out again
}

void ModelDisplay::cutPreview()
{
    if (!mPreview) return;
    const BlockMesh& whole = mPreview->mesh;
    // Each triangle goes to the chunk holding its centroid (none: dropped, it strays a coarse
    // voxel out of the model's blocks).
    std::map<Chunk*, std::vector<std::uint32_t>> parts;
    for (std::uint32_t t = 0; t < whole.triangles.size(); ++t) {
        openvdb::Vec3d centroid(0.0);
        for (const std::uint32_t v : whole.triangles[t])
            centroid += openvdb::Vec3d(whole.positions[v][0], whole.positions[v][1], whole.positions[v][2]) / 3.0;
        const auto it = mChunks.find(chunkOf(openvdb::Coord::floor(mPreview->xform->worldToIndex(centroid))));
        if (it != mChunks.end()) parts[&it->second].push_back(t);
    }
    std::vector<std::uint32_t> scratch(whole.positions.size(), kUnnumbered);
    for (auto& [chunk, triangles] : parts) {
        const BlockMesh part = subMesh(whole, triangles, scratch);
        chunk->coarse = newActor(mLook, mPlacement);
        mRenderer->AddActor(chunk->coarse);
        setMesh(chunk->coarse, polyDataOf(part));
        chunk->coarseTriangles = part.triangles.size();
        chunk->twinBytes = bytesOf(part);
        mTwinBytes += chunk->twinBytes;
        chunk->coarseStale = false;
        std::tie(chunk->lo, chunk->hi) = boundsOf(part.positions.data(), part.positions.size());
        show(*chunk, true);
    }
    mRenderer->RemoveActor(mPreview->actor);
    mPreview.reset();
}

void ModelDisplay::setHidden(bool hidden)
{
    if (hidden == mHidden) return;  // asked every frame: touch the actors only on a change
    mHidden = hidden;
    for (auto& [origin, chunk] : mChunks) show(chunk, chunk.drawsCoarse);
}

}  // namespace sculpt::ui
