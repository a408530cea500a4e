// SPDX-License-Identifier: Apache-2.0
// One libFuzzer target per input the programs parse, chosen at build time by SCULPT_FUZZ_TARGET
// (see tests/fuzz/CMakeLists.txt and scripts/fuzz.sh). Each writes the fuzzer's bytes to a file
// and runs what the program runs on such a file. An InputError is the right answer to bad bytes;
// any other exception, a crash, a sanitizer report, a hang or a runaway allocation is a finding.

#include "core/base/errors.h"
#include "core/base/isolated_call.h"
#include "core/io/mesh_import.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "core/primitives/scene_file.h"
#include "core/scan/kept_scan.h"
#include "sculpt/session/document.h"
#include "sculpt/session/script_replay.h"
#include "sculpt/session/shape_import.h"
#include "sculpt/session/stroke_script.h"

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace sculpt;

void importScan(const fs::path& path)
{
    ImportReport report;
    importShape(path, {}, report);
}

/// Read, inspected and converted coarsely (32 voxels across): what import does, kept fast.
void importMesh(const fs::path& path)
{
    const TriangleMesh mesh = readMesh(path);
    inspectMesh(mesh);
    meshToField(mesh, voxelSizeFor(mesh, 32.0));
}

void openDocument(const fs::path& path) { readVdbDocument(path); }

/// A document of pieces as `sculpt info` and the window read it: every piece's values, look,
/// placement, mask and seal, and the scan it keeps (as `import DOC.vdb` reads it again).
void openPieces(const fs::path& path)
{
    const VdbPieces read = readVdbPieces(path);
    if (findKeptScan(read.companions.grids)) readKeptScan(path);
}

/// A label map imported a piece per label, as `import --labels` does.
void importLabels(const fs::path& path)
{
    ImportReport report;
    importLabelPieces(path, {}, report);
}

/// Replayed on a small ball: stroke limits are what keep absurd numbers from running for hours.
void replayStrokes(const fs::path& path)
{
    const StrokeScript script = readStrokeScript(path);
    Document document(makeSphere(10.0, 1.0), {}, {}, PieceMeshes::None);
    replayScript(document, script, path.string());
}

/// Replayed on two small pieces, so that cuts, mask selections, drains and piece edits all land.
void replayCuts(const fs::path& path)
{
    const StrokeScript script = readStrokeScript(path);
    std::vector<Piece> pieces{{{"ball", {0.8f, 0.8f, 0.8f}}, makeSphere(10.0, 1.0)},
                              {{"box", {0.2f, 0.4f, 0.8f}}, makeBox(4.0, 1.0)}};
    Document document(std::move(pieces), {}, {}, PieceMeshes::None);
    replayScript(document, script, path.string());
}

void readSceneFile(const fs::path& path) { readScene(path); }

struct Target {
    const char* name;
    const char* file;  ///< the input's name, inside a directory of its own
    void (*run)(const fs::path&);
};

const Target kTargets[] = {
    {"nifti", "input.nii", importScan},     {"nifti_gz", "input.nii.gz", importScan},
    {"nrrd", "input.nrrd", importScan},     {"metaimage", "input.mha", importScan},
    {"dicom", "input.dcm", importScan},  // a single slice is refused, a multi-frame file read
    {"ply", "input.ply", importMesh},       {"stl", "input.stl", importMesh},
    {"obj", "input.obj", importMesh},       {"off", "input.off", importMesh},
    {"vdb", "input.vdb", openDocument},     {"strokes", "input.json", replayStrokes},
    {"scene", "input.json", readSceneFile}, {"pieces", "input.vdb", openPieces},
    {"labels", "input.nii", importLabels},  {"cuts", "input.json", replayCuts},
};

const Target& chosenTarget()
{
    for (const Target& target : kTargets) {
        if (std::strcmp(target.name, SCULPT_FUZZ_TARGET) == 0) return target;
    }
    std::abort();  // a target CMake knows and this table does not
}

fs::path inputPath()
{
    static const fs::path path = [] {
        const fs::path dir = fs::temp_directory_path() / ("sculpt-fuzz-" + std::to_string(getpid()));
        const fs::path file = dir / chosenTarget().file;
        fs::create_directories(file.parent_path());
        return file;
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/)
{
    // The decoders run here, not in a child: a crash in one must be the fuzzer's finding, not a
    // refusal the isolation makes of it.
    setIsolation(false);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const fs::path path = inputPath();
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    try {
        chosenTarget().run(path);
    } catch (const sculpt::InputError&) {
        // The answer to bad bytes: one line naming the file, exit 2.
    }
    return 0;
}
