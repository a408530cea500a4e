// SPDX-License-Identifier: Apache-2.0
#include "tests/support/reference_mesher.h"

#include <openvdb/tools/VolumeToMesh.h>

namespace sculpt::test {

TriangleMesh meshWithVolumeToMesh(const FieldImage& field)
{
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(field.grid(), points, triangles, quads, 0.0, 0.0);

    TriangleMesh mesh;
    mesh.positions.reserve(points.size());
    for (const auto& p : points) mesh.positions.push_back({p.x(), p.y(), p.z()});
    // volumeToMesh winds its polygons clockwise seen from outside; we store counter-clockwise.
    mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    for (const auto& t : triangles) mesh.triangles.push_back({t[0], t[2], t[1]});
    for (const auto& q : quads) {
        const float d02 = (points[q[0]] - points[q[2]]).lengthSqr();
        const float d13 = (points[q[1]] - points[q[3]]).lengthSqr();
        if (d02 <= d13) {
            mesh.triangles.push_back({q[0], q[2], q[1]});
            mesh.triangles.push_back({q[0], q[3], q[2]});
        } else {
            mesh.triangles.push_back({q[0], q[3], q[1]});
            mesh.triangles.push_back({q[1], q[3], q[2]});
        }
    }
    return mesh;
}

}  // namespace sculpt::test
