// SPDX-License-Identifier: Apache-2.0
// The Python module `sculpt`: documents made, opened, imported, edited, measured and saved by the
// same code as the `sculpt` program. Long work runs without the GIL and stops on Ctrl-C
// (python_progress.h); a failed edit leaves the document as it was.

#include "core/base/errors.h"
#include "core/field/document_text.h"
#include "core/io/vdb_file.h"
#include "core/io/vdb_layout.h"
#include "core/mesh/incremental_mesher.h"
#include "core/motion/morph_verdict.h"
#include "core/primitives/analytic_shapes.h"
#include "core/solids/hollow.h"
#include "sculpt/python/python_progress.h"
#include "sculpt/session/document.h"
#include "sculpt/session/document_info.h"
#include "sculpt/session/model_filter.h"
#include "sculpt/session/morph_run.h"
#include "sculpt/session/piece_meshes.h"
#include "sculpt/session/script_replay.h"
#include "sculpt/session/shape_import.h"
#include "sculpt/session/stroke_script.h"

#include <unistd.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <filesystem>
#include <sculpt_version.h>

namespace py = pybind11;
using namespace py::literals;

namespace sculpt::python {

namespace {

namespace fs = std::filesystem;

/// A document as Python holds it: its pieces (the first is the one edits change) and the file's
/// other grids (the scan it keeps, masks), as `sculpt` reads and writes them.
struct PyDocument {
    VdbPieces file;
    std::string name;          ///< where it came from, for messages
    bool madeAsField = false;  ///< a new shape or an import: written as `sculpt new` and `import` write it

    FieldImage& edited() { return file.pieces.front().field; }
};

PyDocument documentOf(FieldImage field, std::string name, VdbCompanions companions = {})
{
    PieceLook look;
    look.name = "surface";
    VdbPieces file;
    file.pieces.emplace_back(look, std::move(field));
    file.companions = std::move(companions);
    return {std::move(file), std::move(name), true};
}

/// Writes the document as the program writes the same one (a lone field with no look of its own
/// as a field, else its pieces).
void write(const PyDocument& document, const fs::path& path)
{
    if (document.madeAsField && document.file.pieces.size() == 1)
        writeFieldImage(document.file.pieces.front().field, path, document.file.companions);
    else writeVdbPieces(document.file.pieces, path, document.file.companions);
}

py::object fromJson(const nlohmann::json& json) { return py::module_::import("json").attr("loads")(json.dump()); }

PyDocument newDocument(const std::string& shape, double radius, double minorRadius, double voxelSize,
                       const std::string& units)
{
    if (const std::string problem = unitsProblem(units); !problem.empty())
        throw InputError("units: the length unit cannot be: " + problem);
    const AnalyticSdf sdf = startingShapeSdf(shape, radius, minorRadius);
    FieldImage field = [&] {
        py::gil_scoped_release release;
        return rasterizeSdf(sdf, voxelSize);
    }();
    field.setUnits(units);
    return documentOf(std::move(field), sdf.description);
}

PyDocument openDocument(const fs::path& path, const std::string& grid)
{
    py::gil_scoped_release release;
    return {readVdbPieces(path, grid), path.string(), false};
}

/// `raw_dims` and the other raw_ keywords: a file of bare samples (sculpt import --raw-dims ...).
std::optional<RawLayout> rawLayout(const std::optional<std::array<int, 3>>& dims, const std::string& type,
                                   const std::array<double, 3>& spacing, const std::array<double, 3>& origin,
                                   bool bigEndian, std::size_t header)
{
    if (!dims) return std::nullopt;
    RawLayout raw;
    raw.dims = openvdb::Coord((*dims)[0], (*dims)[1], (*dims)[2]);
    raw.type = type;
    raw.spacing = openvdb::Vec3d(spacing[0], spacing[1], spacing[2]);
    raw.origin = openvdb::Vec3d(origin[0], origin[1], origin[2]);
    raw.bigEndian = bigEndian;
    raw.headerBytes = header;
    return raw;
}

PyDocument importFile(const fs::path& path, std::optional<double> voxelSize, std::optional<double> iso,
                      std::optional<int> label, bool labels, double smooth, bool largestComponent, bool keepScan,
                      std::optional<bool> antialias, const std::optional<std::array<int, 6>>& crop,
                      const std::optional<std::array<int, 3>>& rawDims, const std::string& rawType,
                      const std::array<double, 3>& rawSpacing, const std::array<double, 3>& rawOrigin,
                      bool rawBigEndian, std::size_t rawHeader, const py::object& progress)
{
    ImportOptions options;
    if (crop) {
        const std::array<int, 6>& c = *crop;
        options.crop = openvdb::CoordBBox(openvdb::Coord(c[0], c[1], c[2]), openvdb::Coord(c[3], c[4], c[5]));
    }
    options.raw = rawLayout(rawDims, rawType, rawSpacing, rawOrigin, rawBigEndian, rawHeader);
    options.voxelSize = voxelSize;
    options.iso = iso;
    options.label = label;
    options.smoothSigma = smooth;
    options.largestComponent = largestComponent;
    options.keepScan = keepScan;
    options.antiAliasMask = antialias;
    ImportReport report;
    PyDocument document = PythonProgress(progress).run([&](const Progress& p) {
        if (labels) return PyDocument{{importLabelPieces(path, options, report, p), {}, {}}, path.string(), false};
        return documentOf(importShape(path, options, report, p), path.string());
    });
    if (report.keptScan) document.file.companions.grids.push_back(report.keptScan);
    for (const std::string& warning : report.warnings)
        PyErr_WarnEx(PyExc_UserWarning, (path.string() + ": " + warning).c_str(), 1);
    return document;
}

void save(const PyDocument& document, const fs::path& path)
{
    py::gil_scoped_release release;
    write(document, path);
}

const Piece& pieceNamed(const PyDocument& document, const std::optional<std::string>& name)
{
    if (!name) return document.file.pieces.front();
    for (const Piece& piece : document.file.pieces)
        if (piece.name == *name) return piece;
    throw InputError(document.name + ": no piece named '" + *name + "'");
}

/// (vertices (n, 3) float32, triangles (m, 3) uint32) of a piece's welded surface, placed.
py::tuple mesh(const PyDocument& document, const std::optional<std::string>& name)
{
    const Piece& piece = pieceNamed(document, name);
    const TriangleMesh surface = [&] {
        py::gil_scoped_release release;
        return placedMesh(meshLevelSet(piece.field), piece.placement);
    }();
    py::array_t<float> vertices({py::ssize_t(surface.positions.size()), py::ssize_t(3)});
    py::array_t<std::uint32_t> triangles({py::ssize_t(surface.triangles.size()), py::ssize_t(3)});
    auto v = vertices.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < v.shape(0); ++i)
        for (int c = 0; c < 3; ++c) v(i, c) = surface.positions[std::size_t(i)][c];
    auto t = triangles.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < t.shape(0); ++i)
        for (int c = 0; c < 3; ++c) t(i, c) = surface.triangles[std::size_t(i)][c];
    return py::make_tuple(vertices, triangles);
}

/// The keys of `sculpt info --json` (less the report's command and outputs), measured on the
/// document as it would be saved.
py::object info(const PyDocument& document, double thickness)
{
    static std::atomic<unsigned> counter{0};
    const fs::path file = fs::temp_directory_path() /
                          ("sculpt-info-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".vdb");
    nlohmann::json report;
    {
        py::gil_scoped_release release;
        write(document, file);
        try {
            report = documentInfo(document.file, scanVdbLayout(file), document.name, thickness);
        } catch (...) {
            fs::remove(file);
            throw;
        }
        fs::remove(file);
    }
    return fromJson(report);
}

/// Runs `filter` on the edited piece; the document changes only if it succeeds.
void filter(PyDocument& document, const ModelFilter& filter, const py::object& progress)
{
    FieldImage result = PythonProgress(progress).run(
        [&](const Progress& p) { return applyFilter(document.edited().deepCopy(), filter, document.name, p); });
    document.edited() = std::move(result);
}

py::dict apply(PyDocument& document, const fs::path& script, const py::object& progress)
{
    const StrokeScript strokes = readStrokeScript(script);
    std::vector<Piece> copies;  // replayed on copies: a failing event leaves the document as it was
    for (const Piece& piece : document.file.pieces) copies.emplace_back(piece, piece.field.deepCopy());
    ReplayReport done;
    std::vector<Piece> result = PythonProgress(progress).run([&](const Progress& p) {
        Document replayed(std::move(copies), {}, {}, PieceMeshes::None);
        done = replayScript(replayed, strokes, script.string(), p);
        return replayed.piecesAsFiled();
    });
    document.file.pieces = std::move(result);
    return py::dict("strokes"_a = done.strokes, "stamps"_a = done.stamps, "undos"_a = done.undos,
                    "redos"_a = done.redos, "piece_edits"_a = done.pieceEdits);
}

py::dict morphFrames(const PyDocument& document, const fs::path& target, int frames, bool keepVolume, bool align,
                     std::optional<double> tolerance, std::optional<int> maxSteps, const py::object& progress)
{
    MorphOptions options;
    options.frames = frames;
    options.keepVolume = keepVolume;
    options.align = align;
    if (tolerance) options.toleranceVoxels = *tolerance;
    if (maxSteps) options.maxSteps = *maxSteps;
    MorphRun run = PythonProgress(progress).run(
        [&](const Progress& p) { return sculpt::morphInto(document.file.pieces.front().field, target, options, p); });
    py::list documents;
    for (FieldImage& frame : run.frames) documents.append(documentOf(std::move(frame), target.string()));
    const MorphSummary& s = run.summary;
    return py::dict("frames"_a = documents, "steps"_a = s.steps, "morph_time"_a = s.duration,
                    "final_distance"_a = s.finalDistanceWorld, "verdict"_a = morphVerdict(s, run.target->voxelSize()),
                    "frame_volumes"_a = s.frameVolumes);
}

ModelFilter hollowFilter(double thickness, const std::string& side, double closing, bool drain, double drainRadius,
                         const std::array<double, 3>& up)
{
    ModelFilter f{ModelFilter::Kind::Hollow};
    f.hollow.thicknessWorld = thickness;
    f.hollow.side = shellSideFromName(side);
    f.hollow.closingWorld = closing;
    f.drain = drain;
    f.drainRadiusWorld = drainRadius;
    f.up = openvdb::Vec3d(up[0], up[1], up[2]);
    return f;
}

}  // namespace

}  // namespace sculpt::python

PYBIND11_MODULE(sculpt, m)
{
    using namespace sculpt;
    using namespace sculpt::python;
    m.doc() = "Volumetric clay sculpting on sparse signed-distance grids: the engine of the sculpt "
              "program and window, for scripts and notebooks.";
    m.attr("__version__") = SCULPT_VERSION;
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
    py::register_exception<Cancelled>(m, "Cancelled");

    py::class_<PyDocument>(m, "Document",
                           "A document: its pieces (the first is the one edited) and the grids its "
                           "file keeps beside them.")
        .def_property_readonly(
            "pieces",
            [](const PyDocument& d) {
                std::vector<std::string> names;
                for (const Piece& piece : d.file.pieces) names.push_back(piece.name);
                return names;
            },
            "The pieces' names.")
        .def("save", &save, "path"_a, "Writes the document (.vdb), atomically.")
        .def("mesh", &mesh, "piece"_a = py::none(),
             "The surface of a piece (default: the first) as (vertices (n, 3) float32, triangles (m, 3) uint32), "
             "welded and closed, where the piece is placed.")
        .def("info", &info, "thickness"_a = 0.0,
             "The measures `sculpt info --json` prints, as a dict; with thickness > 0, the thinnest wall under it.")
        .def(
            "smooth",
            [](PyDocument& d, int iterations, bool keepVolume, const py::object& progress) {
                filter(d, {ModelFilter::Kind::Smooth, iterations, keepVolume, 0.0}, progress);
            },
            "iterations"_a = 10, "keep_volume"_a = false, "progress"_a = py::none(), "Mean-curvature smoothing.")
        .def(
            "offset",
            [](PyDocument& d, double distance, const py::object& progress) {
                filter(d, {ModelFilter::Kind::Offset, 0, false, distance}, progress);
            },
            "distance"_a, "progress"_a = py::none(), "Moves the surface along its normal (> 0 grows).")
        .def(
            "hollow",
            [](PyDocument& d, double thickness, const std::string& side, double closing, bool drain, double drainRadius,
               const std::array<double, 3>& up, const py::object& progress) {
                filter(d, hollowFilter(thickness, side, closing, drain, drainRadius, up), progress);
            },
            "thickness"_a, "side"_a = "inside", "closing"_a = 0.0, "drain"_a = false, "drain_radius"_a = 1.0,
            "up"_a = std::array<double, 3>{0.0, 0.0, 1.0}, "progress"_a = py::none(),
            "A shell of this wall thickness, with drain holes under the cavities if asked.")
        .def(
            "remove_islands",
            [](PyDocument& d, double under, const py::object& progress) {
                ModelFilter f{ModelFilter::Kind::RemoveIslands};
                f.minIslandVolume = under;
                filter(d, f, progress);
            },
            "under"_a, "progress"_a = py::none(), "Removes the disjoint solids of less volume.")
        .def("apply", &apply, "script"_a, "progress"_a = py::none(),
             "Replays a stroke script (sculpt apply); returns what it counted.")
        .def("morph", &morphFrames, "target"_a, "frames"_a = 10, "keep_volume"_a = false, "align"_a = false,
             "tolerance"_a = py::none(), "max_steps"_a = py::none(), "progress"_a = py::none(),
             "Morphs the first piece into the shape in a file (a document, scan or mesh); returns the frames as "
             "documents and the morph's summary.");

    m.def("new", &newDocument, "shape"_a = "sphere", "radius"_a = 50.0, "minor_radius"_a = 0.0, "voxel_size"_a = 0.5,
          "units"_a = FieldImage::kDefaultUnits,
          "A new document holding a sphere, box or torus centred at the origin (sculpt new).");
    m.def("open", &openDocument, "path"_a, "grid"_a = "", "Reads a .vdb document.");
    m.def("import_file", &importFile, "path"_a, "voxel_size"_a = py::none(), "iso"_a = py::none(),
          "label"_a = py::none(), "labels"_a = false, "smooth"_a = 0.0, "largest_component"_a = false,
          "keep_scan"_a = true, "antialias"_a = py::none(), "crop"_a = py::none(), "raw_dims"_a = py::none(),
          "raw_type"_a = "uint8", "raw_spacing"_a = std::array<double, 3>{1.0, 1.0, 1.0},
          "raw_origin"_a = std::array<double, 3>{0.0, 0.0, 0.0}, "raw_big_endian"_a = false, "raw_header"_a = 0,
          "progress"_a = py::none(),
          "A scan (NIfTI, NRRD, MetaImage, INRIMAGE, DICOM) or a mesh as a document, with sculpt import's options.");
}
