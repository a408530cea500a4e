#include "core/base/text_format.h"
#include "core/io/vdb_file.h"
#include "core/mesh/field_measures.h"
#include "sculpt/cli/commands.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace sculpt::cli {

namespace {

struct InfoOptions {
    std::string input;
    bool json = false;
};

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

void printText(const FieldMeasures& m, const std::string& units, const std::string& input)
{
    const char* u = units.c_str();
    std::printf("file:                 %s\n", input.c_str());
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
    const FieldImage field = readFieldImage(o.input);
    const FieldMeasures m = measureField(field);
    if (o.json) {
        std::cout << toJson(m, field.units()).dump() << "\n";
    } else {
        printText(m, field.units(), o.input);
    }
}

}  // namespace

void addInfoCommand(CLI::App& app)
{
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd =
        app.add_subcommand("info", "Print a document's voxel size, active voxels, memory, bounding box, volume,\n"
                                   "area, Euler characteristic (2 per sphere-like piece, 0 per torus) and\n"
                                   "number of connected surface components.");
    cmd->add_option("input", options->input, "the .vdb document to measure")->required();
    cmd->add_flag("--json", options->json,
                  "print one JSON object with the keys voxel_size, active_voxels, memory_bytes,\n"
                  "bbox_min, bbox_max, volume, area, euler_characteristic, components\n"
                  "(plus units and half_width_voxels)");
    cmd->callback([options] { runInfo(*options); });
}

}  // namespace sculpt::cli
