// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file hover_key.h
/// @brief What the surface under the pointer depends on: the ray through it, the field and its
///        mesh (by identity and version), and whether the pointer picks at all. The window picks
///        again only when this changes, so no edit has to remember to say the hover is stale.

#include "ui/view/viewport.h"

#include <cstdint>

namespace sculpt::ui {

struct HoverKey {
    Ray ray;
    std::uint64_t fieldId = 0, mesherId = 0, version = 0;
    std::uint64_t clip = 0;  ///< the clip plane's revision
    bool picking = false;    ///< over the view, not dragging the camera or a setting

    bool operator==(const HoverKey& o) const
    {
        return ray.origin == o.ray.origin && ray.direction == o.ray.direction && fieldId == o.fieldId &&
               mesherId == o.mesherId && version == o.version && clip == o.clip && picking == o.picking;
    }
    bool operator!=(const HoverKey& o) const { return !(*this == o); }
};

}  // namespace sculpt::ui
