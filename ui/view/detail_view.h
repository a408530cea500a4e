#pragma once
/// @file detail_view.h
/// @brief The level of detail of the model display: which chunks of the surface may be drawn
///        from their coarse twins this frame.
///
/// While the camera moves or a stroke runs, a chunk whose voxels cover less than two pixels on
/// screen is drawn coarse (clusters of 3 voxels, about 9x fewer triangles): a marching-cubes
/// surface has about two triangles per voxel face, and its back and folded sides are drawn too,
/// so at one pixel a voxel an 8 M-triangle scan still drew 8 M. The triangles drawn then follow
/// the pixels the model covers, not the model's size.
/// Chunks the brush reaches stay at full detail; when the camera is still, everything does.

#include <glm/glm.hpp>

#include <functional>

namespace sculpt::ui {

struct DetailView {
    bool still = true;  ///< the camera rests and no stroke runs: full detail everywhere
    glm::dvec3 eye{0.0};
    std::function<double(const glm::dvec3&)> pixelSizeAt;  ///< world length of one pixel there
    glm::dvec3 brushCentre{0.0};
    double brushRadius = -1.0;  ///< below zero: no brush on the model
};

/// Voxels smaller than this many pixels on screen are drawn from the coarse twin.
inline constexpr double kCoarseBelowVoxelPixels = 2.0;

/// Whether the chunk in world box [lo, hi] of a field with voxels of `voxelSize` is drawn coarse.
bool drawsCoarse(const glm::dvec3& lo, const glm::dvec3& hi, double voxelSize, const DetailView& view);

}  // namespace sculpt::ui
