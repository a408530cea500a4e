// SPDX-License-Identifier: Apache-2.0
#include "core/io/mesh_sequence.h"

#include "core/base/errors.h"

namespace sculpt {

void checkMeshSequence(const MeshSequence& mesh, const std::filesystem::path& path)
{
    if (mesh.frames.empty()) throw InputError(path.string() + ": a mesh sequence needs at least one frame");
    const std::size_t vertices = mesh.frames.front().size();
    for (const auto& frame : mesh.frames)
        if (frame.size() != vertices)
            throw InputError(path.string() + ": every frame of a mesh sequence needs " + std::to_string(vertices) +
                             " vertices (one has " + std::to_string(frame.size()) + ")");
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t v : t)
            if (v >= vertices) throw InputError(path.string() + ": a triangle names vertex " + std::to_string(v));
    if (!mesh.ids.empty() && mesh.ids.size() != vertices)
        throw InputError(path.string() + ": " + std::to_string(mesh.ids.size()) + " vertex ids for " +
                         std::to_string(vertices) + " vertices");
}

}  // namespace sculpt
