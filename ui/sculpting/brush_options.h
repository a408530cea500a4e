// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file brush_options.h
/// @brief The brush as the tool palette sets it, and what the held modifiers make of it.

#include "core/brushes/brush.h"
#include "sculpt/session/stroke_script.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <memory>

namespace sculpt::ui {

/// The shape the follow brush goes towards (and a morph's default target), as loaded from a file.
struct FollowTarget {
    std::filesystem::path path;
    std::shared_ptr<const FieldImage> shape;  ///< null: none loaded
};

struct BrushOptions {
    BrushTool tool = BrushTool::Add;
    double radius = 5.0;  ///< world units
    double strength = 0.5;
    Falloff falloff = Falloff::Smooth;
    double spacing = 0.25;  ///< of the radius
    Symmetry symmetry;
    bool keepVolume = false;        ///< smooth
    bool pressureFromSpeed = true;  ///< a mouse has no pressure: faster strokes press lighter
    FollowTarget target;            ///< follow
    bool stopAtPieces = false;      ///< strokes keep out of the document's other pieces

    /// The tool, radius and target in the window's report.
    void report(nlohmann::json& out) const;
};

/// The tool a stroke uses: Shift smooths while held; Ctrl inverts add/carve, inflate/deflate
/// and a primitive's union/difference (as in Blender's sculpt mode).
BrushTool effectiveTool(BrushTool tool, int mods);

/// The stroke settings (no samples) for these options under these modifiers.
Stroke strokeSettings(const BrushOptions& options, int mods);

/// What a stroke script records of the stroke's extra inputs: the primitive's scene, the
/// follow target's file.
StrokeSources strokeSources(const BrushOptions& options, int mods);

/// The scene JSON of the primitive stamp: one soft blob about the brush's size; a difference
/// when Ctrl is held.
std::string primitiveScene(const BrushOptions& options, int mods);

}  // namespace sculpt::ui
