// SPDX-License-Identifier: Apache-2.0
#include "core/io/mesh_frame.h"

#include <fstream>

namespace sculpt {

std::string meshFrameTag(MeshFrame frame) { return frame == MeshFrame::Lps ? "SPACE=LPS" : "SPACE=RAS"; }

TriangleMesh inOtherFrame(TriangleMesh mesh)
{
    for (auto& p : mesh.positions) p[0] = -p[0], p[1] = -p[1];
    for (auto& n : mesh.normals) n[0] = -n[0], n[1] = -n[1];
    return mesh;
}

std::optional<MeshFrame> declaredMeshFrame(const std::filesystem::path& path)
{
    constexpr std::size_t kHeaderBytes = 4096;  // a PLY header, an OBJ's first comments, an STL's 80 bytes
    std::ifstream in(path, std::ios::binary);
    std::string head(kHeaderBytes, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(in.gcount()));
    for (const MeshFrame frame : {MeshFrame::Lps, MeshFrame::Ras})
        if (head.find(meshFrameTag(frame)) != std::string::npos) return frame;
    return std::nullopt;
}

}  // namespace sculpt
