// SPDX-License-Identifier: Apache-2.0
#include "ui/view/brush_cursor.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <cmath>

namespace sculpt::ui {

namespace {

constexpr int kSegments = 72;

/// The unit circle in the z = 0 plane, as one closed polyline.
vtkSmartPointer<vtkPolyData> unitRing()
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    lines->InsertNextCell(kSegments + 1);
    for (int i = 0; i < kSegments; ++i) {
        const double a = 2.0 * M_PI * i / kSegments;
        points->InsertNextPoint(std::cos(a), std::sin(a), 0.0);
        lines->InsertCellPoint(i);
    }
    lines->InsertCellPoint(0);
    auto ring = vtkSmartPointer<vtkPolyData>::New();
    ring->SetPoints(points);
    ring->SetLines(lines);
    return ring;
}

/// Maps the unit ring to a circle of `radius` at `p`, in the plane normal to `n`.
void setRingMatrix(vtkActor* actor, const glm::dvec3& p, const glm::dvec3& n, double radius)
{
    const glm::dvec3 z = glm::normalize(n);
    const glm::dvec3 helper = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(helper, z));
    const glm::dvec3 y = glm::cross(z, x);
    const glm::dvec3 lifted = p + z * (0.02 * radius);  // just above the clay
    vtkNew<vtkMatrix4x4> m;
    for (int r = 0; r < 3; ++r) {
        m->SetElement(r, 0, x[r] * radius);
        m->SetElement(r, 1, y[r] * radius);
        m->SetElement(r, 2, z[r] * radius);
        m->SetElement(r, 3, lifted[r]);
    }
    actor->SetUserMatrix(m);
}

}  // namespace

BrushCursor::BrushCursor(vtkRenderer* overlay)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(unitRing());
    for (int i = 0; i < 8; ++i) {
        auto ring = vtkSmartPointer<vtkActor>::New();
        ring->SetMapper(mapper);
        ring->GetProperty()->SetLineWidth(2.0f);
        ring->GetProperty()->LightingOff();
        ring->GetProperty()->SetColor(1.0, 1.0, 1.0);
        ring->GetProperty()->SetOpacity(i == 0 ? 1.0 : 0.55);
        ring->VisibilityOff();
        overlay->AddActor(ring);
        mRings.push_back(ring);
    }
}

void BrushCursor::place(bool visible, const glm::dvec3& position, const glm::dvec3& normal, double radius,
                        const Symmetry& symmetry)
{
    int used = 0;
    for (int mask = 0; mask < 8 && visible; ++mask) {
        if (((mask & 1) && !symmetry.x) || ((mask & 2) && !symmetry.y) || ((mask & 4) && !symmetry.z)) continue;
        const glm::dvec3 sign(mask & 1 ? -1.0 : 1.0, mask & 2 ? -1.0 : 1.0, mask & 4 ? -1.0 : 1.0);
        setRingMatrix(mRings[size_t(used)], position * sign, normal * sign, radius);
        mRings[size_t(used++)]->VisibilityOn();
    }
    for (size_t i = size_t(used); i < mRings.size(); ++i) mRings[i]->VisibilityOff();
}

void BrushCursor::setColour(double r, double g, double b)
{
    for (auto& ring : mRings) ring->GetProperty()->SetColor(r, g, b);
}

}  // namespace sculpt::ui
