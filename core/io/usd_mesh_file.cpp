// SPDX-License-Identifier: Apache-2.0
#include "core/io/usd_mesh_file.h"

#include "core/base/atomic_file.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace sculpt {

namespace {

using Points = std::vector<std::array<float, 3>>;

/// Shortest text that reads back as the same float.
void appendNumber(std::string& out, double value)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", value);
    out += text;
}

void appendTuple(std::string& out, const std::array<float, 3>& p)
{
    out += '(';
    for (int k = 0; k < 3; ++k) {
        if (k) out += ", ";
        appendNumber(out, p[std::size_t(k)]);
    }
    out += ')';
}

template <typename List, typename Append>
void appendList(std::string& out, const List& list, Append append)
{
    out += '[';
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (i) out += ", ";
        append(list[i]);
    }
    out += ']';
}

/// `type name.timeSamples = { frame: value, ... }`, one line per frame.
template <typename Value>
void appendTimeSamples(std::string& out, const char* declaration, const MeshSequence& mesh, Value value)
{
    out += std::string("    ") + declaration + ".timeSamples = {\n";
    for (std::size_t f = 0; f < mesh.frames.size(); ++f) {
        out += "        " + std::to_string(mesh.firstFrame + int(f)) + ": ";
        appendList(out, value(f), [&](const std::array<float, 3>& p) { appendTuple(out, p); });
        out += ",\n";
    }
    out += "    }\n";
}

/// Frame f's velocities: central differences, one-sided at the ends, zero for a single frame.
Points velocities(const MeshSequence& mesh, std::size_t f)
{
    const std::size_t last = mesh.frames.size() - 1, before = f > 0 ? f - 1 : 0, after = std::min(f + 1, last);
    Points v(mesh.frames[f].size(), {0.0f, 0.0f, 0.0f});
    if (after == before) return v;
    const double perSecond = mesh.framesPerSecond / double(after - before);
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            v[i][k] = float((double(mesh.frames[after][i][k]) - double(mesh.frames[before][i][k])) * perSecond);
    return v;
}

Points extent(const Points& frame)
{
    Points box{
        {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()},
        {std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest(),
         std::numeric_limits<float>::lowest()}};
    for (const auto& p : frame)
        for (std::size_t k = 0; k < 3; ++k) {
            box[0][k] = std::min(box[0][k], p[k]);
            box[1][k] = std::max(box[1][k], p[k]);
        }
    return box;
}

std::string layerHeader(const MeshSequence& mesh)
{
    const int last = mesh.firstFrame + int(mesh.frames.size()) - 1;
    std::string out = "#usda 1.0\n(\n    defaultPrim = \"" + mesh.name + "\"\n";
    out += "    doc = \"A tracked mesh written by sculpt: fixed faces, points per frame\"\n";
    out += "    metersPerUnit = 0.001\n    upAxis = \"Z\"\n";
    out +=
        "    startTimeCode = " + std::to_string(mesh.firstFrame) + "\n    endTimeCode = " + std::to_string(last) + "\n";
    out += "    framesPerSecond = ";
    appendNumber(out, mesh.framesPerSecond);
    out += "\n    timeCodesPerSecond = ";
    appendNumber(out, mesh.framesPerSecond);
    return out + "\n)\n\n";
}

void appendFaces(std::string& out, const MeshSequence& mesh)
{
    out += "    int[] faceVertexCounts = ";
    appendList(out, mesh.triangles, [&](const auto&) { out += '3'; });
    out += "\n    int[] faceVertexIndices = [";
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            if (t || k) out += ", ";
            out += std::to_string(mesh.triangles[t][k]);
        }
    out += "]\n";
}

}  // namespace

void writeUsdMesh(const MeshSequence& mesh, const std::filesystem::path& path)
{
    checkMeshSequence(mesh, path);
    std::string out = layerHeader(mesh);
    out += "def Mesh \"" + mesh.name + "\"\n{\n";
    out += "    uniform token subdivisionScheme = \"none\"\n    uniform token orientation = \"rightHanded\"\n";
    appendFaces(out, mesh);
    appendTimeSamples(out, "point3f[] points", mesh, [&](std::size_t f) { return mesh.frames[f]; });
    appendTimeSamples(out, "vector3f[] velocities", mesh, [&](std::size_t f) { return velocities(mesh, f); });
    appendTimeSamples(out, "float3[] extent", mesh, [&](std::size_t f) { return extent(mesh.frames[f]); });
    if (!mesh.ids.empty()) {
        out += "    int[] primvars:sculptVertexId = ";
        appendList(out, mesh.ids, [&](std::uint32_t id) { out += std::to_string(id); });
        out += " (\n        interpolation = \"vertex\"\n    )\n";
    }
    out += "}\n";
    writeFileAtomically(path, out);
}

}  // namespace sculpt
