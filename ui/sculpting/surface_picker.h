#pragma once
/// @file surface_picker.h
/// @brief What the mouse points at: the ray cast against the level set itself (OpenVDB's
///        LevelSetRayIntersector), giving the exact hit and normal with no mesh locator to
///        rebuild. The intersector is remade only when the field changed since the last pick.
///
/// During a stroke the picker holds on to the surface as it was when the stroke began (as
/// Blender's strokes do without "accumulate"): otherwise each sample would land on the clay the
/// previous stamps just added, and an add stroke would climb towards the eye.

#include "core/field/field_image.h"
#include "ui/view/viewport.h"

#include <memory>
#include <optional>

namespace sculpt::ui {

struct SurfaceHit {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};  ///< unit, outwards
};

class SurfacePicker {
public:
    SurfacePicker();
    ~SurfacePicker();

    /// The first crossing of `ray` with the zero level set of `field`. `fieldVersion` must change
    /// whenever the field does (the mesher's version does).
    std::optional<SurfaceHit> pick(const FieldImage& field, std::uint64_t fieldVersion, const Ray& ray);
    /// Forget the intersector (a new document).
    void reset();
    /// Picks against a copy of the field as it is now, until thaw().
    void freeze(const FieldImage& field);
    void thaw();

private:
    struct Intersector;
    std::unique_ptr<Intersector> mIntersector;
    openvdb::FloatGrid::Ptr mFrozen;
    std::uint64_t mFieldId = 0;  // FieldImage::id of what the intersector was made from
    std::uint64_t mVersion = 0;
};

}  // namespace sculpt::ui
