// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file brush_cursor.h
/// @brief The brush under the mouse: a ring lying on the surface, turned to its normal and sized
///        to the brush's world radius, plus its mirror images when symmetry is on. The ring's
///        geometry is made once; moving it changes only the actors' matrices.

#include "core/brushes/brush.h"
#include "sculpt/session/stroke.h"

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include <vector>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class BrushCursor {
public:
    /// Draws into `overlay` (a renderer layered above the model, so the ring is never hidden).
    explicit BrushCursor(vtkRenderer* overlay);

    /// Shows the ring at a surface point; hides it when `visible` is false.
    void place(bool visible, const glm::dvec3& position, const glm::dvec3& normal, double radius,
               const Symmetry& symmetry);
    void setColour(double r, double g, double b);

private:
    std::vector<vtkSmartPointer<vtkActor>> mRings;  // [0]: the cursor; then its mirror images
};

}  // namespace sculpt::ui
