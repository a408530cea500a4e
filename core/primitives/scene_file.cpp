// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/scene_file.h"

#include "core/base/errors.h"
#include "core/base/json_fields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace sculpt {

namespace {

using json_fields::field;
using json_fields::number;
using json_fields::vec3;
using nlohmann::json;

openvdb::Mat3d rotationFromDegrees(const openvdb::Vec3d& degrees)
{
    openvdb::Mat3d m = openvdb::Mat3d::identity();
    for (int axis = 0; axis < 3; ++axis) {
        openvdb::Mat3d r = openvdb::math::rotation<openvdb::Mat3d>(axis == 0   ? openvdb::math::X_AXIS
                                                                   : axis == 1 ? openvdb::math::Y_AXIS
                                                                               : openvdb::math::Z_AXIS,
                                                                   degrees[axis] * M_PI / 180.0);
        m = r * m;
    }
    return m;
}

Skeleton parseSkeleton(const json& j, const std::string& where)
{
    Skeleton s;
    const json& type = field(j, "type", where);
    if (!type.is_string()) throw InputError(where + ": field 'type' must be a string");
    s.type = skeletonFromName(type.get<std::string>());
    switch (s.type) {
    case SkeletonType::Point: s.points[0] = vec3(field(j, "position", where), where + ": 'position'"); break;
    case SkeletonType::Segment:
        s.points[0] = vec3(field(j, "from", where), where + ": 'from'");
        s.points[1] = vec3(field(j, "to", where), where + ": 'to'");
        break;
    case SkeletonType::Triangle: {
        const json& points = field(j, "points", where);
        if (!points.is_array() || points.size() != 3) throw InputError(where + ": 'points' must hold 3 points");
        for (int i = 0; i < 3; ++i) s.points[size_t(i)] = vec3(points[size_t(i)], where + ": 'points'");
        break;
    }
    case SkeletonType::Box:
        s.points[0] = vec3(field(j, "center", where), where + ": 'center'");
        s.halfExtents = vec3(field(j, "half_extents", where), where + ": 'half_extents'");
        if (j.contains("rotation_degrees"))
            s.worldFromBox = rotationFromDegrees(vec3(j["rotation_degrees"], where + ": 'rotation_degrees'"));
        break;
    }
    return s;
}

std::vector<Primitive> parsePrimitives(const json& list, bool& graph, const std::string& source)
{
    if (!list.is_array()) throw InputError(source + ": 'primitives' must be an array");
    std::vector<Primitive> primitives;
    std::map<std::string, int> byName;
    for (size_t i = 0; i < list.size(); ++i) {
        const json& j = list[i];
        Primitive p;
        if (j.is_object() && j.contains("name")) p.name = j["name"].is_string() ? j["name"].get<std::string>() : "";
        const std::string where = source + ": " + describePrimitive(int(i), p.name);
        if (!j.is_object()) throw InputError(where + " must be an object");
        p.skeleton = parseSkeleton(field(j, "skeleton", where), where + " skeleton");
        const json& kernel = field(j, "kernel", where);
        if (!kernel.is_string()) throw InputError(where + ": field 'kernel' must be a string");
        try {
            p.kernel.type = kernelFromName(kernel.get<std::string>());
        } catch (const InputError& e) {
            throw InputError(where + ": " + e.what(), e.remedy());
        }
        p.kernel.radius = number(j, "radius", where);
        p.kernel.strength = j.contains("strength") ? number(j, "strength", where) : 1.0;
        if (!p.name.empty() && !byName.emplace(p.name, int(i)).second) throw InputError(where + ": name used twice");
        primitives.push_back(p);
    }
    for (size_t i = 0; i < list.size(); ++i) {
        if (!list[i].contains("neighbours")) continue;
        graph = true;
        const std::string where = source + ": " + describePrimitive(int(i), primitives[i].name);
        const json& neighbours = list[i]["neighbours"];
        if (!neighbours.is_array()) throw InputError(where + ": 'neighbours' must be an array of names");
        for (const json& n : neighbours) {
            const auto found = n.is_string() ? byName.find(n.get<std::string>()) : byName.end();
            if (found == byName.end()) throw InputError(where + ": neighbour " + n.dump() + " names no primitive");
            primitives[i].neighbours.push_back(found->second);
        }
    }
    return primitives;
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& source)
{
    const json root = json_fields::parse(text, source);
    if (!root.is_object()) throw InputError(source + ": a scene must be a JSON object");
    bool graph = false;
    std::vector<Primitive> primitives = parsePrimitives(field(root, "primitives", source), graph, source);
    const double iso = root.contains("iso") ? number(root, "iso", source) : 0.5;
    Scene scene{[&] {
                    try {
                        return PrimitiveSet(std::move(primitives), iso, graph);
                    } catch (const InputError& e) {
                        throw InputError(source + ": " + e.what(), e.remedy());
                    }
                }(),
                CsgOperation::Union, std::nullopt};
    if (root.contains("operation")) {
        const json& op = root["operation"];
        if (!op.is_string()) throw InputError(source + ": field 'operation' must be a string");
        scene.operation = csgFromName(op.get<std::string>());
    }
    if (root.contains("voxel_size")) {
        scene.voxelSize = number(root, "voxel_size", source);
        if (!(*scene.voxelSize > 0.0)) throw InputError(source + ": 'voxel_size' must be positive");
    }
    return scene;
}

namespace {

json vec3Json(const openvdb::Vec3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json skeletonJson(const Skeleton& s)
{
    switch (s.type) {
    case SkeletonType::Point: return {{"type", "point"}, {"position", vec3Json(s.points[0])}};
    case SkeletonType::Segment:
        return {{"type", "segment"}, {"from", vec3Json(s.points[0])}, {"to", vec3Json(s.points[1])}};
    case SkeletonType::Triangle:
        return {{"type", "triangle"},
                {"points", json::array({vec3Json(s.points[0]), vec3Json(s.points[1]), vec3Json(s.points[2])})}};
    case SkeletonType::Box: {
        json j = {{"type", "box"}, {"center", vec3Json(s.points[0])}, {"half_extents", vec3Json(s.halfExtents)}};
        if (!s.worldFromBox.eq(openvdb::Mat3d::identity())) {
            // rotationFromDegrees builds Rz Ry Rx: OpenVDB's XYZ order.
            const openvdb::Vec3d radians = openvdb::math::eulerAngles(s.worldFromBox, openvdb::math::XYZ_ROTATION);
            j["rotation_degrees"] = vec3Json(radians * (180.0 / M_PI));
        }
        return j;
    }
    }
    return {};
}

/// Each primitive's name, made up ("p3") where a graph needs one and it has none.
std::vector<std::string> namesFor(const PrimitiveSet& set)
{
    std::vector<std::string> names;
    for (const Primitive& p : set.primitives()) names.push_back(p.name);
    if (!set.usesGraph()) return names;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (!names[i].empty()) continue;
        std::string name = "p" + std::to_string(i);
        while (std::find(names.begin(), names.end(), name) != names.end()) name += "_";
        names[i] = name;
    }
    return names;
}

}  // namespace

std::string writeScene(const Scene& scene)
{
    const PrimitiveSet& set = scene.primitives;
    const std::vector<std::string> names = namesFor(set);
    json primitives = json::array();
    for (std::size_t i = 0; i < set.primitives().size(); ++i) {
        const Primitive& p = set.primitives()[i];
        json j = {{"kernel", kernelName(p.kernel.type)},
                  {"radius", p.kernel.radius},
                  {"strength", p.kernel.strength},
                  {"skeleton", skeletonJson(p.skeleton)}};
        if (!names[i].empty()) j["name"] = names[i];
        if (set.usesGraph()) {
            json neighbours = json::array();
            for (int n : p.neighbours) neighbours.push_back(names[std::size_t(n)]);
            j["neighbours"] = std::move(neighbours);
        }
        primitives.push_back(std::move(j));
    }
    json root = {{"iso", set.iso()}, {"operation", csgName(scene.operation)}, {"primitives", std::move(primitives)}};
    if (scene.voxelSize) root["voxel_size"] = *scene.voxelSize;
    return root.dump(1) + "\n";
}

Scene readScene(const std::filesystem::path& path)
{
    std::ifstream in(path);
    if (!in) throw InputError(path.string() + ": cannot read the scene file");
    std::stringstream text;
    text << in.rdbuf();
    return parseScene(text.str(), path.string());
}

}  // namespace sculpt
