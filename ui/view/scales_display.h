// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scales_display.h
/// @brief The "scales" view (after Desbrun, Tsingos and Cani): small discs lying on the surface
///        at its samples, each turned to the surface normal there. A quick read of the shape, its
///        normals and its sampling, drawn with far fewer primitives than the full mesh: one
///        hexagon per sample, a sample per 3-voxel cell of the surface (vertex clustering of the
///        mesher's blocks), drawn as instances of one glyph (vtkGlyph3DMapper).

#include "core/mesh/incremental_mesher.h"

#include <vtkSmartPointer.h>

#include <cstdint>

class vtkActor;
class vtkGlyph3DMapper;
class vtkRenderer;

namespace sculpt::ui {

class ScalesDisplay {
public:
    static constexpr double kCellVoxels = 3.0;  ///< one scale per cell of this many voxels

    explicit ScalesDisplay(vtkRenderer* renderer);
    ~ScalesDisplay();

    void setShown(bool shown);
    bool shown() const { return mShown; }
    /// While shown: rebuilds the scales when the mesher (or its version) changed.
    void sync(const IncrementalMesher& mesher, double voxelSize);
    std::size_t scaleCount() const { return mCount; }

private:
    vtkRenderer* mRenderer;
    vtkSmartPointer<vtkActor> mActor;
    vtkSmartPointer<vtkGlyph3DMapper> mMapper;
    std::uint64_t mSourceId = 0;  // IncrementalMesher::id of the mesher shown
    std::uint64_t mVersion = ~std::uint64_t(0);
    bool mShown = false;
    std::size_t mCount = 0;
};

}  // namespace sculpt::ui
