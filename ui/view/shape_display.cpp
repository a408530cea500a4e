// SPDX-License-Identifier: Apache-2.0
#include "ui/view/shape_display.h"

#include "core/field/placed_box.h"
#include "core/mesh/incremental_mesher.h"
#include "ui/view/block_cluster.h"
#include "ui/view/block_polydata.h"
#include "ui/view/placement_matrix.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

ShapeDisplay::ShapeDisplay(vtkRenderer* renderer, ShapeStyle style) : mRenderer(renderer), mStyle(style) {}

ShapeDisplay::~ShapeDisplay()
{
    if (mActor) mRenderer->RemoveActor(mActor);
}

void ShapeDisplay::set(const FieldImage* shape)
{
    if (mActor) mRenderer->RemoveActor(mActor);
    mActor = nullptr;
    mTriangles = 0;
    mBox = openvdb::BBoxd();
    if (!shape) return;
    IncrementalMesher mesher;
    mesher.rebuild(*shape);
    set(mesher, shape->voxelSize());
}

void ShapeDisplay::set(const IncrementalMesher& mesher, double voxelSize)
{
    if (mActor) mRenderer->RemoveActor(mActor);
    // Welded first: blocks clustered apart would leave seams that translucency shows.
    const TriangleMesh welded = mesher.weldedMesh();
    BlockMesh whole;
    whole.positions.assign(welded.positions.begin(), welded.positions.end());
    whole.normals.assign(welded.normals.begin(), welded.normals.end());
    whole.triangles.assign(welded.triangles.begin(), welded.triangles.end());
    const BlockMesh shown =
        mStyle.clusterVoxels > 0.0 ? clusterBlockMesh(whole, mStyle.clusterVoxels * voxelSize) : whole;
    mTriangles = shown.triangles.size();
    mBox = openvdb::BBoxd();
    for (const auto& p : shown.positions) mBox.expand(openvdb::Vec3d(p[0], p[1], p[2]));
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(polyDataOf(shown));
    mapper->ScalarVisibilityOff();
    if (mStyle.clipping) mapper->SetClippingPlanes(mStyle.clipping);
    mActor = vtkSmartPointer<vtkActor>::New();
    mActor->SetMapper(mapper);
    vtkProperty* look = mActor->GetProperty();
    look->SetColor(mStyle.red, mStyle.green, mStyle.blue);
    look->SetOpacity(mStyle.opacity);
    look->SetSpecular(0.0);
    look->SetBackfaceCulling(mStyle.opacity < 1.0);
    mActor->SetPickable(false);
    mActor->SetVisibility(mShown);
    mRenderer->AddActor(mActor);
    setPlacement(mPlacement);
}

void ShapeDisplay::setPlacement(const openvdb::Mat4d& placement)
{
    mPlacement = placement;
    if (!mActor) return;
    vtkNew<vtkMatrix4x4> matrix;
    setPlacementMatrix(*matrix, placement);
    mActor->SetUserMatrix(matrix);
}

openvdb::BBoxd ShapeDisplay::worldBox() const { return mActor ? placedBox(mBox, mPlacement) : openvdb::BBoxd(); }

void ShapeDisplay::setColour(double red, double green, double blue)
{
    mStyle.red = red;
    mStyle.green = green;
    mStyle.blue = blue;
    if (mActor) mActor->GetProperty()->SetColor(red, green, blue);
}

void ShapeDisplay::setShown(bool shown)
{
    mShown = shown;
    if (mActor) mActor->SetVisibility(shown);
}

}  // namespace sculpt::ui
