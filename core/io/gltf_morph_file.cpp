// SPDX-License-Identifier: Apache-2.0
#include "core/io/gltf_morph_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/io/byte_order.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace sculpt {

namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedInt = 5125;                 // accessor component types
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;  // buffer view targets
constexpr std::uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;

/// The file's one buffer and the glTF objects that describe parts of it.
class GltfBuffer {
public:
    /// Appends a view of `values` (4-byte numbers) and returns its index.
    template <typename Number>
    int view(const std::vector<Number>& values, int target = 0)
    {
        json v{{"buffer", 0}, {"byteOffset", mBytes.size()}, {"byteLength", values.size() * 4}};
        if (target) v["target"] = target;
        for (const Number x : values) appendLittle(mBytes, x);
        mViews.push_back(std::move(v));
        return int(mViews.size()) - 1;
    }
    /// An accessor of `count` elements of `type` in view `view`, from `offset` bytes.
    int accessor(int view, std::size_t offset, int componentType, std::size_t count, const char* type,
                 json extra = json::object())
    {
        extra["bufferView"] = view;
        extra["byteOffset"] = offset;
        extra["componentType"] = componentType;
        extra["count"] = count;
        extra["type"] = type;
        mAccessors.push_back(std::move(extra));
        return int(mAccessors.size()) - 1;
    }
    /// The bounds glTF asks of every POSITION accessor.
    int positions(int view, std::size_t offset, const std::vector<float>& xyz)
    {
        std::vector<float> lo(3, std::numeric_limits<float>::max()), hi(3, std::numeric_limits<float>::lowest());
        for (std::size_t i = 0; i < xyz.size(); ++i) {
            lo[i % 3] = std::min(lo[i % 3], xyz[i]);
            hi[i % 3] = std::max(hi[i % 3], xyz[i]);
        }
        if (xyz.empty()) lo = hi = {0.0f, 0.0f, 0.0f};
        return accessor(view, offset, kFloat, xyz.size() / 3, "VEC3", {{"min", lo}, {"max", hi}});
    }

    void describe(json& gltf) const
    {
        gltf["buffers"] = json::array({json{{"byteLength", mBytes.size()}}});
        gltf["bufferViews"] = mViews;
        gltf["accessors"] = mAccessors;
    }
    const std::string& bytes() const { return mBytes; }

private:
    std::string mBytes;
    json mViews = json::array(), mAccessors = json::array();
};

std::vector<float> flat(const std::vector<std::array<float, 3>>& points)
{
    std::vector<float> xyz;
    xyz.reserve(points.size() * 3);
    for (const auto& p : points) xyz.insert(xyz.end(), p.begin(), p.end());
    return xyz;
}

/// The animation: target k - 1 weighs 1 at frame k, every other 0.
json weightAnimation(GltfBuffer& buffer, std::size_t frames, double fps)
{
    const std::size_t targets = frames - 1;
    std::vector<float> times(frames), weights(frames * targets, 0.0f);
    for (std::size_t k = 0; k < frames; ++k) {
        times[k] = float(double(k) / fps);
        if (k > 0) weights[k * targets + (k - 1)] = 1.0f;
    }
    const int input = buffer.accessor(buffer.view(times), 0, kFloat, frames, "SCALAR",
                                      {{"min", json::array({times.front()})}, {"max", json::array({times.back()})}});
    const int output = buffer.accessor(buffer.view(weights), 0, kFloat, weights.size(), "SCALAR");
    const json sampler{{"input", input}, {"output", output}, {"interpolation", "LINEAR"}};
    const json channel{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}};
    return {{"name", "morph"}, {"samplers", json::array({sampler})}, {"channels", json::array({channel})}};
}

/// `chunk` padded with `pad` to 4 bytes, behind its length and type.
void appendChunk(std::string& glb, std::string chunk, std::uint32_t type, char pad)
{
    chunk.resize((chunk.size() + 3) / 4 * 4, pad);
    appendLittle(glb, std::uint32_t(chunk.size()));
    appendLittle(glb, type);
    glb += chunk;
}

}  // namespace

void writeGltfMorph(const MeshSequence& mesh, const std::filesystem::path& path)
{
    checkMeshSequence(mesh, path);
    GltfBuffer buffer;
    const std::vector<float> base = flat(mesh.frames.front());
    const int position = buffer.positions(buffer.view(base, kArrayBuffer), 0, base);
    std::vector<std::uint32_t> indices;
    for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    const int index =
        buffer.accessor(buffer.view(indices, kElementArrayBuffer), 0, kUnsignedInt, indices.size(), "SCALAR");

    json primitive{{"attributes", {{"POSITION", position}}}, {"indices", index}, {"mode", 4}};
    json gltfMesh{{"name", mesh.name}, {"primitives", json::array()}};
    const json scene{{"nodes", json::array({0})}};
    const json node{{"mesh", 0}, {"name", mesh.name}};
    json gltf{{"asset", {{"version", "2.0"}, {"generator", "sculpt"}}},
              {"scene", 0},
              {"scenes", json::array({scene})},
              {"nodes", json::array({node})}};
    if (mesh.frames.size() > 1) {
        std::vector<float> deltas;
        for (std::size_t k = 1; k < mesh.frames.size(); ++k) {
            const std::vector<float> frame = flat(mesh.frames[k]);
            for (std::size_t i = 0; i < frame.size(); ++i) deltas.push_back(frame[i] - base[i]);
        }
        const int view = buffer.view(deltas, kArrayBuffer);
        json targets = json::array(), names = json::array();
        for (std::size_t k = 1; k < mesh.frames.size(); ++k) {
            const std::size_t first = (k - 1) * base.size();
            const std::vector<float> delta(deltas.begin() + long(first), deltas.begin() + long(first + base.size()));
            targets.push_back(json{{"POSITION", buffer.positions(view, first * 4, delta)}});
            char name[32];
            std::snprintf(name, sizeof(name), "frame_%04zu", k);
            names.push_back(name);
        }
        primitive["targets"] = targets;
        gltfMesh["weights"] = std::vector<float>(mesh.frames.size() - 1, 0.0f);
        gltfMesh["extras"] = {{"targetNames", names}};  // Blender names the shape keys after them
        gltf["animations"] = json::array({weightAnimation(buffer, mesh.frames.size(), mesh.framesPerSecond)});
    }
    gltfMesh["primitives"].push_back(primitive);
    gltf["meshes"] = json::array({gltfMesh});
    buffer.describe(gltf);

    std::string glb;
    appendLittle(glb, kGlbMagic);
    appendLittle(glb, std::uint32_t(2));
    appendLittle(glb, std::uint32_t(0));  // the total length, set below
    appendChunk(glb, gltf.dump(), kJsonChunk, ' ');
    appendChunk(glb, buffer.bytes(), kBinChunk, '\0');
    std::string total;
    appendLittle(total, std::uint32_t(glb.size()));
    glb.replace(8, 4, total);
    writeFileAtomically(path, glb);
}

}  // namespace sculpt
