// SPDX-License-Identifier: Apache-2.0
// Pieces: the contact query through local boxes beside sampling every vertex, and a label map's
// import as pieces beside one label's, in one run.
// Run: build/tests/bench/pieces_bench
//
// BM_Contact/P/B : CGAL's cow against its figure eight (libcgal-demo), each 256 voxels across,
//                  the cow moved along x from touching (P = 0) to centred on the eight (P = 100);
//                  B = 1: overlap() through the local boxes, B = 0: every vertex of each sampled in
//                  the other's field (the brute force; both parallel). Counters: vertices sampled,
//                  vertices found inside.
// BM_RigidMove/R : one step of a move in the window: the contact bisection against a piece apart
//                  (freeFraction with the boxes found at the move's start; they do not meet) and
//                  the move as a document's undo step (Document::movePiece), for a moved ball of R
//                  voxels radius (0.5 mm voxels).
//                  Counter: the moved ball's active voxels. Should not grow with R.
// BM_LabelImport/M/A : M = 0 mricron-data's JHU white-matter atlas at 1 mm (182 x 218 x 182, 48
//                  labels), M = 1 CGAL's liver segmentation (liver.inr.gz, 438 x 353 x 165, 4
//                  labels), M = 2 the limits' label map: 2,000 labels of 2 x 2 x 2 samples side by
//                  side (26 x 26 x 24 int16, written here): A = 1 every label as a piece
//                  (importLabelPieces), A = 0 one label (the atlas's 3, the liver's 255, the
//                  map's 1000: importShape --label, read and converted from the whole map).
//                  Counter: pieces.

#include "core/field/placed_box.h"
#include "core/io/mesh_import.h"
#include "core/mesh/incremental_mesher.h"
#include "core/pieces/contact.h"
#include "core/primitives/analytic_shapes.h"
#include "core/scan/label_map_files.h"
#include "sculpt/session/document.h"
#include "sculpt/session/shape_import.h"
#include "tests/support/cgal_data.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <array>
#include <filesystem>
#include <memory>

namespace {

using namespace sculpt;
using openvdb::Mat4d;
using openvdb::Vec3d;

struct Body {
    FieldImage field;
    IncrementalMesher mesher;
    TriangleMesh welded;
    openvdb::BBoxd box;
};

std::unique_ptr<Body> bodyOf(const std::string& name)
{
    const std::filesystem::path path = test::cgalMesh(name);
    if (path.empty()) return nullptr;
    const TriangleMesh mesh = readMesh(path);
    auto body = std::make_unique<Body>(Body{meshToField(mesh, voxelSizeFor(mesh)), IncrementalMesher(), {}, {}});
    body->mesher.rebuild(body->field);
    body->welded = body->mesher.weldedMesh();
    for (const auto& p : body->welded.positions) body->box.expand(Vec3d(p[0], p[1], p[2]));
    return body;
}

/// Vertices of `a` (placed at `pa`) inside `b`, every one sampled.
std::size_t everyVertexInside(const Body& a, const Mat4d& pa, const Body& b)
{
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, a.welded.positions.size(), 4096), std::size_t(0),
        [&](const tbb::blocked_range<std::size_t>& range, std::size_t inside) {
            const auto accessor = b.field.grid().getConstAccessor();
            for (std::size_t v = range.begin(); v != range.end(); ++v) {
                const auto& p = a.welded.positions[v];
                const Vec3d index = b.field.grid().transform().worldToIndex(pa.transform(Vec3d(p[0], p[1], p[2])));
                inside += openvdb::tools::BoxSampler::sample(accessor, index) < 0.0;
            }
            return inside;
        },
        [](std::size_t x, std::size_t y) { return x + y; });
}

void BM_Contact(benchmark::State& state)
{
    static const auto cow = bodyOf("cow.off"), eight = bodyOf("eight.off");
    if (!cow || !eight) return state.SkipWithError("install libcgal-demo");
    // From the cow's +x side touching the eight's -x side to their centres together.
    const double touching = eight->box.min().x() - cow->box.max().x();
    const double centred = eight->box.getCenter().x() - cow->box.getCenter().x();
    const double p = double(state.range(0)) / 100.0;
    Mat4d placement = Mat4d::identity();
    placement.setTranslation(Vec3d((1.0 - p) * touching + p * centred,
                                   eight->box.getCenter().y() - cow->box.getCenter().y(),
                                   eight->box.getCenter().z() - cow->box.getCenter().z()));
    const bool boxes = state.range(1) == 1;
    Penetration found;
    for (auto _ : state) {
        if (boxes) {
            found = overlap({cow->field, cow->mesher, placement}, {eight->field, eight->mesher});
        } else {
            found.sampledVertices = cow->welded.positions.size() + eight->welded.positions.size();
            found.penetratingVertices =
                everyVertexInside(*cow, placement, *eight) + everyVertexInside(*eight, placement.inverse(), *cow);
        }
        benchmark::DoNotOptimize(found);
    }
    state.counters["sampled"] = double(found.sampledVertices);
    state.counters["inside"] = double(found.penetratingVertices);
}
BENCHMARK(BM_Contact)
    ->ArgsProduct({{0, 25, 50, 100}, {0, 1}})
    ->ArgNames({"overlap%", "boxes"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RigidMove(benchmark::State& state)
{
    const double radius = 0.5 * double(state.range(0));
    std::vector<Piece> pieces{{{"moved"}, makeSphere(radius, 0.5)}, {{"apart"}, makeSphere(8.0, 0.5)}};
    pieces[1].placement.setTranslation(Vec3d(radius + 40.0, 0.0, 0.0));
    Document document(std::move(pieces));
    const DocumentPiece &moved = document.pieces()[0], &apart = document.pieces()[1];
    // The boxes a move in the window finds once, at its start.
    const openvdb::BBoxd movedBox = leafWorldBox(moved.session->field());
    const ContactBody other{apart.session->field(), *apart.session->mesher(), apart.look.placement,
                            leafWorldBox(apart.session->field())};
    bool there = false;
    for (auto _ : state) {
        const Mat4d from = document.pieces()[0].look.placement;
        Mat4d to = from;
        to.setTranslation(Vec3d((there = !there) ? 1.0 : 0.0, 0.0, 0.0));  // to and fro: never nearer
        const auto along = [&](double t) {
            Mat4d m = from;
            m.setTranslation(from.getTranslation() * (1.0 - t) + to.getTranslation() * t);
            return m;
        };
        const double free =
            freeFraction({moved.session->field(), *moved.session->mesher(), from, movedBox}, other, along);
        document.movePiece(0, along(free), {}, "move");
    }
    state.counters["voxels"] = double(document.pieces()[0].session->field().grid().activeVoxelCount());
}
BENCHMARK(BM_RigidMove)->Arg(16)->Arg(64)->Arg(256)->ArgName("radius")->Unit(benchmark::kMicrosecond);

/// The README's label map at its stated cost: 2,000 labels of 2 x 2 x 2 samples, side by side.
std::filesystem::path twoThousandLabels()
{
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "pieces_bench_2000_labels.nii";
    LabelMap map;
    map.lattice.dims = openvdb::Coord(26, 26, 24);
    for (int k = 0; k < 24; ++k)
        for (int j = 0; j < 26; ++j)
            for (int i = 0; i < 26; ++i) {
                const int block = i / 2 + 13 * (j / 2 + 13 * (k / 2));
                map.labels.push_back(std::uint16_t(block < 2000 ? block + 1 : 0));
            }
    writeLabelMap(map, path);
    return path;
}

void BM_LabelImport(benchmark::State& state)
{
    const int which = int(state.range(0));
    const std::filesystem::path map = which == 2   ? twoThousandLabels()
                                      : which == 1 ? test::cgalData("images/liver.inr.gz")
                                                   : "/usr/share/mricron/templates/JHU-WhiteMatter-labels-1mm.nii.gz";
    if (map.empty() || !std::filesystem::exists(map)) return state.SkipWithError("install mricron-data, libcgal-demo");
    std::size_t pieces = 1;
    for (auto _ : state) {
        ImportReport report;
        if (state.range(1) == 1) {
            pieces = importLabelPieces(map, {}, report).size();
        } else {
            ImportOptions one;
            one.label = std::array<int, 3>{3, 255, 1000}[which];
            benchmark::DoNotOptimize(importShape(map, one, report).voxelSize());
        }
    }
    state.counters["pieces"] = double(pieces);
    if (which == 2) std::filesystem::remove(map);
}
BENCHMARK(BM_LabelImport)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->ArgNames({"map", "all"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace
