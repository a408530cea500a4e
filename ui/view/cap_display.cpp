// SPDX-License-Identifier: Apache-2.0
#include "ui/view/cap_display.h"

#include "core/mesh/incremental_mesher.h"
#include "ui/view/block_polydata.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

namespace {

/// The cap's shade of a piece's colour: the cut reads as the inside of the clay.
constexpr double kCapShade = 0.75;

}  // namespace

struct CapDisplay::Cap {
    std::uint64_t fieldId = 0, version = 0, planeRevision = 0;
    openvdb::Mat4d placement;
    openvdb::Vec3f colour;
    bool shown = false;
    vtkSmartPointer<vtkActor> actor;
    double area = 0.0;
    std::size_t triangles = 0;
};

CapDisplay::CapDisplay(vtkRenderer* renderer) : mRenderer(renderer) {}

CapDisplay::~CapDisplay()
{
    for (Cap& cap : mCaps)
        if (cap.actor) mRenderer->RemoveActor(cap.actor);
}

void CapDisplay::sync(const std::vector<FieldPiece>& pieces, const std::optional<SectionPlane>& plane,
                      std::uint64_t planeRevision)
{
    while (mCaps.size() > pieces.size()) {
        if (mCaps.back().actor) mRenderer->RemoveActor(mCaps.back().actor);
        mCaps.pop_back();
    }
    mCaps.resize(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        Cap& cap = mCaps[i];
        const FieldPiece& piece = pieces[i];
        const bool shown = plane && piece.look->visible;
        const bool same = cap.shown == shown && cap.fieldId == piece.field->id() &&
                          cap.planeRevision == planeRevision && cap.placement == piece.look->placement &&
                          cap.colour == piece.colour;
        // An edit away from the plane (most strokes) leaves the cap as it is: checked on the blocks
        // it re-meshed, so a stroke frame does not pay for the whole cap.
        if (same && (cap.version == piece.version || !shown || !changedNear(piece, cap.version, *plane))) {
            cap.version = piece.version;
            continue;
        }
        cap.shown = shown;
        cap.fieldId = piece.field->id();
        cap.version = piece.version;
        cap.planeRevision = planeRevision;
        cap.placement = piece.look->placement;
        cap.colour = piece.colour;
        if (shown) remake(cap, piece, *plane);
        if (cap.actor) cap.actor->SetVisibility(shown && cap.triangles > 0);
        if (!shown) cap.area = 0.0, cap.triangles = 0;
    }
}

bool CapDisplay::changedNear(const FieldPiece& piece, std::uint64_t version, const SectionPlane& plane)
{
    const IncrementalMesher::Changes changes = piece.mesher->changesSince(version);
    const openvdb::math::Transform& xform = piece.field->grid().transform();
    const int block = piece.mesher->blockVoxels();
    constexpr int kMargin = 2;  // voxels: a cap sample interpolates its neighbours
    for (const auto* origins : {&changes.updated, &changes.removed})
        for (const openvdb::Coord& origin : *origins) {
            bool below = false, above = false;
            for (int c = 0; c < 8; ++c) {
                const openvdb::Coord corner =
                    origin.offsetBy((c & 1) ? block + kMargin : -kMargin, (c & 2) ? block + kMargin : -kMargin,
                                    (c & 4) ? block + kMargin : -kMargin);
                const openvdb::Vec3d world = piece.look->placement.transform(xform.indexToWorld(corner));
                const double side = (world - plane.origin).dot(plane.normal);
                below = below || side <= 0.0;
                above = above || side >= 0.0;
            }
            if (below && above) return true;
        }
    return false;
}

void CapDisplay::remake(Cap& cap, const FieldPiece& piece, const SectionPlane& plane)
{
    ++mRemakes;
    const CrossSection section = placedCrossSection(*piece.field, piece.look->placement, plane);
    cap.triangles = section.region.triangles.size();
    cap.area = section.area;
    if (!cap.actor) {
        cap.actor = vtkSmartPointer<vtkActor>::New();
        cap.actor->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
        cap.actor->SetPickable(false);
        vtkProperty* look = cap.actor->GetProperty();
        look->SetAmbient(0.45);
        look->SetDiffuse(0.55);
        look->SetSpecular(0.0);
        mRenderer->AddActor(cap.actor);
    }
    BlockMesh mesh;
    mesh.positions.assign(section.region.positions.begin(), section.region.positions.end());
    mesh.normals.assign(section.region.normals.begin(), section.region.normals.end());
    mesh.triangles.assign(section.region.triangles.begin(), section.region.triangles.end());
    vtkPolyDataMapper::SafeDownCast(cap.actor->GetMapper())->SetInputData(polyDataOf(mesh));
    cap.actor->GetProperty()->SetColor(kCapShade * piece.colour[0], kCapShade * piece.colour[1],
                                       kCapShade * piece.colour[2]);
}

double CapDisplay::area() const
{
    double area = 0.0;
    for (const Cap& cap : mCaps) area += cap.area;
    return area;
}

std::size_t CapDisplay::triangleCount() const
{
    std::size_t triangles = 0;
    for (const Cap& cap : mCaps) triangles += cap.triangles;
    return triangles;
}

}  // namespace sculpt::ui
