// SPDX-License-Identifier: Apache-2.0
#include "ui/view/wire_display.h"

#include "ui/view/block_polydata.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

WireDisplay::WireDisplay(vtkRenderer* renderer) : mRenderer(renderer) {}

WireDisplay::~WireDisplay()
{
    if (mActor) mRenderer->RemoveActor(mActor);
}

void WireDisplay::set(const TriangleMesh* mesh)
{
    if (mActor) mRenderer->RemoveActor(mActor);
    mActor = nullptr;
    if (!mesh) return;
    BlockMesh lines;
    lines.positions.assign(mesh->positions.begin(), mesh->positions.end());
    lines.normals.assign(lines.positions.size(), {0.0f, 0.0f, 1.0f});  // unlit: any
    lines.triangles.assign(mesh->triangles.begin(), mesh->triangles.end());
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(polyDataOf(lines));
    mapper->ScalarVisibilityOff();
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -3000.0);
    mActor = vtkSmartPointer<vtkActor>::New();
    mActor->SetMapper(mapper);
    vtkProperty* look = mActor->GetProperty();
    look->SetRepresentationToWireframe();
    look->SetColor(0.12, 0.2, 0.35);
    look->SetLighting(false);
    look->SetLineWidth(1.0f);
    mActor->SetPickable(false);
    mActor->SetVisibility(mShown);
    mRenderer->AddActor(mActor);
}

void WireDisplay::setShown(bool shown)
{
    mShown = shown;
    if (mActor) mActor->SetVisibility(shown);
}

}  // namespace sculpt::ui
