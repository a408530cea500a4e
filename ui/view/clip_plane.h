// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file clip_plane.h
/// @brief View > Clip Plane: a plane hiding the clay on one side so its inside shows (Slicer's
///        and ITK-SNAP's cut plane), across the patient frame's x, y or z or the view direction,
///        moved along its normal by keys or the slider. CapDisplay closes the cut with the exact
///        section from the field, and picking stops at it, so strokes land on the cap.
///
/// Every mapper of the clay takes planes() (the model's chunks, the other pieces); when the plane
/// is off it lies far beyond everything, so turning it on or off never rebuilds a shader.

#include "core/solids/cross_section.h"

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <optional>

class vtkPlane;
class vtkPlaneCollection;

namespace sculpt::ui {

enum class ClipAxis { Off, X, Y, Z, View };
inline constexpr const char* kClipAxisNames[] = {"Off", "x (left-right)", "y (front-back)", "z (up-down)",
                                                 "View direction"};

class ClipPlane {
public:
    ClipPlane();
    ~ClipPlane();

    ClipAxis axis() const { return mAxis; }
    /// Turns the plane to `axis` (the view direction `viewDirection` for View, fixed from then),
    /// through `through` (the model's centre).
    void setAxis(ClipAxis axis, const glm::dvec3& viewDirection, const glm::dvec3& through);
    /// Its distance along the normal from the world's origin; move() shifts it.
    double offset() const { return mOffset; }
    void setOffset(double offset);
    void move(double distance) { setOffset(mOffset + distance); }
    /// Which side is hidden: by default the side the normal points to (+x, +y, +z, towards the eye).
    bool flipped() const { return mFlipped; }
    void setFlipped(bool flipped);

    /// The plane with its hidden side positive, when on.
    std::optional<SectionPlane> plane() const;
    /// Whether `world` is hidden.
    bool hides(const glm::dvec3& world) const;
    /// For the clay's mappers (vtkMapper::SetClippingPlanes).
    vtkPlaneCollection* planes() const;
    /// Changes whenever the plane does (the caps, the hover).
    std::uint64_t revision() const { return mRevision; }

private:
    void update();

    ClipAxis mAxis = ClipAxis::Off;
    glm::dvec3 mNormal{0.0, 0.0, 1.0};
    double mOffset = 0.0;
    bool mFlipped = false;
    vtkSmartPointer<vtkPlane> mPlane;
    vtkSmartPointer<vtkPlaneCollection> mPlanes;
    std::uint64_t mRevision = 0;
};

}  // namespace sculpt::ui
