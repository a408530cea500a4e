// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/written_outputs.h"
#include "core/io/mesh_file.h"
#include "core/io/vdb_file.h"
#include "core/mesh/incremental_mesher.h"
#include "core/motion/morph_verdict.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/frame_files.h"
#include "sculpt/session/morph_tracking.h"
#include "sculpt/session/shape_import.h"
#include "sculpt/session/tracked_export.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace sculpt::cli {

namespace fs = std::filesystem;

namespace {

struct MorphCommandOptions {
    std::string source, target, directory, mesh, tracked;
    MorphOptions morph;
    RunOptions run;
};

/// The verdict with the option that does what it suggests.
std::string verdict(const MorphSummary& s, double voxelSize)
{
    const char* option = s.stop == MorphStop::Stalled     ? " (--tolerance)"
                         : s.stop == MorphStop::StepLimit ? " (--max-steps)"
                                                          : "";
    return morphVerdict(s, voxelSize) + option;
}

/// Sees the field after each step; none unless tracking (a morph watched by steps resumes from
/// no kept state, so its frames take longer).
using MorphStepWatch = std::function<void(const FieldImage&)>;

void reportTracking(const MorphTracking& tracking, const std::string& directory, CommandReport& report)
{
    const TrackedSequence& sequence = tracking.sequence();
    const TrackingTally& t = tracking.tally();
    report.wrote(directory, "tracked");
    report["tracked_segments"] = sequence.segments().size();
    report.sayFormatted(
        "tracked mesh: %zu segments of constant connectivity in %s (segment_0000.ply/.pc2/.glb/.usda ...); over %zu "
        "steps %zu splits, %zu collapses, %zu inverted triangles unfolded, %zu quasi-critical points; topology "
        "events: %zu cut and closed, %zu seeded again, %zu shells vanished under the resolution; seeded again "
        "after folding over %g%% of its triangles: %zu",
        sequence.segments().size(), directory.c_str(), t.steps, t.splits, t.collapses, t.inverted, t.quasiCritical,
        t.surgeries, t.reseeds - t.folds, t.vanished, 100.0 * MeshTracker::kLostFoldedShare, t.folds);
    for (std::size_t s = 0; s < sequence.segments().size(); ++s) {
        const TrackedSegment& segment = sequence.segments()[s];
        double angle = 180.0, shortest = 1e30, longest = 0.0;
        std::size_t flagged = 0;
        for (const TrackedFrame& frame : tracking.frames())
            if (frame.segment == s) {
                angle = std::min(angle, frame.quality.smallestAngle);
                shortest = std::min(shortest, frame.quality.shortestEdge / tracking.edgeLength());
                longest = std::max(longest, frame.quality.longestEdge / tracking.edgeLength());
                flagged += frame.flagged;
            }
        report.sayFormatted(
            "  segment %04zu: frames %d to %zu, %zu vertices, %zu triangles; smallest angle %.1f degrees, "
            "edges %.2f e to %.2f e, %zu points flagged",
            s, segment.firstFrame, segment.firstFrame + segment.positions.size() - 1, segment.ids.size(),
            segment.triangles.size(), angle, shortest, longest, flagged);
    }
}

void runMorph(const MorphCommandOptions& o)
{
    if (!o.mesh.empty()) meshFormatOf("frame." + o.mesh);
    // Documents keep their voxels; a scan or mesh takes the other shape's voxel size.
    std::vector<std::string> warnings;
    const bool sourceIsDocument = fs::path(o.source).extension() == ".vdb";
    const FieldImage first = loadShape(sourceIsDocument ? o.source : o.target, std::nullopt, warnings);
    const FieldImage second = loadShape(sourceIsDocument ? o.target : o.source, first.voxelSize(), warnings);
    const FieldImage& source = sourceIsDocument ? first : second;
    const FieldImage& target = sourceIsDocument ? second : first;
    for (const std::string& warning : warnings) std::cerr << "sculpt: warning: " << warning << "\n";
    WrittenOutputs outputs;  // a morph that fails leaves no frames behind
    outputs.directory(o.directory);
    if (!o.tracked.empty()) outputs.directory(o.tracked);

    // Frames grow towards the target's size: the disk must hold the rest at the larger one's.
    const double growth = std::max(1.0, double(target.grid().activeVoxelCount()) /
                                            double(std::max<openvdb::Index64>(1, source.grid().activeVoxelCount())));
    MorphSummary summary;
    MorphTracking tracking;
    {
        ProgressBar bar("morphing");
        summary = morph(
            source, target, o.morph,
            [&](const MorphFrame& frame) {
                writeFieldImage(frame.field, outputs.file(framePath(o.directory, frame.index, "vdb")));
                if (!o.mesh.empty())
                    writeMesh(meshLevelSet(frame.field), outputs.file(framePath(o.directory, frame.index, o.mesh)));
                if (frame.index == 0) {
                    outputs.requireRoomFor(o.morph.frames - 1, growth,
                                           "the other " + std::to_string(o.morph.frames - 1) + " frames");
                }
                if (!o.tracked.empty()) tracking.frame(frame.field);
            },
            bar.callback(),
            o.tracked.empty() ? MorphStepWatch() : [&](const FieldImage& field) { tracking.step(field); });
    }
    CommandReport report("morph", o.run);
    if (!o.tracked.empty()) {
        writeTrackedSequence(tracking.sequence(), o.tracked);
        reportTracking(tracking, o.tracked, report);
    }
    outputs.keep();
    report.wrote(o.directory, "frames");
    report["frames"] = o.morph.frames;
    report["translation"] = {summary.translation.x(), summary.translation.y(), summary.translation.z()};
    report["steps"] = summary.steps;
    report["morph_time"] = summary.duration;
    report["final_distance"] = summary.finalDistanceWorld;
    report["worst_distance"] = summary.worstDistanceWorld;
    report["resolved_fraction"] = summary.resolvedFraction;
    report["verdict"] = verdict(summary, target.voxelSize());
    report["units"] = target.units();
    report["frame_volumes"] = summary.frameVolumes;
    report.sayFormatted("wrote %d frames to %s (frame_0000.vdb ... frame_%04d.vdb%s)", o.morph.frames,
                        o.directory.c_str(), o.morph.frames - 1,
                        o.mesh.empty() ? "" : (" and ." + o.mesh + " meshes").c_str());
    if (summary.translation != openvdb::Vec3d(0.0)) {
        report.sayFormatted("aligned: source moved by (%g, %g, %g)", summary.translation.x(), summary.translation.y(),
                            summary.translation.z());
    }
    report.sayFormatted("steps: %d, morph time: %g, final distance to target: %g %s (%s)", summary.steps,
                        summary.duration, summary.finalDistanceWorld, target.units().c_str(),
                        verdict(summary, target.voxelSize()).c_str());
    if (summary.resolvedFraction < 1.0) {
        report.sayFormatted(
            "  measured where the target is at least 2.4 voxels thick (%.1f%% of the surface); at its thinner "
            "parts and sharp edges: %g %s",
            100.0 * summary.resolvedFraction, summary.worstDistanceWorld, target.units().c_str());
    }
    for (size_t i = 0; i < summary.frameVolumes.size(); ++i)
        report.sayFormatted("frame %04zu volume %g %s^3", i, summary.frameVolumes[i], target.units().c_str());
    report.print();
}

}  // namespace

void addMorphCommand(CLI::App& app)
{
    auto options = std::make_shared<MorphCommandOptions>();
    CLI::App* cmd =
        app.add_subcommand("morph", "Morph the source shape into the target: the source surface follows the target\n"
                                    "by level-set motion (growing where the target is larger, shrinking where it is\n"
                                    "smaller, changing topology as needed). Writes DIR/frame_0000.vdb ... evenly\n"
                                    "spaced in morph time; the last frame is the converged shape.");
    cmd->footer("Examples:\n  sculpt morph ball.vdb box.vdb --frames 24 -o frames --mesh ply\n  sculpt render frames "
                "-o movie   (then one camera for every frame)");
    cmd->add_option("source", options->source,
                    "the shape to start from: a .vdb document, a scan or a mesh (as for import)")
        ->required();
    cmd->add_option("target", options->target, "the shape to arrive at: a .vdb document, a scan or a mesh")->required();
    cmd->add_option("--frames", options->morph.frames,
                    "number of frames, first and last included (at most 10,000; the disk must hold them,\n"
                    "which is checked once the first is written)")
        ->check(CLI::Range(2, kMaxMorphFrames))
        ->capture_default_str();
    cmd->add_option("-o,--output", options->directory, "directory for the frames (created if missing)")->required();
    cmd->add_option("--mesh", options->mesh, "also write a mesh per frame: ply, obj or stl")
        ->check(CLI::IsMember({"ply", "obj", "stl"}));
    cmd->add_option("--tracked", options->tracked,
                    "also write a mesh that moves with the surface (vertices and triangles kept while they can\n"
                    "be) into this directory: per segment of constant connectivity a rest mesh (.ply), a point\n"
                    "cache (.pc2, Blender's Mesh Cache), a glTF with a shape key per frame (.glb) and a USD\n"
                    "layer with points and velocities per frame (.usda, Blender's Mesh Sequence Cache). A\n"
                    "vertex an edge split adds sits at the edge's midpoint in the segment's earlier frames, one\n"
                    "a collapse removes rides on its neighbour after; topology events start a new segment");
    cmd->add_flag("--keep-volume", options->morph.keepVolume,
                  "keep each frame's volume on the straight line between the two shapes' volumes");
    cmd->add_flag("--align", options->morph.align,
                  "first move the source so its centroid sits on the target's (needed when the\n"
                  "shapes do not overlap)");
    cmd->add_option("--tolerance", options->morph.toleranceVoxels,
                    "converged when every surface point is this near the target (voxels)")
        ->check(positiveNumber())
        ->capture_default_str();
    cmd->add_option("--max-steps", options->morph.maxSteps, "give up after this many steps")
        ->check(positiveNumber())
        ->capture_default_str();
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runMorph(*options); });
}

}  // namespace sculpt::cli
