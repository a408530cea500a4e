// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scan_lattice.h
/// @brief Where a scan's samples lie: how many along each index axis, and the affine map from a
///        sample's index (i, j, k) to the documents' world (LPS millimetres).

#include <openvdb/openvdb.h>

namespace sculpt {

struct ScanLattice {
    openvdb::Coord dims;
    openvdb::Mat4d worldFromIndex = openvdb::Mat4d::identity();  ///< row vectors, as OpenVDB

    double samples() const { return double(dims.x()) * double(dims.y()) * double(dims.z()); }
    openvdb::CoordBBox indexBox() const { return {openvdb::Coord(0), dims - openvdb::Coord(1)}; }
};

}  // namespace sculpt
