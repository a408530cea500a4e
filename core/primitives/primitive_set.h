// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file primitive_set.h
/// @brief Implicit primitives blended into one field (Desbrun, Tsingos & Cani 1995).
///
/// Each primitive is a skeleton with a kernel of the distance to it. The set's field is the sum
/// of its primitives' fields, unless a blending graph is given: then at a point p the
/// preponderant primitive i (largest f_i(p)) blends only with its neighbours,
///     f(p) = f_i(p) + sum over j in neighbours(i) of f_j(p),
/// so two primitives that are not neighbours meet in a crease instead of fusing (the two ends of a
/// bent chain touch without a bridge). The surface is f = iso, the inside f > iso.

#include "core/primitives/kernels.h"
#include "core/primitives/skeleton.h"

#include <string>
#include <vector>

namespace sculpt {

struct Primitive {
    std::string name;  ///< for messages; may be empty
    Skeleton skeleton;
    Kernel kernel;
    std::vector<int> neighbours;  ///< indices of primitives it blends with (graph mode)
};

class PrimitiveSet {
public:
    /// @param useGraph blend through `neighbours` (made symmetric) instead of summing all.
    /// @throws InputError naming the primitive (index and name) and field at fault: degenerate
    ///         skeleton, radius or strength not positive, neighbour index out of range, iso not in
    ///         (0, strength) of some primitive.
    PrimitiveSet(std::vector<Primitive> primitives, double iso, bool useGraph);

    /// Field value at p: sum, or preponderant-plus-neighbours in graph mode.
    double field(const openvdb::Vec3d& p) const;
    /// Field value at p from only the listed primitives (those whose influence reaches p).
    double field(const openvdb::Vec3d& p, const std::vector<int>& nearby) const;

    double iso() const { return mIso; }
    /// Blends through the neighbours graph (else sums every primitive).
    bool usesGraph() const { return mUseGraph; }
    const std::vector<Primitive>& primitives() const { return mPrimitives; }
    /// World box of primitive i's influence: its skeleton grown by its radius.
    openvdb::BBoxd influence(int i) const;
    /// World box of the whole set's influence.
    openvdb::BBoxd influence() const;
    /// The same set moved by `offset` (a primitive stamp placed on the surface).
    PrimitiveSet translated(const openvdb::Vec3d& offset) const;

private:
    std::vector<Primitive> mPrimitives;
    double mIso;
    bool mUseGraph;
};

/// "primitive 3 ('head')" or "primitive 3": how messages name a primitive.
std::string describePrimitive(int index, const std::string& name);

}  // namespace sculpt
