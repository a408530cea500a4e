// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/document_info.h"

#include "core/base/errors.h"
#include "core/scan/kept_scan.h"
#include "core/solids/wall_thickness.h"

namespace sculpt {

namespace {

nlohmann::json gridsJson(const VdbLayout& layout)
{
    nlohmann::json grids = nlohmann::json::array();
    for (const VdbGridEntry& g : layout.grids)
        grids.push_back({{"name", g.name}, {"type", g.type}, {"class", g.gridClass}});
    return grids;
}

}  // namespace

nlohmann::json measuresJson(const FieldMeasures& m, const std::string& units)
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

FieldMeasures totalMeasures(const std::vector<FieldMeasures>& pieces)
{
    FieldMeasures sum = pieces.front();
    for (std::size_t i = 1; i < pieces.size(); ++i) {
        const FieldMeasures& m = pieces[i];
        sum.activeVoxels += m.activeVoxels;
        sum.memoryBytes += m.memoryBytes;
        sum.bboxMin = openvdb::math::minComponent(sum.bboxMin, m.bboxMin);
        sum.bboxMax = openvdb::math::maxComponent(sum.bboxMax, m.bboxMax);
        sum.volume += m.volume;
        sum.area += m.area;
        sum.eulerCharacteristic += m.eulerCharacteristic;
        sum.components += m.components;
    }
    return sum;
}

nlohmann::json keptScanJson(const VdbCompanions& companions, const VdbLayout& layout, const std::string& path)
{
    const openvdb::FloatGrid::ConstPtr grid = findKeptScan(companions.grids);
    if (!grid) return nullptr;
    KeptScanRecord record;
    try {
        record = keptScanRecord(*grid);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    std::int64_t fileBytes = 0;
    for (const VdbGridEntry& entry : layout.grids)
        if (entry.name == grid->getName() && entry.located()) fileBytes = entry.end - entry.begin;
    const openvdb::Coord& d = record.lattice.dims;
    nlohmann::json kept = {{"dims", {d.x(), d.y(), d.z()}},
                           {"source", record.source},
                           {"sample_type", record.sampleType},
                           {"iso", nullptr},
                           {"memory_bytes", grid->memUsage()},
                           {"file_bytes", fileBytes},
                           {"dense_float_bytes", 4.0 * double(d.x()) * d.y() * d.z()}};
    if (record.iso) kept["iso"] = *record.iso;
    return kept;
}

nlohmann::json thinnestJson(const FieldImage& field, double under)
{
    const std::optional<ThinnestWall> thinnest = thinnestWall(field, under);
    if (!thinnest) return nullptr;
    const openvdb::Vec3d& w = thinnest->where;
    return {{"thickness", thinnest->thickness}, {"where", {w.x(), w.y(), w.z()}}};
}

nlohmann::json documentInfo(const VdbPieces& read, const VdbLayout& layout, const std::string& path, double thickness)
{
    const std::vector<Piece>& pieces = read.pieces;
    std::vector<FieldMeasures> measures;
    for (const Piece& piece : pieces) measures.push_back(measureField(piece.field));
    const std::string& units = pieces.front().field.units();
    nlohmann::json info = measuresJson(totalMeasures(measures), units);
    info["frame"] = FieldImage::kFrame;
    info["frame_recorded"] = !layout.frame.empty();
    info["grid"] = pieces.front().field.grid().getName();
    info["grids"] = gridsJson(layout);
    info["kept_scan"] = keptScanJson(read.companions, layout, path);
    info["pieces"] = nlohmann::json::array();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        nlohmann::json piece = measuresJson(measures[i], units);
        const openvdb::Vec3f& c = pieces[i].colour;
        piece["name"] = pieces[i].name;
        piece["colour"] = {c[0], c[1], c[2]};
        piece["visible"] = pieces[i].visible;
        info["pieces"].push_back(piece);
    }
    if (thickness > 0.0) info["thinnest_wall"] = thinnestJson(pieces.front().field, thickness);
    return info;
}

}  // namespace sculpt
