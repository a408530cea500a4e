#include "core/base/text_format.h"
#include "core/io/vdb_layout.h"
#include "core/mesh/field_measures.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace sculpt::cli {

namespace {

struct InfoOptions {
    DocumentInput input;
    bool json = false;
};

nlohmann::json gridsJson(const VdbLayout& layout)
{
    nlohmann::json grids = nlohmann::json::array();
    for (const VdbGridEntry& g : layout.grids)
        grids.push_back({{"name", g.name}, {"type", g.type}, {"class", g.gridClass}});
    return grids;
}

nlohmann::json toJson(const FieldMeasures& m, const std::string& units)
{
    auto vec = [](const openvdb::Vec3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
    return {{"voxel_size", m.voxelSize},
            {"units", units},
            {"half_width_voxels", m.halfWidthVoxels},
            {"active_voxels", m.activeVoxels},
            {"memory_bytes", m.memoryBytes},
            {"bbox_min", vec(m.bboxMin)},
            {"bbox_max", vec(m.bboxMax)},
            {"volume", m.volume},
            {"area", m.area},
            {"euler_characteristic", m.eulerCharacteristic},
            {"components", m.components}};
}

void printText(const FieldMeasures& m, const std::string& units, const std::string& input, const std::string& grid,
               const VdbLayout& layout)
{
    const char* u = units.c_str();
    std::printf("file:                 %s\n", input.c_str());
    std::printf("grid:                 %s (the file holds %s)\n", grid.c_str(), describeGrids(layout).c_str());
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

void runInfo(const InfoOptions& o)
{
    const FieldImage field = readDocument(o.input).field;
    const VdbLayout layout = scanVdbLayout(o.input.path);
    const FieldMeasures m = measureField(field);
    if (o.json) {
        nlohmann::json report = toJson(m, field.units());
        report["grid"] = field.grid().getName();
        report["grids"] = gridsJson(layout);
        std::cout << report.dump() << "\n";
    } else {
        printText(m, field.units(), o.input.path, field.grid().getName(), layout);
    }
}

}  // namespace

void addInfoCommand(CLI::App& app)
{
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd =
        app.add_subcommand("info", "Print a document's voxel size, active voxels, memory, bounding box, volume,\n"
                                   "area, Euler characteristic (2 per sphere-like piece, 0 per torus) and\n"
                                   "number of connected surface components, and the grids the file holds.");
    addDocumentInput(*cmd, options->input, "the .vdb document to measure");
    cmd->add_flag("--json", options->json,
                  "print one JSON object with the keys voxel_size, active_voxels, memory_bytes,\n"
                  "bbox_min, bbox_max, volume, area, euler_characteristic, components\n"
                  "(plus units, half_width_voxels, grid: the grid measured, and grids: every\n"
                  "grid of the file with its name, type and class)");
    cmd->callback([options] { runInfo(*options); });
}

}  // namespace sculpt::cli
