// SPDX-License-Identifier: Apache-2.0
#include "core/masks/mask_edit.h"

#include "core/field/central_difference.h"
#include "core/field/leaf_journal.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;

}  // namespace

MaskSite::MaskSite(const FieldImage& field)
    : mTransform(field.grid().transform()), mSurface(field.grid().getConstAccessor())
{
    if (field.mask()) mMask.emplace(field.mask()->getConstAccessor());
}

openvdb::Vec3d MaskSite::footWorld(const openvdb::Coord& ijk) const
{
    return closestSurfacePoint(mTransform.indexToWorld(ijk), mSurface.getValue(ijk),
                               centralDifferenceAt(mSurface, ijk));
}

std::vector<openvdb::Coord> maskDomain(const FieldImage& field)
{
    std::vector<openvdb::Coord> origins;
    for (auto leaf = field.grid().tree().cbeginLeaf(); leaf; ++leaf) origins.push_back(leaf->origin());
    return origins;
}

DirtyRegion rewriteMask(FieldImage& field, const std::vector<openvdb::Coord>& leafOrigins, LeafJournal* journal,
                        const MaskRule& rule)
{
    std::vector<openvdb::Coord> origins;
    for (const openvdb::Coord& origin : leafOrigins)
        if (field.grid().tree().probeConstLeaf(origin)) origins.push_back(origin);
    std::vector<std::array<float, LeafT::SIZE>> values(origins.size());
    std::vector<char> changed(origins.size(), 0), empty(origins.size(), 1);
    openvdb::FloatGrid& mask = field.mutableMask();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, origins.size()), [&](const auto& range) {
        const MaskSite site(field);
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            for (auto ijk = openvdb::CoordBBox::createCube(origins[i], LeafT::DIM).begin(); ijk; ++ijk) {
                const float now = float(std::clamp(rule(*ijk, site), 0.0, 1.0));
                values[i][LeafT::coordToOffset(*ijk)] = now;
                changed[i] |= now != float(site.mask(*ijk));
                empty[i] &= now == 0.0f;
            }
            // A leaf left all zero goes: the mask keeps leaves only where something is masked.
            changed[i] |= empty[i] && mask.tree().probeConstLeaf(origins[i]);
        }
    });
    // Every leaf is saved before any is written (see LocalPatch::commit).
    for (std::size_t i = 0; i < origins.size(); ++i)
        if (changed[i] && journal) journal->saveMask(mask.tree(), origins[i]);
    auto acc = mask.getAccessor();
    DirtyRegion touched;
    for (std::size_t i = 0; i < origins.size(); ++i) {
        if (!changed[i]) continue;
        touched.addVoxel(origins[i]);
        if (empty[i]) {
            acc.addTile(1, origins[i], 0.0f, false);
            continue;
        }
        LeafT* leaf = acc.touchLeaf(origins[i]);
        for (openvdb::Index k = 0; k < LeafT::SIZE; ++k) {
            if (values[i][k] > 0.0f) {
                leaf->setValueOn(k, values[i][k]);
            } else {
                leaf->setValueOff(k, 0.0f);
            }
        }
    }
    field.markDirty(touched);
    return touched;
}

}  // namespace sculpt
