// SPDX-License-Identifier: Apache-2.0
#include "core/brushes/brush.h"

#include "core/base/enum_names.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/brushes/brush_tools.h"
#include "core/masks/mask_paint.h"

#include <cmath>

namespace sculpt {

namespace {

constexpr EnumNames<BrushTool, kBrushToolCount> kToolNames{{{BrushTool::Add, "add"},
                                                            {BrushTool::Carve, "carve"},
                                                            {BrushTool::Inflate, "inflate"},
                                                            {BrushTool::Deflate, "deflate"},
                                                            {BrushTool::Smooth, "smooth"},
                                                            {BrushTool::Flatten, "flatten"},
                                                            {BrushTool::Grab, "grab"},
                                                            {BrushTool::Pinch, "pinch"},
                                                            {BrushTool::Follow, "follow"},
                                                            {BrushTool::Primitive, "primitive"},
                                                            {BrushTool::Mask, "mask"},
                                                            {BrushTool::Unmask, "unmask"}}};

}  // namespace

BrushTool brushToolFromName(const std::string& name) { return enumFromName(kToolNames, name, "tool"); }

const char* brushToolName(BrushTool tool) { return enumName(kToolNames, tool); }

void BrushSettings::validate() const
{
    if (!(radiusWorld > 0.0) || !std::isfinite(radiusWorld)) {
        throw InputError("field 'radius' must be a positive number (got " + formatNumber(radiusWorld) + ")");
    }
    if (!(strength > 0.0 && strength <= 1.0)) {
        throw InputError("field 'strength' must be in (0, 1] (got " + formatNumber(strength) + ")");
    }
    if (tool == BrushTool::Primitive && !primitive) throw InputError("the primitive tool needs field 'primitives'");
    if (tool == BrushTool::Follow && !target) throw InputError("the follow tool needs a target shape (field 'target')");
}

DirtyRegion applyStamp(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    brush.validate();
    if (!std::isfinite(stamp.centreWorld.lengthSqr()) || !std::isfinite(stamp.previousWorld.lengthSqr())) {
        throw InputError("stamp position is not finite");
    }
    if (!(stamp.pressure > 0.0 && stamp.pressure <= 1.0)) {
        throw InputError("field 'pressure' must be in (0, 1] (got " + formatNumber(stamp.pressure) + ")");
    }
    switch (brush.tool) {
    case BrushTool::Add: return sweepBall(field, brush, stamp, CsgMode::Add, journal);
    case BrushTool::Carve: return sweepBall(field, brush, stamp, CsgMode::Carve, journal);
    case BrushTool::Inflate: return inflate(field, brush, stamp, +1.0, journal);
    case BrushTool::Deflate: return inflate(field, brush, stamp, -1.0, journal);
    case BrushTool::Smooth: return smoothUnder(field, brush, stamp, journal);
    case BrushTool::Flatten: return flatten(field, brush, stamp, journal);
    case BrushTool::Grab: return grab(field, brush, stamp, journal);
    case BrushTool::Pinch: return pinch(field, brush, stamp, journal);
    case BrushTool::Follow: return follow(field, brush, stamp, journal);
    case BrushTool::Primitive: return stampPrimitives(field, *brush.primitive, stamp, journal);
    case BrushTool::Mask:
    case BrushTool::Unmask: {
        const double amount = brush.strength * stamp.pressure * (brush.tool == BrushTool::Mask ? 1.0 : -1.0);
        return paintMask(field, {stamp.centreWorld, brush.radiusWorld, brush.falloff}, amount, journal);
    }
    }
    return {};
}

}  // namespace sculpt
