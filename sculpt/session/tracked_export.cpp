// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/tracked_export.h"

#include "core/base/atomic_file.h"
#include "core/base/written_outputs.h"
#include "core/io/gltf_morph_file.h"
#include "core/io/mesh_file.h"
#include "core/io/point_cache_file.h"
#include "core/io/usd_mesh_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace sculpt {

namespace fs = std::filesystem;

std::string segmentName(std::size_t index)
{
    char name[32];
    std::snprintf(name, sizeof(name), "segment_%04zu", index);
    return name;
}

fs::path segmentPath(const fs::path& directory, std::size_t index, const std::string& extension)
{
    return directory / (segmentName(index) + "." + extension);
}

std::vector<fs::path> writeTrackedSequence(const TrackedSequence& sequence, const fs::path& directory, double fps)
{
    WrittenOutputs outputs;  // all of it, or none of it
    outputs.directory(directory);
    std::vector<fs::path> written;
    const auto next = [&](std::size_t s, const char* extension) -> const fs::path& {
        written.push_back(segmentPath(directory, s, extension));
        return outputs.file(written.back());
    };
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t s = 0; s < sequence.segments().size(); ++s) {
        const TrackedSegment& segment = sequence.segments()[s];
        const TriangleMesh rest = segment.frameMesh(0);
        writeMesh(rest, next(s, "ply"));
        writePointCache({float(segment.firstFrame), 1.0f, segment.positions}, next(s, "pc2"));
        const MeshSequence animated{segmentName(s),     rest.triangles, segment.positions, fps,
                                    segment.firstFrame, segment.ids};
        writeGltfMorph(animated, next(s, "glb"));
        writeUsdMesh(animated, next(s, "usda"));
        list.push_back({{"segment", s},
                        {"first_frame", segment.firstFrame},
                        {"frames", segment.positions.size()},
                        {"vertices", segment.ids.size()},
                        {"triangles", segment.triangles.size()}});
    }
    const nlohmann::json summary{{"format", "sculpt-tracked-sequence"},
                                 {"version", 1},
                                 {"frames", sequence.frameCount()},
                                 {"frames_per_second", fps},
                                 {"segments", list}};
    written.push_back(directory / "segments.json");
    writeFileAtomically(outputs.file(written.back()), summary.dump(2) + "\n");
    outputs.keep();
    return written;
}

}  // namespace sculpt
