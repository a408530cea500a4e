// SPDX-License-Identifier: Apache-2.0
#include "ui/view/symmetry_planes.h"

#include <vtkActor.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

SymmetryPlanes::SymmetryPlanes(vtkRenderer* renderer)
{
    const double colours[3][3] = {{0.95, 0.35, 0.35}, {0.45, 0.9, 0.45}, {0.4, 0.55, 1.0}};
    for (int axis = 0; axis < 3; ++axis) {
        vtkNew<vtkPlaneSource> plane;
        plane->SetOrigin(-1, -1, 0);  // a unit square in z = 0, turned to its axis below
        plane->SetPoint1(1, -1, 0);
        plane->SetPoint2(-1, 1, 0);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(plane->GetOutputPort());
        auto actor = vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(mapper);
        actor->GetProperty()->SetColor(colours[axis][0], colours[axis][1], colours[axis][2]);
        actor->GetProperty()->SetOpacity(0.12);
        actor->GetProperty()->LightingOff();
        if (axis == 0) actor->RotateY(90.0);
        if (axis == 1) actor->RotateX(90.0);
        actor->VisibilityOff();
        actor->PickableOff();
        renderer->AddActor(actor);
        mPlanes[size_t(axis)] = actor;
    }
}

void SymmetryPlanes::show(const Symmetry& symmetry, double halfSize)
{
    const bool on[3] = {symmetry.x, symmetry.y, symmetry.z};
    for (int axis = 0; axis < 3; ++axis) {
        mPlanes[size_t(axis)]->SetScale(halfSize);
        mPlanes[size_t(axis)]->SetVisibility(on[axis]);
    }
}

}  // namespace sculpt::ui
