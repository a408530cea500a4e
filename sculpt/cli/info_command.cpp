// SPDX-License-Identifier: Apache-2.0
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/io/vdb_layout.h"
#include "core/mesh/field_measures.h"
#include "core/scan/kept_scan.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/cli/run_options.h"
#include "sculpt/session/document_info.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace sculpt::cli {

namespace {

struct InfoOptions {
    DocumentInput input;
    RunOptions run;
    double thickness = 0.0;  ///< > 0: look for walls thinner than this
};

void printMeasures(const FieldMeasures& m, const std::string& units)
{
    const char* u = units.c_str();
    std::printf("voxel size:           %g %s (band half width %g voxels)\n", m.voxelSize, u, m.halfWidthVoxels);
    std::printf("active voxels:        %llu\n", static_cast<unsigned long long>(m.activeVoxels));
    std::printf("memory:               %s\n", formatBytes(double(m.memoryBytes)).c_str());
    std::printf("bounding box:         (%g, %g, %g) .. (%g, %g, %g) %s\n", m.bboxMin.x(), m.bboxMin.y(), m.bboxMin.z(),
                m.bboxMax.x(), m.bboxMax.y(), m.bboxMax.z(), u);
    std::printf("volume:               %g %s^3\n", m.volume, u);
    std::printf("area:                 %g %s^2\n", m.area, u);
    std::printf("euler characteristic: %d\n", m.eulerCharacteristic);
    std::printf("components:           %d\n", m.components);
}

/// "#cc7a66": a piece's colour as people type it.
std::string hexColour(const openvdb::Vec3f& c)
{
    char text[8];
    const auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]));
    return text;
}

/// The file's grids that are not pieces, their masks or the scan the document keeps (which have
/// lines of their own).
VdbLayout othersThan(VdbLayout layout, const VdbPieces& read)
{
    const openvdb::FloatGrid::ConstPtr kept = findKeptScan(read.companions.grids);
    const auto isShown = [&](const VdbGridEntry& grid) {
        if (kept && grid.name == kept->getName()) return true;
        return std::any_of(read.pieces.begin(), read.pieces.end(), [&](const Piece& p) {
            return p.name == grid.name || (p.field.mask() && grid.name == p.name + ".mask");
        });
    };
    layout.grids.erase(std::remove_if(layout.grids.begin(), layout.grids.end(), isShown), layout.grids.end());
    return layout;
}

void printPieces(const std::vector<Piece>& pieces, const std::vector<FieldMeasures>& measures, const VdbLayout& others)
{
    if (!others.grids.empty()) std::printf("other grids:          %s\n", describeGrids(others).c_str());
    const std::string& units = pieces.front().field.units();
    std::printf("pieces:               %zu\n", pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const FieldMeasures& m = measures[i];
        std::printf("  %-20s volume %g %s^3, area %g %s^2, euler characteristic %d, %d components, voxel size %g, "
                    "%s%s%s\n",
                    ("'" + pieces[i].name + "'").c_str(), m.volume, units.c_str(), m.area, units.c_str(),
                    m.eulerCharacteristic, m.components, m.voxelSize, hexColour(pieces[i].colour).c_str(),
                    pieces[i].visible ? "" : ", hidden", pieces[i].field.mask() ? ", masked" : "");
    }
    std::printf("all pieces:\n");
}

void printKeptScan(const nlohmann::json& kept)
{
    if (kept.is_null()) {
        std::printf("kept scan:            none\n");
        return;
    }
    const auto& d = kept["dims"];
    std::printf(
        "kept scan:            %d x %d x %d samples (%s) from %s%s; %s in memory, %s in the file\n", d[0].get<int>(),
        d[1].get<int>(), d[2].get<int>(), kept["sample_type"].get<std::string>().c_str(),
        kept["source"].get<std::string>().c_str(),
        kept["iso"].is_null() ? "" : (", imported at iso-value " + formatNumber(kept["iso"].get<double>())).c_str(),
        formatBytes(kept["memory_bytes"].get<double>()).c_str(), formatBytes(kept["file_bytes"].get<double>()).c_str());
}

void runInfo(const InfoOptions& o)
{
    const VdbPieces read = readPieces(o.input);
    const VdbLayout layout = scanVdbLayout(o.input.path);
    if (o.run.quiet) return;
    if (o.run.json) {
        nlohmann::json report = documentInfo(read, layout, o.input.path, o.thickness);
        report["command"] = "info";
        report["outputs"] = nlohmann::json::array();
        std::cout << report.dump() << "\n";
        return;
    }
    const std::vector<Piece>& pieces = read.pieces;
    const nlohmann::json kept = keptScanJson(read.companions, layout, o.input.path);
    std::vector<FieldMeasures> measures;
    for (const Piece& piece : pieces) measures.push_back(measureField(piece.field));
    const FieldMeasures all = totalMeasures(measures);
    const std::string& units = pieces.front().field.units();
    std::printf("file:                 %s\n", o.input.path.c_str());
    if (pieces.size() == 1) {
        std::printf("grid:                 %s (the file holds %s)\n", pieces.front().field.grid().getName().c_str(),
                    describeGrids(layout).c_str());
    } else {
        printPieces(pieces, measures, othersThan(layout, read));
    }
    std::printf("frame:                %s %s (x to the patient's left, y to the back, z up%s)\n", FieldImage::kFrame,
                units.c_str(), layout.frame.empty() ? "; assumed: the file records none" : "");
    printMeasures(all, units);
    printKeptScan(kept);
    if (o.thickness <= 0.0) return;
    const nlohmann::json thinnest = thinnestJson(pieces.front().field, o.thickness);
    if (thinnest.is_null()) {
        std::printf("thinnest wall:        none under %g %s\n", o.thickness, units.c_str());
    } else {
        std::printf("thinnest wall:        %g %s at (%g, %g, %g)\n", thinnest["thickness"].get<double>(), units.c_str(),
                    thinnest["where"][0].get<double>(), thinnest["where"][1].get<double>(),
                    thinnest["where"][2].get<double>());
    }
}

}  // namespace

void addInfoCommand(CLI::App& app)
{
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd =
        app.add_subcommand("info", "Print a document's voxel size, active voxels, memory, bounding box, volume,\n"
                                   "area, Euler characteristic (2 per sphere-like piece, 0 per torus) and\n"
                                   "number of connected surface components, and the grids the file holds.\n"
                                   "A document of several pieces is measured per piece and in total.");
    cmd->footer("Examples:\n  sculpt info head.vdb\n  sculpt info head.vdb --json");
    addDocumentInput(*cmd, options->input, "the .vdb document to measure");
    addRunOptions(*cmd, options->run,
                  "here the keys voxel_size, active_voxels, memory_bytes,\n"
                  "bbox_min, bbox_max, volume, area, euler_characteristic, components\n"
                  "(plus units, frame: LPS, x to the patient's left, y to the back, z up, and\n"
                  "frame_recorded: false for a file that records none, read as LPS;\n"
                  "half_width_voxels, grid: the first grid measured, grids: every grid of the file\n"
                  "with its name, type and class, kept_scan: the scan the document keeps (dims,\n"
                  "source, sample_type, iso, memory_bytes, file_bytes, dense_float_bytes) or null,\n"
                  "and pieces: the same keys per\n"
                  "piece with its name, colour (sRGB 0..1) and visible; the top-level keys are the\n"
                  "pieces' total)");
    cmd->add_option("--thickness", options->thickness,
                    "also find the thinnest wall under this thickness (world units; measured into the solid\n"
                    "along the normal at every surface sample of the first piece): its thickness and where")
        ->check(positiveNumber());
    cmd->callback([options] { runInfo(*options); });
}

}  // namespace sculpt::cli
