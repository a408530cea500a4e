// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/written_outputs.h"
#include "core/io/image_file.h"
#include "core/render/ray_tracer.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/frame_files.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

namespace fs = std::filesystem;
using openvdb::Vec3d;

struct RenderCommandOptions {
    DocumentInput input;
    std::string output;
    RenderOptions render;
    std::vector<double> camera, lookAt, up;
    double fov = 35.0;
    std::string background = "0.16,0.16,0.18";
    int turntable = 0;
    std::string format = "png";
    std::string frames;  ///< "A-B": the part of a sequence to render
    RunOptions run;
};

/// The frames `--frames A-B` names (first and last included, counted from 0) of a sequence of
/// `count`; all of them without the option.
std::pair<std::size_t, std::size_t> frameRange(const std::string& text, std::size_t count)
{
    if (text.empty()) return {0, count - 1};
    std::istringstream in(text);
    long first = -1, last = -1;
    char dash = 0;
    if (!(in >> first >> dash >> last) || dash != '-' || !in.eof() || first < 0 || last < first)
        throw InputError("--frames: expected A-B, the first and last frame counted from 0 (got '" + text + "')");
    if (std::size_t(last) >= count) {
        throw InputError("--frames " + text + ": the sequence has " + std::to_string(count) + " frames (0-" +
                         std::to_string(count - 1) + ")");
    }
    return {std::size_t(first), std::size_t(last)};
}

Vec3d vec3(const std::vector<double>& v) { return Vec3d(v[0], v[1], v[2]); }

/// "r,g,b" in [0, 1], or "none" for a transparent background.
std::optional<Vec3d> parseBackground(const std::string& text)
{
    if (text == "none") return std::nullopt;
    std::istringstream in(text);
    Vec3d c;
    char comma1 = 0, comma2 = 0;
    if (!(in >> c[0] >> comma1 >> c[1] >> comma2 >> c[2]) || comma1 != ',' || comma2 != ',' || !in.eof()) {
        throw InputError("--background: expected r,g,b (0 to 1 each) or none (got '" + text + "')");
    }
    return c;
}

/// The camera the options ask for: the automatic three-quarter view of `extent`, with any of
/// position, look-at point and up the user gave.
Camera chooseCamera(const RenderCommandOptions& o, const SurfaceExtent& extent)
{
    Camera camera = framingCamera(extent, double(o.render.width) / o.render.height, o.fov);
    if (!o.lookAt.empty()) {
        const Vec3d offset = camera.position - camera.lookAt;
        camera.lookAt = vec3(o.lookAt);
        camera.position = camera.lookAt + offset;
    }
    if (!o.camera.empty()) camera.position = vec3(o.camera);
    if (!o.up.empty()) camera.up = vec3(o.up);
    camera.validate();
    return camera;
}

/// Renders one document to one image file, the progress of the whole job running from `from`
/// to `to`.
void renderOne(const FieldImage& field, const Camera& camera, const RenderOptions& options, const fs::path& output,
               const Progress& progress, double from, double to)
{
    RenderReport summary;
    const RenderedImage image = renderField(field, camera, options, summary,
                                            [&](double f) { return !progress || progress(from + (to - from) * f); });
    for (const std::string& warning : summary.warnings)
        std::cerr << "sculpt: warning: " << output.string() << ": " << warning << "\n";
    writeImage(image, camera, output);
}

void runRender(RenderCommandOptions o)
{
    o.render.background = parseBackground(o.background);
    o.render.validate();
    const bool sequence = fs::is_directory(o.input.path);
    if (sequence && o.turntable > 0) {
        throw InputError(o.input.path + ": --turntable turns one document, not a directory of frames");
    }
    if (!sequence && !o.frames.empty()) {
        throw InputError(o.input.path + ": --frames picks frames of a directory of .vdb frames, not of one document");
    }
    CommandReport report("render", o.run);
    report["width"] = o.render.width;
    report["height"] = o.render.height;
    WrittenOutputs outputs;  // a sequence that fails leaves no frames behind
    if (sequence || o.turntable > 0) {
        imageFormatOf("frame." + o.format);
        outputs.directory(o.output);
    } else {
        imageFormatOf(o.output);
        AtomicFile::checkTarget(o.output);
    }
    if (sequence) {
        // One camera for every frame: it frames the union of the frames' bounds.
        // The camera frames the whole sequence even for a part of it, so parts rendered apart
        // (in parallel jobs) join up; frames keep their numbers.
        const std::vector<fs::path> frames = documentsIn(o.input.path);
        const auto [first, last] = frameRange(o.frames, frames.size());
        // Frames are read twice (here and to render) so that only one is in memory at a time.
        SurfaceExtent extent;
        for (const fs::path& frame : frames) extent.add(readFieldImage(frame, o.input.grid));
        const Camera camera = chooseCamera(o, extent);
        const std::size_t count = last - first + 1;
        ProgressBar bar("rendering " + std::to_string(count) + " frames");
        const Progress progress = bar.callback();
        for (std::size_t i = first; i <= last; ++i) {
            renderOne(readFieldImage(frames[i], o.input.grid), camera, o.render,
                      outputs.file(framePath(o.output, int(i), o.format)), progress, double(i - first) / count,
                      double(i - first + 1) / count);
            if (i == first) outputs.requireRoomFor(count - 1, 1.0, "the other frames' images");
        }
        outputs.keep();
        report.wrote(o.output, "frames");
        report["frames"] = {first, last};
        report["camera"] = {camera.position.x(), camera.position.y(), camera.position.z()};
        report.say("wrote " + std::to_string(count) + " frames to " + o.output + " (" +
                   framePath("", int(first), o.format).string() + " ... " +
                   framePath("", int(last), o.format).string() + "), one camera for the whole sequence");
        report.print();
        return;
    }
    const FieldImage field = readDocument(o.input).field;
    const Camera camera = chooseCamera(o, SurfaceExtent(field));
    ProgressBar bar("rendering");
    const Progress progress = bar.callback();
    if (o.turntable > 0) {
        for (int i = 0; i < o.turntable; ++i) {
            renderOne(field, camera.orbited(2.0 * M_PI * i / o.turntable), o.render,
                      outputs.file(framePath(o.output, i, o.format)), progress, double(i) / o.turntable,
                      double(i + 1) / o.turntable);
            if (i == 0) outputs.requireRoomFor(o.turntable - 1, 1.0, "the other turntable images");
        }
        outputs.keep();
        report.wrote(o.output, "frames");
        report["frames"] = {0, o.turntable - 1};
        report["camera"] = {camera.position.x(), camera.position.y(), camera.position.z()};
        report.say("wrote " + std::to_string(o.turntable) + " turntable frames to " + o.output + " (frame_0000." +
                   o.format + " ...)");
        report.print();
        return;
    }
    renderOne(field, camera, o.render, o.output, progress, 0.0, 1.0);
    report.wrote(o.output, "image");
    report["camera"] = {camera.position.x(), camera.position.y(), camera.position.z()};
    std::ostringstream line;
    line << "wrote " << o.output << ": " << o.render.width << " x " << o.render.height << ", camera at ("
         << camera.position.x() << ", " << camera.position.y() << ", " << camera.position.z() << ")";
    report.say(line.str());
    report.print();
}

}  // namespace

void addRenderCommand(CLI::App& app)
{
    auto o = std::make_shared<RenderCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Ray-trace a final image of a document against its level set (no mesh): clay shading with\n"
                  "a key and a fill light, ambient occlusion, anti-aliasing. .exr gets half-float RGBA plus\n"
                  "Z (camera distance) and N.X N.Y N.Z (world normal) layers and the camera in its header;\n"
                  ".png a tone-mapped 8-bit picture. --turntable N writes N frames around the model into\n"
                  "the directory -o; a directory of .vdb frames (a morph) renders to frames in -o with one\n"
                  "camera that frames them all. Without --camera, a three-quarter view frames the model.");
    cmd->footer(
        "Examples:\n  sculpt render head.vdb -o head.png\n  sculpt render head.vdb --turntable 36 -o turntable");
    addDocumentInput(*cmd, o->input, "a .vdb document, or a directory of .vdb frames");
    cmd->add_option("-o,--output", o->output, "the image (.exr or .png), or a directory for frames")->required();
    cmd->add_option("--width", o->render.width, "image width in pixels (1 to 16384)")->capture_default_str();
    cmd->add_option("--height", o->render.height, "image height in pixels (1 to 16384)")->capture_default_str();
    cmd->add_option("--camera", o->camera, "camera position x,y,z (default: a three-quarter view)")
        ->delimiter(',')
        ->expected(3);
    cmd->add_option("--look-at", o->lookAt, "the point at the image's centre x,y,z (default: the model's)")
        ->delimiter(',')
        ->expected(3);
    cmd->add_option("--up", o->up, "the camera's up direction x,y,z (default: 0,1,0)")->delimiter(',')->expected(3);
    cmd->add_option("--fov", o->fov, "vertical field of view in degrees")->capture_default_str();
    cmd->add_option("--samples", o->render.samples, "samples per pixel (anti-aliasing; rounded up to a square)")
        ->capture_default_str();
    cmd->add_option("--occlusion", o->render.occlusionRays, "ambient-occlusion rays per pixel (0: none)")
        ->capture_default_str();
    cmd->add_option("--background", o->background, "background colour r,g,b (linear, 0 to 1), or none (transparent)")
        ->capture_default_str();
    cmd->add_option("--turntable", o->turntable,
                    "render N frames around the model into the directory -o (at most 3,600: a tenth of a degree\n"
                    "apart)")
        ->check(CLI::Range(1, 3600));
    cmd->add_option("--format", o->format, "image format of frames written into a directory")
        ->check(CLI::IsMember({"png", "exr"}))
        ->capture_default_str();
    cmd->add_option("--frames", o->frames,
                    "A-B: render only frames A to B of a directory of frames (counted from 0), framed as the\n"
                    "whole sequence and numbered as in it, so parts rendered by parallel jobs join up");
    addRunOptions(*cmd, o->run);
    cmd->callback([o] { runRender(*o); });
}

}  // namespace sculpt::cli
