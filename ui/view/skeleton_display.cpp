// SPDX-License-Identifier: Apache-2.0
#include "ui/view/skeleton_display.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

namespace {

/// Dots at the skeletons' points and lines along their edges.
vtkSmartPointer<vtkPolyData> skeletonGeometry(const std::vector<const Skeleton*>& skeletons)
{
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> dots, lines;
    const auto point = [&](const openvdb::Vec3d& p) { return points->InsertNextPoint(p.x(), p.y(), p.z()); };
    const auto line = [&](vtkIdType a, vtkIdType b) {
        const vtkIdType ids[2] = {a, b};
        lines->InsertNextCell(2, ids);
    };
    for (const Skeleton* s : skeletons) {
        switch (s->type) {
        case SkeletonType::Point: {
            const vtkIdType id = point(s->points[0]);
            dots->InsertNextCell(1, &id);
            break;
        }
        case SkeletonType::Segment: line(point(s->points[0]), point(s->points[1])); break;
        case SkeletonType::Triangle: {
            const vtkIdType a = point(s->points[0]), b = point(s->points[1]), c = point(s->points[2]);
            line(a, b), line(b, c), line(c, a);
            break;
        }
        case SkeletonType::Box: {
            vtkIdType corner[8];
            for (int k = 0; k < 8; ++k) {
                const openvdb::Vec3d local((k & 1 ? 1 : -1) * s->halfExtents.x(), (k & 2 ? 1 : -1) * s->halfExtents.y(),
                                           (k & 4 ? 1 : -1) * s->halfExtents.z());
                corner[k] = point(s->points[0] + s->worldFromBox * local);
            }
            for (int k = 0; k < 8; ++k)
                for (int bit : {1, 2, 4})
                    if (!(k & bit)) line(corner[k], corner[k | bit]);  // the 12 edges
            break;
        }
        }
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(dots);
    poly->SetLines(lines);
    return poly;
}

vtkSmartPointer<vtkActor> skeletonActor(double r, double g, double b)
{
    auto actor = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    vtkProperty* look = actor->GetProperty();
    look->SetColor(r, g, b);
    look->SetLineWidth(2.5f);
    look->SetPointSize(9.f);
    look->RenderPointsAsSpheresOn();
    look->LightingOff();
    actor->PickableOff();
    actor->VisibilityOff();
    return actor;
}

}  // namespace

SkeletonDisplay::SkeletonDisplay(vtkRenderer* overlay)
    : mOverlay(overlay), mOthers(skeletonActor(0.35, 0.8, 1.0)), mSelected(skeletonActor(1.0, 0.85, 0.2))
{
    mOverlay->AddActor(mOthers);
    mOverlay->AddActor(mSelected);
}

SkeletonDisplay::~SkeletonDisplay()
{
    mOverlay->RemoveActor(mOthers);
    mOverlay->RemoveActor(mSelected);
}

void SkeletonDisplay::show(const std::vector<Primitive>& primitives, int selected)
{
    std::vector<const Skeleton*> others, chosen;
    for (int i = 0; i < int(primitives.size()); ++i)
        (i == selected ? chosen : others).push_back(&primitives[size_t(i)].skeleton);
    for (auto& [actor, skeletons] : {std::pair{mOthers, others}, std::pair{mSelected, chosen}}) {
        vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(skeletonGeometry(skeletons));
        actor->SetVisibility(!skeletons.empty());
    }
}

}  // namespace sculpt::ui
