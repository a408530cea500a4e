// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file symmetry_planes.h
/// @brief The active mirror planes (x = 0, y = 0, z = 0), drawn faintly through the model.

#include "sculpt/session/stroke.h"

#include <vtkSmartPointer.h>

#include <array>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class SymmetryPlanes {
public:
    explicit SymmetryPlanes(vtkRenderer* renderer);
    /// Shows the planes `symmetry` turns on, as squares of half side `halfSize` at the origin.
    void show(const Symmetry& symmetry, double halfSize);

private:
    std::array<vtkSmartPointer<vtkActor>, 3> mPlanes;
};

}  // namespace sculpt::ui
