// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file contact.h
/// @brief Whether two pieces overlap, looked for only where their local boxes meet
///        (Desbrun, Tsingos and Cani 1995, section 5).
///
/// A piece's local boxes are its non-empty mesher blocks: together they hold its whole surface.
/// A vertex of one piece penetrates another where the other's phi (trilinear) is negative, by
/// -phi. The vertices of a block are sampled one by one only where the block's box meets one of
/// the other's blocks. A block meeting none of them holds no part of the other's surface, so
/// the other's phi has one sign over all of it: one probe tells whether every vertex is inside
/// (a piece wholly inside another is seen) or none is. A block off the other's global box is
/// outside it and costs nothing. The answer is the one every vertex sampled would give.

#include "core/field/field_image.h"
#include "core/mesh/incremental_mesher.h"

#include <openvdb/openvdb.h>

#include <cstddef>
#include <functional>

namespace sculpt {

/// A piece as contact sees it: its field, its surface (the mesher, up to date with the field)
/// and where it is placed.
struct ContactBody {
    const FieldImage& field;
    const IncrementalMesher& mesher;
    /// World from the field's own world (row vectors, as OpenVDB: p * placement): a rigid move
    /// (or a uniform scale) that never touches a voxel.
    openvdb::Mat4d placement = openvdb::Mat4d::identity();
    /// Its surface's box in its field's world if the caller keeps it (a move: once per gesture);
    /// empty: found from the field's leaves.
    openvdb::BBoxd box = openvdb::BBoxd();
};

struct Penetration {
    std::size_t sampledVertices = 0;      ///< vertices whose depth was sampled one by one
    std::size_t penetratingVertices = 0;  ///< vertices inside the other piece
    double deepest = 0.0;                 ///< largest -phi, in the other field's own units
    bool any() const { return penetratingVertices > 0; }
};

/// The vertices of `moving` inside `other`. Cost: nothing more when their global boxes do not
/// meet; else the blocks of both, and the vertices of those of `moving` that meet `other`'s.
Penetration penetration(const ContactBody& moving, const ContactBody& other);

/// Both ways: `a`'s vertices inside `b` and `b`'s inside `a` (a sharp tip of either is seen).
Penetration overlap(const ContactBody& a, const ContactBody& b);

/// How far along a move `moving` can go without overlapping `other`: the placements of the move
/// are `along(t)` for t in [0, 1]; returns 1 if the whole move is free, else the largest t
/// found free by `bisections` halvings of [0, 1] (0 if they overlap at its start already).
double freeFraction(const ContactBody& moving, const ContactBody& other,
                    const std::function<openvdb::Mat4d(double)>& along, int bisections = 20);

}  // namespace sculpt
