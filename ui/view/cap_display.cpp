#include "ui/view/cap_display.h"

#include "ui/view/block_polydata.h"
#include "ui/view/placement_matrix.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace sculpt::ui {

namespace {

/// The cap's shade of a piece's colour: the cut reads as the inside of the clay.
constexpr double kCapShade = 0.75;

/// `plane` (world) in a piece's own world: its placement undone.
SectionPlane inFieldWorld(const SectionPlane& plane, const openvdb::Mat4d& placement)
{
    const openvdb::Mat4d inverse = placement.inverse();
    const openvdb::Vec3d axis = std::abs(plane.normal.x()) < 0.9 ? openvdb::Vec3d(1, 0, 0) : openvdb::Vec3d(0, 1, 0);
    const openvdb::Vec3d t1 = plane.normal.cross(axis).unit(), t2 = plane.normal.cross(t1);
    // Placements never mirror (placementProblem), so the turned tangents keep the normal's side.
    const openvdb::Vec3d n = inverse.transform3x3(t2).cross(inverse.transform3x3(t1)).unit();
    return {inverse.transform(plane.origin), n.dot(inverse.transform3x3(plane.normal)) >= 0.0 ? n : -n};
}

double worldArea(const TriangleMesh& mesh, const openvdb::Mat4d& placement)
{
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        openvdb::Vec3d p[3];
        for (int k = 0; k < 3; ++k) p[k] = placement.transform(openvdb::Vec3d(mesh.positions[t[k]].data()));
        area += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length();
    }
    return area;
}

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

void CapDisplay::sync(const std::vector<CappedPiece>& pieces, const std::optional<SectionPlane>& plane,
                      std::uint64_t planeRevision)
{
    while (mCaps.size() > pieces.size()) {
        if (mCaps.back().actor) mRenderer->RemoveActor(mCaps.back().actor);
        mCaps.pop_back();
    }
    mCaps.resize(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        Cap& cap = mCaps[i];
        const CappedPiece& piece = pieces[i];
        const bool shown = plane && piece.look->visible;
        const bool same = cap.shown == shown && cap.fieldId == piece.field->id() && cap.version == piece.version &&
                          cap.planeRevision == planeRevision && cap.placement == piece.look->placement &&
                          cap.colour == piece.colour;
        if (same) continue;
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

void CapDisplay::remake(Cap& cap, const CappedPiece& piece, const SectionPlane& plane)
{
    const CrossSection section = crossSection(*piece.field, inFieldWorld(plane, piece.look->placement));
    cap.triangles = section.region.triangles.size();
    cap.area = worldArea(section.region, piece.look->placement);
    if (!cap.actor) {
        cap.actor = vtkSmartPointer<vtkActor>::New();
        cap.actor->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
        cap.actor->SetUserMatrix(vtkSmartPointer<vtkMatrix4x4>::New());
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
    setPlacementMatrix(*cap.actor->GetUserMatrix(), piece.look->placement);
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
