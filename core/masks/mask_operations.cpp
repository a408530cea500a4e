// SPDX-License-Identifier: Apache-2.0
#include "core/masks/mask_operations.h"

#include "core/base/enum_names.h"
#include "core/base/errors.h"
#include "core/field/leaf_journal.h"
#include "core/masks/mask_edit.h"

#include <algorithm>
#include <array>

namespace sculpt {

namespace {

constexpr EnumNames<MaskOperation, 6> kNames{{{MaskOperation::Invert, "invert"},
                                              {MaskOperation::Clear, "clear"},
                                              {MaskOperation::Blur, "blur"},
                                              {MaskOperation::Sharpen, "sharpen"},
                                              {MaskOperation::Grow, "grow"},
                                              {MaskOperation::Shrink, "shrink"}}};

const std::array<openvdb::Coord, 6> kNeighbours{openvdb::Coord(1, 0, 0), openvdb::Coord(-1, 0, 0),
                                                openvdb::Coord(0, 1, 0), openvdb::Coord(0, -1, 0),
                                                openvdb::Coord(0, 0, 1), openvdb::Coord(0, 0, -1)};

/// The rule of one pass of `operation`.
MaskRule ruleOf(MaskOperation operation)
{
    switch (operation) {
    case MaskOperation::Invert: return [](const openvdb::Coord& ijk, const MaskSite& s) { return 1.0 - s.mask(ijk); };
    case MaskOperation::Sharpen:
        return [](const openvdb::Coord& ijk, const MaskSite& s) {
            const double m = s.mask(ijk);
            return m * m * (3.0 - 2.0 * m);
        };
    case MaskOperation::Blur:
        return [](const openvdb::Coord& ijk, const MaskSite& s) {
            double sum = s.mask(ijk);
            for (const openvdb::Coord& d : kNeighbours) sum += s.mask(ijk + d);
            return sum / 7.0;
        };
    case MaskOperation::Grow:
    case MaskOperation::Shrink: {
        const bool grow = operation == MaskOperation::Grow;
        return [grow](const openvdb::Coord& ijk, const MaskSite& s) {
            double m = s.mask(ijk);
            for (const openvdb::Coord& d : kNeighbours)
                m = grow ? std::max(m, s.mask(ijk + d)) : std::min(m, s.mask(ijk + d));
            return m;
        };
    }
    case MaskOperation::Clear: break;  // clearMask drops the mask whole
    }
    return {};
}

/// Drops the mask whole (the journal keeps it whole): nothing is left to read.
DirtyRegion clearMask(FieldImage& field, LeafJournal* journal)
{
    if (!field.mask()) return {};
    DirtyRegion cleared;
    for (auto leaf = field.mask()->tree().cbeginLeaf(); leaf; ++leaf) cleared.addVoxel(leaf->origin());
    if (journal) journal->saveWholeMask(field.maskPtr());
    field.setMask(nullptr);
    field.markDirty(cleared);
    return cleared;
}

}  // namespace

MaskOperation maskOperationFromName(const std::string& name) { return enumFromName(kNames, name, "mask operation"); }

const char* maskOperationName(MaskOperation operation) { return enumName(kNames, operation); }

DirtyRegion applyMaskOperation(FieldImage& field, MaskOperation operation, int times, LeafJournal* journal)
{
    if (times < 1) throw InputError("a mask operation runs at least once (got " + std::to_string(times) + ")");
    if (operation == MaskOperation::Clear) return clearMask(field, journal);
    const std::vector<openvdb::Coord> domain = maskDomain(field);
    DirtyRegion changed;
    for (int i = 0; i < times; ++i) changed.merge(rewriteMask(field, domain, journal, ruleOf(operation)));
    return changed;
}

}  // namespace sculpt
