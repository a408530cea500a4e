// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file detail_view.h
/// @brief The level of detail of the model display: which chunks of the surface are drawn from
///        their coarse twins this frame.
///
/// While the camera moves or a stroke runs, a chunk whose voxels cover less than two pixels on
/// screen is drawn coarse (clusters of 3 voxels, about 9x fewer triangles): a marching-cubes
/// surface has about two triangles per voxel face, and its back and folded sides are drawn too,
/// so at one pixel a voxel an 8 M-triangle scan still drew 8 M. If more triangles than the
/// window's pixels remain, the chunks smallest on screen go coarse next until they fit: Mesa's
/// llvmpipe draws about 10-20 M triangles a second on two cores, so a budget of one triangle a
/// pixel keeps a moving frame near 10 fps whatever the model.
/// Chunks the brush reaches stay at full detail, as do chunks that changed this frame; when the
/// camera is still, everything does.

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace sculpt::ui {

struct DetailView {
    bool still = true;  ///< the camera rests and no stroke runs: full detail everywhere
    glm::dvec3 eye{0.0};
    std::function<double(const glm::dvec3&)> pixelSizeAt;  ///< world length of one pixel there
    glm::dvec3 brushCentre{0.0};
    double brushRadius = -1.0;       ///< below zero: no brush on the model
    std::size_t triangleBudget = 0;  ///< triangles to draw at most while moving (0: no bound)
};

/// Voxels smaller than this many pixels on screen are drawn from the coarse twin.
inline constexpr double kCoarseBelowVoxelPixels = 2.0;

/// A display chunk as the rule sees it.
struct ChunkDetail {
    glm::dvec3 lo{0.0}, hi{0.0};  ///< world bounds of its vertices
    std::size_t fullTriangles = 0, coarseTriangles = 0;
    bool pinned = false;  ///< drawn in full whatever the view (it changed this frame)
};

/// For each chunk, whether it draws its coarse twin, for a field with voxels of `voxelSize`.
std::vector<bool> chooseCoarse(const std::vector<ChunkDetail>& chunks, double voxelSize, const DetailView& view);

}  // namespace sculpt::ui
