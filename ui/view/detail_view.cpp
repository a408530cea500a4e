// SPDX-License-Identifier: Apache-2.0
#include "ui/view/detail_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt::ui {

namespace {

/// Pixels a voxel of the chunk covers where it is nearest the eye (where its voxels look
/// largest); infinite for a chunk that must be drawn in full.
double voxelPixels(const ChunkDetail& chunk, double voxelSize, const DetailView& view)
{
    constexpr double kFull = std::numeric_limits<double>::infinity();
    if (chunk.pinned) return kFull;
    if (view.brushRadius >= 0.0 &&
        glm::length(glm::clamp(view.brushCentre, chunk.lo, chunk.hi) - view.brushCentre) <= view.brushRadius)
        return kFull;
    const glm::dvec3 nearest = glm::clamp(view.eye, chunk.lo, chunk.hi);
    if (nearest == view.eye) return kFull;  // the eye is inside the chunk
    return voxelSize / view.pixelSizeAt(nearest);
}

}  // namespace

std::vector<bool> chooseCoarse(const std::vector<ChunkDetail>& chunks, double voxelSize, const DetailView& view)
{
    std::vector<bool> coarse(chunks.size(), false);
    if (view.still || !view.pixelSizeAt) return coarse;
    std::vector<double> pixels(chunks.size());
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        pixels[i] = voxelPixels(chunks[i], voxelSize, view);
        coarse[i] = pixels[i] < kCoarseBelowVoxelPixels;
        drawn += coarse[i] ? chunks[i].coarseTriangles : chunks[i].fullTriangles;
    }
    if (view.triangleBudget == 0 || drawn <= view.triangleBudget) return coarse;
    std::vector<std::size_t> order;  // the chunks still full that may go coarse, smallest on screen first
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        if (!coarse[i] && std::isfinite(pixels[i])) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pixels[a] < pixels[b]; });
    for (std::size_t i : order) {
        if (drawn <= view.triangleBudget) break;
        coarse[i] = true;
        drawn -= chunks[i].fullTriangles - std::min(chunks[i].fullTriangles, chunks[i].coarseTriangles);
    }
    return coarse;
}

}  // namespace sculpt::ui
