// SPDX-License-Identifier: Apache-2.0
#include "ui/view/scales_display.h"

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>

#include <cmath>
#include <unordered_set>

namespace sculpt::ui {

namespace {

/// One sample per cell of `cellWorld`: the first vertex of the blocks' meshes falling in it.
vtkSmartPointer<vtkPolyData> samplesOf(const IncrementalMesher& mesher, double cellWorld)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetName("normals");
    normals->SetNumberOfComponents(3);
    std::unordered_set<std::uint64_t> taken;
    for (const auto& [origin, mesh] : mesher.blocks()) {
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const auto& p = mesh.positions[i];
            std::uint64_t key = 0;  // 21 bits of cell index per axis
            for (int a = 0; a < 3; ++a) {
                key |= (std::uint64_t(std::int64_t(std::floor(p[a] / cellWorld))) & 0x1fffffu) << (21 * a);
            }
            if (!taken.insert(key).second) continue;
            points->InsertNextPoint(p[0], p[1], p[2]);
            normals->InsertNextTuple(mesh.normals[i].data());
        }
    }
    auto samples = vtkSmartPointer<vtkPolyData>::New();
    samples->SetPoints(points);
    samples->GetPointData()->AddArray(normals);
    return samples;
}

}  // namespace

ScalesDisplay::ScalesDisplay(vtkRenderer* renderer)
    : mRenderer(renderer), mActor(vtkSmartPointer<vtkActor>::New()), mMapper(vtkSmartPointer<vtkGlyph3DMapper>::New())
{
    // A hexagon in the glyph's y-z plane: the mapper turns its x axis, the normal, to each
    // sample's normal.
    vtkNew<vtkRegularPolygonSource> hexagon;
    hexagon->SetNumberOfSides(6);
    hexagon->SetNormal(1.0, 0.0, 0.0);
    hexagon->SetRadius(1.0);
    mMapper->SetSourceConnection(hexagon->GetOutputPort());
    mMapper->SetOrientationArray("normals");
    mMapper->SetOrientationModeToDirection();
    mMapper->ScalingOn();
    mMapper->SetScaleModeToNoDataScaling();  // every scale the same size: ScaleFactor
    mActor->SetMapper(mMapper);
    mActor->GetProperty()->SetColor(0.85, 0.62, 0.48);
    mActor->GetProperty()->SetSpecular(0.2);
    mActor->SetVisibility(false);
    mRenderer->AddActor(mActor);
}

ScalesDisplay::~ScalesDisplay() { mRenderer->RemoveActor(mActor); }

void ScalesDisplay::setShown(bool shown)
{
    mShown = shown;
    mActor->SetVisibility(shown);
}

void ScalesDisplay::sync(const IncrementalMesher& mesher, double voxelSize)
{
    if (!mShown || (mesher.id() == mSourceId && mesher.version() == mVersion)) return;
    const double cell = kCellVoxels * voxelSize;
    vtkSmartPointer<vtkPolyData> samples = samplesOf(mesher, cell);
    mCount = std::size_t(samples->GetNumberOfPoints());
    mMapper->SetInputData(samples);
    mMapper->SetScaleFactor(0.6 * cell);  // hexagons of 0.6 cell: overlapping scales with gaps
    mSourceId = mesher.id();
    mVersion = mesher.version();
}

}  // namespace sculpt::ui
