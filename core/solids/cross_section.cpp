// SPDX-License-Identifier: Apache-2.0
#include "core/solids/cross_section.h"

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt {

namespace {

/// The plane's lattice: (a, b) steps of h along u and v from `corner`, u x v = the normal.
struct PlaneLattice {
    openvdb::Vec3d corner, u, v;
    double h = 1.0;
    int nu = 0, nv = 0;  // samples along u and v
    openvdb::Vec3d at(double a, double b) const { return corner + u * (a * h) + v * (b * h); }
};

/// u and v: unit, orthogonal to each other and to `normal`, u x v = normal.
std::pair<openvdb::Vec3d, openvdb::Vec3d> planeAxes(const openvdb::Vec3d& normal)
{
    const int least = std::abs(normal.x()) < std::abs(normal.y())
                          ? (std::abs(normal.x()) < std::abs(normal.z()) ? 0 : 2)
                          : (std::abs(normal.y()) < std::abs(normal.z()) ? 1 : 2);
    openvdb::Vec3d axis(0.0);
    axis[least] = 1.0;
    const openvdb::Vec3d u = (axis - normal * normal.dot(axis)).unit();
    return {u, normal.cross(u)};
}

/// The lattice covering the plane's part of the field's leaf box; nothing (nu = 0) if the plane
/// misses the box.
PlaneLattice latticeOver(const FieldImage& field, const SectionPlane& plane)
{
    PlaneLattice lattice;
    openvdb::CoordBBox leaves;
    field.grid().tree().evalLeafBoundingBox(leaves);
    if (leaves.empty()) return lattice;
    const auto [u, v] = planeAxes(plane.normal);
    double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    double hi[2] = {-lo[0], -lo[1]}, side[2] = {lo[0], -lo[0]};
    for (int c = 0; c < 8; ++c) {
        const openvdb::Vec3d corner((c & 1) ? leaves.max().x() + 1 : leaves.min().x(),
                                    (c & 2) ? leaves.max().y() + 1 : leaves.min().y(),
                                    (c & 4) ? leaves.max().z() + 1 : leaves.min().z());
        const openvdb::Vec3d d = field.grid().transform().indexToWorld(corner - openvdb::Vec3d(0.5)) - plane.origin;
        const double ab[2] = {d.dot(u), d.dot(v)};
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], ab[k]), hi[k] = std::max(hi[k], ab[k]);
        side[0] = std::min(side[0], d.dot(plane.normal));
        side[1] = std::max(side[1], d.dot(plane.normal));
    }
    if (side[0] > 0.0 || side[1] < 0.0) return lattice;
    lattice.h = field.voxelSize();
    lattice.u = u;
    lattice.v = v;
    lattice.corner = plane.origin + u * (std::floor(lo[0] / lattice.h) * lattice.h) +
                     v * (std::floor(lo[1] / lattice.h) * lattice.h);
    lattice.nu = int(std::ceil((hi[0] - std::floor(lo[0] / lattice.h) * lattice.h) / lattice.h)) + 1;
    lattice.nv = int(std::ceil((hi[1] - std::floor(lo[1] / lattice.h) * lattice.h) / lattice.h)) + 1;
    return lattice;
}

/// phi at every lattice point (row b after row b - 1), interpolated trilinearly in the field.
std::vector<float> sampleField(const FieldImage& field, const PlaneLattice& lattice)
{
    std::vector<float> phi(std::size_t(lattice.nu) * std::size_t(lattice.nv));
    tbb::parallel_for(tbb::blocked_range<int>(0, lattice.nv), [&](const tbb::blocked_range<int>& rows) {
        const auto accessor = field.grid().getConstAccessor();
        const openvdb::math::Transform& xform = field.grid().transform();
        for (int b = rows.begin(); b < rows.end(); ++b)
            for (int a = 0; a < lattice.nu; ++a) {
                float value = 0.0f;
                openvdb::tools::BoxSampler::sample(accessor, xform.worldToIndex(lattice.at(a, b)), value);
                phi[std::size_t(b) * std::size_t(lattice.nu) + std::size_t(a)] = value;
            }
    });
    return phi;
}

/// A lattice point (a, b) with its phi.
struct Corner {
    double a, b, phi;
};

/// Builds the section: polygons of the plane's (a, b) coordinates into its mesh and area.
class SectionBuilder {
public:
    SectionBuilder(const PlaneLattice& lattice, const openvdb::Vec3d& normal, bool region)
        : mLattice(lattice), mRegion(region)
    {
        mNormal = {float(normal.x()), float(normal.y()), float(normal.z())};
    }

    /// The part of triangle (p, q, r) where phi < 0, and its outline.
    void clipTriangle(const Corner& p, const Corner& q, const Corner& r)
    {
        const Corner in[3] = {p, q, r};
        Corner kept[4];
        int count = 0;
        Corner crossings[3];
        int crossed = 0;
        for (int k = 0; k < 3; ++k) {
            const Corner& s = in[k];
            const Corner& e = in[(k + 1) % 3];
            if (s.phi < 0.0) kept[count++] = s;
            if ((s.phi < 0.0) != (e.phi < 0.0)) {
                const double t = s.phi / (s.phi - e.phi);
                const Corner x{s.a + t * (e.a - s.a), s.b + t * (e.b - s.b), 0.0};
                kept[count++] = x;
                crossings[crossed++] = x;
            }
        }
        for (int k = 1; mRegion && k + 1 < count; ++k) addTriangle(kept[0], kept[k], kept[k + 1]);
        if (crossed == 2)
            mSection.outline.push_back(
                {mLattice.at(crossings[0].a, crossings[0].b), mLattice.at(crossings[1].a, crossings[1].b)});
    }

    CrossSection take() { return std::move(mSection); }

private:
    void addTriangle(const Corner& p, const Corner& q, const Corner& r)
    {
        const double h = mLattice.h;
        mSection.area += 0.5 * h * h * ((q.a - p.a) * (r.b - p.b) - (r.a - p.a) * (q.b - p.b));
        TriangleMesh& mesh = mSection.region;
        const auto first = std::uint32_t(mesh.positions.size());
        for (const Corner* c : {&p, &q, &r}) {
            const openvdb::Vec3d w = mLattice.at(c->a, c->b);
            mesh.positions.push_back({float(w.x()), float(w.y()), float(w.z())});
            mesh.normals.push_back(mNormal);
        }
        mesh.triangles.push_back({first, first + 1, first + 2});
    }

    const PlaneLattice& mLattice;
    bool mRegion;
    std::array<float, 3> mNormal{};
    CrossSection mSection;
};

}  // namespace

CrossSection crossSection(const FieldImage& field, const SectionPlane& plane, SectionParts parts)
{
    const PlaneLattice lattice = latticeOver(field, plane);
    if (lattice.nu < 2 || lattice.nv < 2) return {};
    const std::vector<float> phi = sampleField(field, lattice);
    const auto at = [&](int a, int b) {
        return Corner{double(a), double(b), phi[std::size_t(b) * std::size_t(lattice.nu) + std::size_t(a)]};
    };
    SectionBuilder builder(lattice, plane.normal, parts == SectionParts::RegionAndOutline);
    for (int b = 0; b + 1 < lattice.nv; ++b)
        for (int a = 0; a + 1 < lattice.nu; ++a) {
            const Corner c00 = at(a, b), c10 = at(a + 1, b), c11 = at(a + 1, b + 1), c01 = at(a, b + 1);
            const int inside = (c00.phi < 0.0) + (c10.phi < 0.0) + (c11.phi < 0.0) + (c01.phi < 0.0);
            if (inside == 0 || (inside == 4 && parts == SectionParts::Outline)) continue;
            builder.clipTriangle(c00, c10, c11);
            builder.clipTriangle(c00, c11, c01);
        }
    return builder.take();
}

CrossSection placedCrossSection(const FieldImage& field, const openvdb::Mat4d& placement, const SectionPlane& plane,
                                SectionParts parts)
{
    const openvdb::Mat4d inverse = placement.inverse();
    const openvdb::Vec3d axis = std::abs(plane.normal.x()) < 0.9 ? openvdb::Vec3d(1, 0, 0) : openvdb::Vec3d(0, 1, 0);
    const openvdb::Vec3d t1 = plane.normal.cross(axis).unit(), t2 = plane.normal.cross(t1);
    // The plane's tangents turned into the field's world span its plane there; placements never
    // mirror (placementProblem), so their cross product keeps the normal's side.
    const openvdb::Vec3d n = inverse.transform3x3(t2).cross(inverse.transform3x3(t1)).unit();
    CrossSection section = crossSection(field, {inverse.transform(plane.origin), n}, parts);
    const std::array<float, 3> normal{float(plane.normal.x()), float(plane.normal.y()), float(plane.normal.z())};
    TriangleMesh& region = section.region;
    for (auto& p : region.positions) {
        const openvdb::Vec3d w = placement.transform(openvdb::Vec3d(p[0], p[1], p[2]));
        p = {float(w.x()), float(w.y()), float(w.z())};
    }
    for (auto& normalOf : region.normals) normalOf = normal;
    for (auto& segment : section.outline)
        for (auto& end : segment) end = placement.transform(end);
    section.area = 0.0;
    for (const auto& t : region.triangles) {
        const openvdb::Vec3d a(region.positions[t[0]].data()), b(region.positions[t[1]].data()),
            c(region.positions[t[2]].data());
        section.area += 0.5 * (b - a).cross(c - a).length();
    }
    return section;
}

}  // namespace sculpt
