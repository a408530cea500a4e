// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_picker.h
/// @brief What the mouse points at: the ray cast against the level set itself (firstSurfaceCrossing),
///        giving the exact hit and normal with no mesh locator to rebuild. Only the model's leaf
///        box, found again when the field changed since the last pick, bounds the search.
///
/// During a stroke the picker sees the surface as it was when the stroke began (as Blender's
/// strokes do without "accumulate"): otherwise each sample would land on the clay the previous
/// stamps just added, and an add stroke would climb towards the eye. That surface is the field
/// read through the stroke's own journal (PreEditField), so a stroke copies nothing.

#include "core/field/field_image.h"
#include "core/field/leaf_journal.h"
#include "ui/view/viewport.h"

#include <optional>

namespace sculpt::ui {

struct SurfaceHit {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};  ///< unit, outwards
};

class SurfacePicker {
public:
    /// The first crossing of `ray` with the zero level set of `field`, as it was before the edits
    /// in `editedSince` (a live stroke's journal; null: as it is). `fieldVersion` must change
    /// whenever the field does (the mesher's version does).
    std::optional<SurfaceHit> pick(const FieldImage& field, std::uint64_t fieldVersion, const Ray& ray,
                                   const LeafJournal* editedSince = nullptr);
    /// Forget the model's box (a new document).
    void reset();
    /// Keeps the model's box as it is now (`fieldVersion`) until thaw(): a stroke only adds to it.
    void freeze(const FieldImage& field, std::uint64_t fieldVersion);
    void thaw() { mFrozen = false; }

private:
    void refreshBox(const FieldImage& field, std::uint64_t fieldVersion);

    openvdb::CoordBBox mBox;  // the leaves' index box of the field (id, version)
    std::uint64_t mFieldId = 0, mVersion = 0;
    bool mFrozen = false;
};

}  // namespace sculpt::ui
