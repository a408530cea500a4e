// SPDX-License-Identifier: Apache-2.0
#include "core/io/mesh_import.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/base/union_find.h"
#include "core/field/voxel_size.h"
#include "core/io/mesh_frame.h"
#include "core/io/obj_file.h"
#include "core/io/off_file.h"
#include "core/io/ply_file.h"
#include "core/io/stl_file.h"
#include "core/mesh/polygon_soup.h"

#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace sculpt {

namespace fs = std::filesystem;

bool isMeshPath(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".off";
}

TriangleMesh readMesh(const fs::path& path)
{
    if (!fs::is_regular_file(path)) throw InputError(path.string() + ": no such file");
    const std::string ext = lowerExtension(path);
    TriangleMesh mesh = [&] {
        if (ext == ".off") return readOff(path);
        if (ext == ".obj") return readObj(path);
        if (ext == ".ply") return readPly(path);
        if (ext == ".stl") return readStl(path);
        throw InputError(path.string() + ": unknown mesh format '" + ext + "' (expected .obj, .ply, .stl or .off)");
    }();
    if (declaredMeshFrame(path) == MeshFrame::Ras) mesh = inOtherFrame(std::move(mesh));  // documents are LPS
    joinCoincidentVertices(mesh);
    if (mesh.triangles.empty()) throw InputError(path.string() + ": no triangles in the mesh");
    for (const auto& p : mesh.positions) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            throw InputError(path.string() + ": a vertex has non-finite coordinates");
        }
    }
    return mesh;
}

MeshImportReport inspectMesh(const TriangleMesh& mesh)
{
    // Each edge's triangles; corners (3 per triangle) around a vertex joined across shared
    // edges give the vertex's fans: a vertex where two cones touch counts twice, as the surface
    // sees it.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.triangles[t][size_t(e)], b = mesh.triangles[t][size_t((e + 1) % 3)];
            edges[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    }
    const auto corner = [&](std::uint32_t t, std::uint32_t v) {
        const auto& tri = mesh.triangles[t];
        return 3 * t + (tri[0] == v ? 0u : tri[1] == v ? 1u : 2u);
    };
    UnionFind fans(3 * mesh.triangles.size());
    MeshImportReport report;
    report.triangles = mesh.triangles.size();
    for (const auto& [edge, triangles] : edges) {
        if (triangles.size() == 1) ++report.boundaryEdges;
        if (triangles.size() > 2) ++report.nonManifoldEdges;
        for (std::size_t k = 1; k < triangles.size(); ++k) {
            for (std::uint32_t v : {edge.first, edge.second})
                fans.join(corner(triangles[0], v), corner(triangles[k], v));
        }
    }
    report.eulerCharacteristic = (long long)fans.count() - (long long)edges.size() + (long long)mesh.triangles.size();
    return report;
}

double voxelSizeFor(const TriangleMesh& mesh, double voxelsAcross)
{
    openvdb::BBoxd box;
    for (const auto& p : mesh.positions) box.expand(openvdb::Vec3d(p[0], p[1], p[2]));
    const double longest = box.extents()[box.maxExtent()];
    return longest > 0.0 ? longest / voxelsAcross : 1.0;
}

namespace {

/// OpenVDB's interrupter asking our Progress: MeshToVolume checks it between its passes and
/// inside its parallel loops (from several threads: hence the atomics).
struct ProgressInterrupter : openvdb::util::NullInterrupter {
    explicit ProgressInterrupter(const Progress& p) : progress(p) {}
    bool wasInterrupted(int percent = -1) override
    {
        if (percent >= 0) fraction = percent / 100.0;
        if (!stopped && progress && !progress(fraction)) stopped = true;
        return stopped;
    }
    const Progress& progress;
    std::atomic<double> fraction{0.0};
    std::atomic<bool> stopped{false};
};

}  // namespace

FieldImage meshToField(const TriangleMesh& mesh, double h, const Progress& progress)
{
    if (!(h > 0.0) || !std::isfinite(h))
        throw InputError("voxel size must be a positive number (got " + formatNumber(h) + ")");
    double area = 0.0;
    std::vector<openvdb::Vec3s> points(mesh.positions.size());
    for (size_t i = 0; i < points.size(); ++i)
        points[i] = openvdb::Vec3s(mesh.positions[i][0], mesh.positions[i][1], mesh.positions[i][2]);
    std::vector<openvdb::Vec3I> triangles(mesh.triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        triangles[i] = openvdb::Vec3I(t[0], t[1], t[2]);
        const openvdb::Vec3d a(points[t[0]]), b(points[t[1]]), c(points[t[2]]);  // float would overflow
        area += 0.5 * (b - a).cross(c - a).length();
    }
    openvdb::BBoxd bounds;
    for (const openvdb::Vec3s& p : points) bounds.expand(openvdb::Vec3d(p));
    requireWithinModelExtent(bounds, h, "the mesh");
    const double halfWidth = FieldImage::kDefaultHalfWidthVoxels;
    // The band holds about area / h^2 x (2 half width) voxels at ~5 bytes each, leaves included.
    requireMemory(area / (h * h) * 2.0 * halfWidth * 8.0, "the mesh at voxel size " + formatNumber(h));
    auto xform = voxelTransform(h);
    std::vector<openvdb::Vec4I> quads;
    ProgressInterrupter interrupter(progress);
    auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(interrupter, *xform, points, triangles, quads,
                                                                   float(halfWidth));
    if (interrupter.stopped) throw Cancelled();
    if (grid->activeVoxelCount() == 0)
        throw InputError("the mesh produced no surface at voxel size " + formatNumber(h));
    return FieldImage(grid);
}

}  // namespace sculpt
