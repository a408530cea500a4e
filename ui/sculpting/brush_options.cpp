// SPDX-License-Identifier: Apache-2.0
#include "ui/sculpting/brush_options.h"

#include "core/field/csg_combine.h"
#include "core/primitives/scene_file.h"
#include "ui/input/input_event.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

void BrushOptions::report(nlohmann::json& out) const
{
    out["target"] = target.path.string();
    out["radius"] = radius;
    out["tool"] = brushToolName(tool);
}

BrushTool effectiveTool(BrushTool tool, int mods)
{
    if (mods & kShift) return BrushTool::Smooth;
    if (!(mods & kControl)) return tool;
    switch (tool) {
    case BrushTool::Add: return BrushTool::Carve;
    case BrushTool::Carve: return BrushTool::Add;
    case BrushTool::Inflate: return BrushTool::Deflate;
    case BrushTool::Deflate: return BrushTool::Inflate;
    case BrushTool::Mask: return BrushTool::Unmask;
    case BrushTool::Unmask: return BrushTool::Mask;
    default: return tool;
    }
}

std::string primitiveScene(const BrushOptions& options, int mods)
{
    // A soft object of radius R crosses iso 0.5 near R / 2: twice the brush gives a blob its size.
    const nlohmann::json scene = {{"iso", 0.5},
                                  {"operation", (mods & kControl) ? "difference" : "union"},
                                  {"primitives",
                                   {{{"kernel", "soft-object"},
                                     {"radius", 2.0 * options.radius},
                                     {"strength", 1.0},
                                     {"skeleton", {{"type", "point"}, {"position", {0.0, 0.0, 0.0}}}}}}}};
    return scene.dump();
}

StrokeSources strokeSources(const BrushOptions& options, int mods)
{
    StrokeSources sources;
    const BrushTool tool = effectiveTool(options.tool, mods);
    if (tool == BrushTool::Primitive) sources.primitivesScene = primitiveScene(options, mods);
    if (tool == BrushTool::Follow) sources.targetPath = std::filesystem::absolute(options.target.path).string();
    return sources;
}

Stroke strokeSettings(const BrushOptions& options, int mods)
{
    Stroke stroke;
    stroke.brush.tool = effectiveTool(options.tool, mods);
    stroke.brush.radiusWorld = options.radius;
    stroke.brush.strength = options.strength;
    stroke.brush.falloff = options.falloff;
    stroke.brush.keepVolume = options.keepVolume && stroke.brush.tool == BrushTool::Smooth;
    stroke.spacing = options.spacing;
    stroke.symmetry = options.symmetry;
    if (stroke.brush.tool == BrushTool::Follow) stroke.brush.target = options.target.shape;
    if (stroke.brush.tool == BrushTool::Primitive) {
        const Scene scene = parseScene(primitiveScene(options, mods), "primitive stamp");
        stroke.brush.primitive =
            std::make_shared<const PrimitiveStamp>(PrimitiveStamp{scene.primitives, scene.operation});
    }
    return stroke;
}

}  // namespace sculpt::ui
