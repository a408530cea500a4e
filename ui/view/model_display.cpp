#include "ui/view/model_display.h"

#include "ui/view/block_cluster.h"
#include "ui/view/block_polydata.h"
#include "ui/view/surface_look.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <set>

namespace sculpt::ui {

namespace {

constexpr double kCoarseCellVoxels = 3.0;
/// Of a still frame, spent building coarse twins ahead of the next camera move; as much again
/// at most on a moving frame for a twin it needs (the others draw full detail meanwhile).
constexpr double kTwinSecondsPerFrame = 0.010;

using Clock = std::chrono::steady_clock;

Clock::time_point after(double seconds)
{
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

vtkSmartPointer<vtkActor> newActor(const SurfaceLook& look)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    look.apply(actor);
    return actor;
}

/// Hands `mesh` to the actor's mapper: its buffers are re-uploaded at the next render.
void setMesh(vtkActor* actor, const BlockMesh& mesh)
{
    vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(polyDataOf(mesh));
}

std::size_t bytesOf(const BlockMesh& mesh)
{
    return mesh.positions.size() * 24 + mesh.triangles.size() * 3 * sizeof(std::int32_t);
}

}  // namespace

struct ModelDisplay::Chunk {
    vtkSmartPointer<vtkActor> full, coarse;  // coarse: made when first drawn
    std::size_t fullTriangles = 0, coarseTriangles = 0, bytes = 0;
    glm::dvec3 lo{0.0}, hi{0.0};  // world bounds of its vertices
    bool fullStale = true, coarseStale = true, drawsCoarse = false;
    bool fresh = false;  // uploaded by this sync: drawn in full, its twin not yet built
};

ModelDisplay::ModelDisplay(vtkRenderer* renderer, const SurfaceLook& look, int chunkBlocks)
    : mRenderer(renderer), mLook(look), mFixedChunkBlocks(chunkBlocks)
{}

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
    mMeshBytes = 0;
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
        chunk.full = newActor(mLook);
        chunk.full->SetVisibility(!mHidden);
        mRenderer->AddActor(chunk.full);
    }
    setMesh(chunk.full, mesh);
    mMeshBytes += bytesOf(mesh) - chunk.bytes;
    chunk.bytes = bytesOf(mesh);
    mLastBytes += chunk.bytes;
    chunk.fullTriangles = mesh.triangles.size();
    chunk.lo = glm::dvec3(std::numeric_limits<double>::max());
    chunk.hi = -chunk.lo;
    for (const auto& p : mesh.positions) {
        chunk.lo = glm::min(chunk.lo, glm::dvec3(p[0], p[1], p[2]));
        chunk.hi = glm::max(chunk.hi, glm::dvec3(p[0], p[1], p[2]));
    }
    chunk.fullStale = false;
    chunk.coarseStale = true;
    chunk.fresh = true;
    ++mLastChunkUploads;
}

void ModelDisplay::uploadCoarse(const IncrementalMesher& mesher, const openvdb::Coord& origin, Chunk& chunk,
                                double voxelSize)
{
    const BlockMesh mesh = clusterBlockMesh(joined(mesher, origin), kCoarseCellVoxels * voxelSize);
    if (!chunk.coarse) {
        chunk.coarse = newActor(mLook);
        chunk.coarse->SetVisibility(false);
        mRenderer->AddActor(chunk.coarse);
    }
    setMesh(chunk.coarse, mesh);
    mLastBytes += bytesOf(mesh);
    chunk.coarseTriangles = mesh.triangles.size();
    chunk.coarseStale = false;
}

void ModelDisplay::show(Chunk& chunk, bool coarse)
{
    chunk.drawsCoarse = coarse;
    chunk.full->SetVisibility(!mHidden && !coarse);
    if (chunk.coarse) chunk.coarse->SetVisibility(!mHidden && coarse);
}

void ModelDisplay::chooseDetail(const IncrementalMesher& mesher, double voxelSize, const DetailView& view)
{
    const double twinShrink = kCoarseCellVoxels * kCoarseCellVoxels;  // a twin not yet built, estimated
    std::vector<ChunkDetail> details;
    details.reserve(mChunks.size());
    for (const auto& [origin, chunk] : mChunks) {
        const std::size_t twin =
            chunk.coarseStale ? std::size_t(double(chunk.fullTriangles) / twinShrink) : chunk.coarseTriangles;
        details.push_back({chunk.lo, chunk.hi, chunk.fullTriangles, twin, chunk.fresh});
    }
    const std::vector<bool> wanted = chooseCoarse(details, voxelSize, view);
    const Clock::time_point deadline = after(kTwinSecondsPerFrame);
    mTrianglesDrawn = mCoarseChunks = 0;
    std::size_t i = 0;
    for (auto& [origin, chunk] : mChunks) {
        bool coarse = wanted[i++];
        if (coarse && chunk.coarseStale) {
            if (Clock::now() < deadline) uploadCoarse(mesher, origin, chunk, voxelSize);
            else coarse = false;  // full detail this frame; the twin is built on a later one
        }
        if (coarse != chunk.drawsCoarse) show(chunk, coarse);
        chunk.fresh = false;
        mTrianglesDrawn += coarse ? chunk.coarseTriangles : chunk.fullTriangles;
        mCoarseChunks += coarse ? 1 : 0;
    }
}

bool ModelDisplay::buildCoarseTwins(const IncrementalMesher& mesher, double voxelSize, double seconds)
{
    if (mesher.id() != mSourceId || mesher.version() != mVersion) return false;  // the next sync lays out anew
    const Clock::time_point deadline = after(seconds);
    for (auto& [origin, chunk] : mChunks) {
        if (!chunk.coarseStale) continue;
        if (Clock::now() >= deadline) return true;
        uploadCoarse(mesher, origin, chunk, voxelSize);
    }
    return false;
}

void ModelDisplay::sync(const IncrementalMesher& mesher, double voxelSize, const DetailView& view)
{
    mLastUploads = mLastRemovals = mLastChunkUploads = mLastBytes = 0;
    if (mesher.id() != mSourceId) {
        clear();
        layOut(mesher);
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
    for (auto it = mChunks.begin(); it != mChunks.end();) {
        Chunk& chunk = it->second;
        if (chunk.fullStale) uploadFull(mesher, it->first, chunk);
        if (chunk.fullTriangles > 0) {
            ++it;
            continue;
        }
        mRenderer->RemoveActor(chunk.full);  // every block of it is gone
        if (chunk.coarse) mRenderer->RemoveActor(chunk.coarse);
        mMeshBytes -= chunk.bytes;
        it = mChunks.erase(it);
    }
    chooseDetail(mesher, voxelSize, view);
    if (view.still) buildCoarseTwins(mesher, voxelSize, kTwinSecondsPerFrame);
}

void ModelDisplay::setHidden(bool hidden)
{
    if (hidden == mHidden) return;  // asked every frame: touch the actors only on a change
    mHidden = hidden;
    for (auto& [origin, chunk] : mChunks) show(chunk, chunk.drawsCoarse);
}

}  // namespace sculpt::ui
