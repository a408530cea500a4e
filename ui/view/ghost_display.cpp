#include "ui/view/ghost_display.h"

#include "core/mesh/incremental_mesher.h"
#include "ui/view/block_polydata.h"
#include "ui/view/model_display.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

namespace {

constexpr double kClusterVoxels = 2.0;
constexpr double kOpacity = 0.3;

}  // namespace

GhostDisplay::GhostDisplay(vtkRenderer* renderer) : mRenderer(renderer) {}

GhostDisplay::~GhostDisplay()
{
    if (mActor) mRenderer->RemoveActor(mActor);
}

void GhostDisplay::set(const FieldImage* shape)
{
    if (mActor) mRenderer->RemoveActor(mActor);
    mActor = nullptr;
    mTriangles = 0;
    if (!shape) return;
    IncrementalMesher mesher;
    mesher.rebuild(*shape);
    // Welded first: blocks clustered apart would leave seams that translucency shows.
    const TriangleMesh welded = mesher.weldedMesh();
    BlockMesh whole;
    whole.positions.assign(welded.positions.begin(), welded.positions.end());
    whole.normals.assign(welded.normals.begin(), welded.normals.end());
    whole.triangles.assign(welded.triangles.begin(), welded.triangles.end());
    const BlockMesh ghost = clusterBlockMesh(whole, kClusterVoxels * shape->voxelSize());
    mTriangles = ghost.triangles.size();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(polyDataOf(ghost));
    mapper->ScalarVisibilityOff();
    mActor = vtkSmartPointer<vtkActor>::New();
    mActor->SetMapper(mapper);
    vtkProperty* look = mActor->GetProperty();
    look->SetColor(0.45, 0.7, 1.0);
    look->SetOpacity(kOpacity);
    look->SetSpecular(0.0);
    look->BackfaceCullingOn();
    mActor->SetPickable(false);
    mActor->SetVisibility(mShown);
    mRenderer->AddActor(mActor);
}

void GhostDisplay::setShown(bool shown)
{
    mShown = shown;
    if (mActor) mActor->SetVisibility(shown);
}

}  // namespace sculpt::ui
