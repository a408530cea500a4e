#include "ui/view/model_display.h"

#include "ui/view/block_polydata.h"
#include "ui/view/surface_look.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <cmath>
#include <unordered_map>

namespace sculpt::ui {

namespace {

constexpr double kCoarseCellVoxels = 3.0;
constexpr int kChunkBlocks = 4;  // per axis

vtkSmartPointer<vtkActor> actorOf(const BlockMesh& mesh, const SurfaceLook& look)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(polyDataOf(mesh));
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    look.apply(actor);
    return actor;
}

std::size_t bytesOf(const BlockMesh& mesh)
{
    return mesh.positions.size() * 24 + mesh.triangles.size() * 3 * sizeof(vtkIdType);
}

}  // namespace

struct ModelDisplay::Block {
    vtkSmartPointer<vtkActor> full;
    BlockMesh coarse;
    std::size_t bytes = 0;  // of the full mesh
};

struct ModelDisplay::Chunk {
    vtkSmartPointer<vtkActor> actor;
    std::size_t triangles = 0;
    bool dirty = true;
};

ModelDisplay::ModelDisplay(vtkRenderer* renderer, const SurfaceLook& look) : mRenderer(renderer), mLook(look) {}

ModelDisplay::~ModelDisplay()
{
    while (!mBlocks.empty()) remove(mBlocks.begin()->first);
    for (auto& [origin, chunk] : mChunks) mRenderer->RemoveActor(chunk.actor);
}

openvdb::Coord ModelDisplay::chunkOf(const openvdb::Coord& block) const
{
    const int size = kChunkBlocks * mBlockVoxels;
    return {floorToMultiple(block.x(), size), floorToMultiple(block.y(), size), floorToMultiple(block.z(), size)};
}

void ModelDisplay::remove(const openvdb::Coord& origin)
{
    auto it = mBlocks.find(origin);
    if (it == mBlocks.end()) return;
    mRenderer->RemoveActor(it->second.full);
    mMeshBytes -= it->second.bytes;
    mBlocks.erase(it);
    mChunks[chunkOf(origin)].dirty = true;
}

void ModelDisplay::upload(const openvdb::Coord& origin, const BlockMesh& mesh, double voxelSize)
{
    remove(origin);
    Block block{actorOf(mesh, mLook), clusterBlockMesh(mesh, kCoarseCellVoxels * voxelSize), bytesOf(mesh)};
    block.full->SetVisibility(!mCoarse && !mHidden);
    mRenderer->AddActor(block.full);
    mMeshBytes += block.bytes;
    mLastBytes += block.bytes;
    mBlocks.emplace(origin, std::move(block));
    mChunks[chunkOf(origin)].dirty = true;
}

void ModelDisplay::rebuildChunk(const openvdb::Coord& origin, Chunk& chunk)
{
    const int size = kChunkBlocks * mBlockVoxels;
    BlockMesh joined;
    // The map orders blocks by x, then y, then z: walk each x slab of the chunk.
    for (int x = origin.x(); x < origin.x() + size; x += mBlockVoxels) {
        for (auto it = mBlocks.lower_bound(openvdb::Coord(x, origin.y(), origin.z()));
             it != mBlocks.end() && it->first.x() == x && it->first.y() < origin.y() + size; ++it) {
            if (it->first.z() >= origin.z() && it->first.z() < origin.z() + size) append(joined, it->second.coarse);
        }
    }
    if (chunk.actor) mRenderer->RemoveActor(chunk.actor);
    mCoarseTriangles -= chunk.triangles;
    chunk.actor = actorOf(joined, mLook);
    chunk.actor->SetVisibility(mCoarse && !mHidden);
    chunk.triangles = joined.triangles.size();
    mCoarseTriangles += chunk.triangles;
    mRenderer->AddActor(chunk.actor);
    mLastBytes += bytesOf(joined);
    chunk.dirty = false;
}

void ModelDisplay::rebuildDirtyChunks()
{
    for (auto& [origin, chunk] : mChunks) {
        if (chunk.dirty) rebuildChunk(origin, chunk);
    }
}

void ModelDisplay::sync(const IncrementalMesher& mesher, double voxelSize)
{
    mLastUploads = mLastRemovals = mLastBytes = 0;
    IncrementalMesher::Changes changes;
    if (mesher.id() != mSourceId) {
        while (!mBlocks.empty()) remove(mBlocks.begin()->first);
        for (auto& [origin, chunk] : mChunks) mRenderer->RemoveActor(chunk.actor);
        mChunks.clear();
        mCoarseTriangles = 0;
        for (const auto& [origin, mesh] : mesher.blocks()) changes.updated.push_back(origin);
        mSourceId = mesher.id();
        mBlockVoxels = mesher.blockVoxels();
    } else {
        if (mesher.version() == mVersion) return;
        changes = mesher.changesSince(mVersion);
    }
    mVersion = mesher.version();
    for (const openvdb::Coord& origin : changes.removed) {
        remove(origin);
        ++mLastRemovals;
    }
    for (const openvdb::Coord& origin : changes.updated) {
        upload(origin, mesher.blocks().at(origin), voxelSize);
        ++mLastUploads;
    }
    if (mCoarse) rebuildDirtyChunks();
}

void ModelDisplay::setCoarse(bool coarse)
{
    if (coarse == mCoarse) return;
    mCoarse = coarse;
    if (coarse) rebuildDirtyChunks();
    setHidden(mHidden);
}

void ModelDisplay::setHidden(bool hidden)
{
    if (hidden == mHidden) return;  // asked every frame: touch the actors only on a change
    mHidden = hidden;
    for (auto& [origin, block] : mBlocks) block.full->SetVisibility(!mCoarse && !hidden);
    for (auto& [origin, chunk] : mChunks) {
        if (chunk.actor) chunk.actor->SetVisibility(mCoarse && !hidden);  // built when first shown
    }
}

BlockMesh clusterBlockMesh(const BlockMesh& mesh, double cellWorld)
{
    BlockMesh out;
    std::unordered_map<std::uint64_t, std::uint32_t> clusterOf;
    std::vector<std::uint32_t> counts;
    std::vector<std::uint32_t> remap(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto& p = mesh.positions[v];
        std::uint64_t key = 0;
        for (int a = 0; a < 3; ++a)
            key = key << 21 | (std::uint64_t(std::int64_t(std::floor(p[a] / cellWorld)) + (1 << 20)) & 0x1FFFFF);
        auto [it, fresh] = clusterOf.try_emplace(key, std::uint32_t(out.positions.size()));
        if (fresh) {
            out.positions.push_back({0.f, 0.f, 0.f});
            out.normals.push_back({0.f, 0.f, 0.f});
            counts.push_back(0);
        }
        const std::uint32_t c = it->second;
        for (int a = 0; a < 3; ++a) {
            out.positions[c][a] += p[a];
            out.normals[c][a] += mesh.normals[v][a];
        }
        ++counts[c];
        remap[v] = c;
    }
    for (std::size_t c = 0; c < out.positions.size(); ++c) {
        float length = 0.f;
        for (int a = 0; a < 3; ++a) {
            out.positions[c][a] /= float(counts[c]);
            length += out.normals[c][a] * out.normals[c][a];
        }
        length = std::sqrt(length) > 0.f ? std::sqrt(length) : 1.f;
        for (int a = 0; a < 3; ++a) out.normals[c][a] /= length;
    }
    for (const auto& t : mesh.triangles) {
        const std::array<std::uint32_t, 3> r{remap[t[0]], remap[t[1]], remap[t[2]]};
        if (r[0] != r[1] && r[1] != r[2] && r[0] != r[2]) out.triangles.push_back(r);
    }
    return out;
}

}  // namespace sculpt::ui
