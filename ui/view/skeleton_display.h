// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file skeleton_display.h
/// @brief The skeletons of the primitives being placed, drawn over everything (in the overlay
///        layer): points as dots, segments, triangles and boxes as their edges; the selected one
///        brighter. Seen through the transparent sculpt, they show where each primitive's field
///        comes from.

#include "core/primitives/primitive_set.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class SkeletonDisplay {
public:
    explicit SkeletonDisplay(vtkRenderer* overlay);
    ~SkeletonDisplay();

    /// Draws `primitives` (none: hidden), `selected` highlighted.
    void show(const std::vector<Primitive>& primitives, int selected);

private:
    vtkRenderer* mOverlay;
    vtkSmartPointer<vtkActor> mOthers, mSelected;
};

}  // namespace sculpt::ui
