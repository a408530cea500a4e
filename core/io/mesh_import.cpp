#include "core/io/mesh_import.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/io/vtk_error_catcher.h"

#include <openvdb/tools/MeshToVolume.h>
#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// A binary STL is 84 bytes and 50 per triangle: a count the file does not match is refused
/// before VTK allocates for it. Text STLs open with "solid" and hold "facet".
void checkStlSize(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the mesh");
    char head[84] = {};
    in.read(head, sizeof head);
    const std::size_t size = std::size_t(fs::file_size(path));
    std::string start(head, std::size_t(in.gcount()));
    if (start.rfind("solid", 0) == 0 && start.find("facet") != std::string::npos) return;  // text
    if (size < 84)
        throw InputError(path.string() + ": too short for a binary STL (" + std::to_string(size) + " bytes)");
    const std::uint32_t count = std::uint32_t(std::uint8_t(head[80])) | std::uint32_t(std::uint8_t(head[81])) << 8 |
                                std::uint32_t(std::uint8_t(head[82])) << 16 |
                                std::uint32_t(std::uint8_t(head[83])) << 24;
    const double expected = 84.0 + 50.0 * double(count);
    if (double(size) < expected) {
        throw InputError(path.string() + ": truncated binary STL: it declares " + std::to_string(count) +
                         " triangles (" + formatNumber(expected) + " bytes) but holds " + std::to_string(size) +
                         " bytes");
    }
}

/// One element of a PLY header: how many, and its properties (sizes; a list's count and item
/// sizes, its items taken as at least 3).
struct PlyElement {
    std::string name;
    double count = 0.0;
    double minimalBytes = 0.0;  // per element, binary
    int scalars = 0;            // properties that are not lists
    bool listFirst = false;     // a single list property ("3 i j k")
    int lists = 0;
};

double plyTypeBytes(const std::string& type, const fs::path& path)
{
    static const std::map<std::string, double> sizes{{"char", 1},  {"int8", 1},    {"uchar", 1},  {"uint8", 1},
                                                     {"short", 2}, {"int16", 2},   {"ushort", 2}, {"uint16", 2},
                                                     {"int", 4},   {"int32", 4},   {"uint", 4},   {"uint32", 4},
                                                     {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    if (type.empty()) throw InputError(path.string() + ": corrupt PLY header (a property without a type: cut short?)");
    const auto found = sizes.find(type);
    if (found == sizes.end()) throw InputError(path.string() + ": unknown PLY property type '" + type + "'");
    return found->second;
}

/// A text PLY's body: a line per element with the words its properties need, and face indices
/// that name a vertex. vtkPLYReader crashes on less.
void checkPlyText(std::istream& in, const std::vector<PlyElement>& elements, const fs::path& path)
{
    double vertices = 0.0;
    for (const PlyElement& e : elements) {
        if (e.name == "vertex") vertices = e.count;
        for (double k = 0; k < e.count; ++k) {
            std::string line;
            if (!std::getline(in, line))
                throw InputError(path.string() + ": truncated PLY: " + e.name + " " + formatNumber(k) + " is missing");
            std::istringstream words(line);
            std::vector<double> values;
            for (double v; words >> v;) values.push_back(v);
            const bool face = e.listFirst && e.lists == 1 && e.scalars == 0;
            const std::size_t needed =
                face && !values.empty() ? std::size_t(std::max(0.0, values[0])) + 1 : std::size_t(e.scalars + e.lists);
            if (values.size() < needed)
                throw InputError(path.string() + ": truncated or corrupt PLY: " + e.name + " " + formatNumber(k));
            for (std::size_t i = 1; face && e.name == "face" && i < needed; ++i) {
                if (values[i] < 0 || values[i] >= vertices)
                    throw InputError(path.string() + ": PLY face " + formatNumber(k) + " names vertex " +
                                     formatNumber(values[i]) + " of " + formatNumber(vertices));
            }
        }
    }
}

/// A PLY's header read and what it declares checked against the body before vtkPLYReader
/// (which crashes on a cut file) sees it: a binary body must hold every fixed-size property and
/// a list of at least 3 per element; a text body is checked line by line.
void checkPlyHeader(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the mesh");
    std::string line, format;
    std::size_t headerBytes = 0;
    std::vector<PlyElement> elements;
    for (bool first = true;; first = false) {
        if (!std::getline(in, line) || headerBytes > 65536 || line.find('\0') != std::string::npos)
            throw InputError(path.string() + ": truncated or corrupt PLY header (no end_header)");
        headerBytes += line.size() + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (first && word != "ply") throw InputError(path.string() + ": not a PLY file (it must start with \"ply\")");
        if (word == "format") words >> format;
        if (word == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count) || e.count < 0 || e.count > 4e9 || e.count != std::floor(e.count))
                throw InputError(path.string() + ": corrupt PLY element line '" + line + "'");
            elements.push_back(e);
        }
        if (word == "property" && !elements.empty()) {
            PlyElement& e = elements.back();
            std::string type, countType, itemType;
            words >> type;
            if (type == "list") {
                words >> countType >> itemType;
                e.minimalBytes += plyTypeBytes(countType, path) + 3.0 * plyTypeBytes(itemType, path);
                e.listFirst = e.lists == 0 && e.scalars == 0;
                ++e.lists;
            } else {
                e.minimalBytes += plyTypeBytes(type, path);
                ++e.scalars;
            }
        }
        if (word == "end_header") break;
    }
    if (format == "ascii") return checkPlyText(in, elements, path);
    double needed = 0.0;
    for (const PlyElement& e : elements) needed += e.count * e.minimalBytes;
    const double body = double(fs::file_size(path)) - double(headerBytes);
    if (body < needed) {
        throw InputError(path.string() + ": truncated PLY: its elements need at least " + formatNumber(needed) +
                         " bytes; it holds " + formatNumber(std::max(0.0, body)));
    }
}

/// Runs a VTK mesh reader, then triangulates and merges coincident points.
TriangleMesh readWithVtk(vtkAlgorithm* reader, const fs::path& path)
{
    const VtkErrorCatcher catcher(reader);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(reader->GetOutputPort());
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(triangles->GetOutputPort());
    clean->PointMergingOn();
    clean->SetTolerance(0.0);
    clean->Update();
    if (catcher.caught()) throw InputError(path.string() + ": cannot read the mesh (corrupt or truncated?)");
    vtkPolyData* poly = clean->GetOutput();
    TriangleMesh mesh;
    mesh.positions.resize(size_t(poly->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
        double p[3];
        poly->GetPoint(i, p);
        mesh.positions[size_t(i)] = {float(p[0]), float(p[1]), float(p[2])};
    }
    vtkCellArray* polys = poly->GetPolys();
    mesh.triangles.resize(size_t(polys->GetNumberOfCells()));
    vtkIdType count;
    const vtkIdType* ids;
    size_t t = 0;
    for (polys->InitTraversal(); polys->GetNextCell(count, ids);) {
        if (count == 3) mesh.triangles[t++] = {std::uint32_t(ids[0]), std::uint32_t(ids[1]), std::uint32_t(ids[2])};
    }
    mesh.triangles.resize(t);
    return mesh;
}

/// The words of an OFF file's lines, comments (from '#') dropped, empty lines skipped.
class OffLines {
public:
    OffLines(std::istream& in, const fs::path& path) : mIn(in), mPath(path) {}
    /// The next line's words; empty at the end of the file.
    std::vector<std::string> next()
    {
        std::string line;
        while (std::getline(mIn, line)) {
            line = line.substr(0, line.find('#'));
            std::istringstream words(line);
            std::vector<std::string> out;
            for (std::string w; words >> w;) out.push_back(w);
            if (!out.empty()) return out;
        }
        return {};
    }
    /// `word` as a number. @throws InputError naming `what`.
    double number(const std::string& word, const std::string& what) const
    {
        std::size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(word, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != word.size() || !std::isfinite(value))
            throw InputError(mPath.string() + ": " + what + " has \"" + word + "\", not a number");
        return value;
    }

private:
    std::istream& mIn;
    const fs::path& mPath;
};

/// The header keyword of the OFF family: [ST][C][N]OFF (texture coordinates, colours and normals
/// follow each vertex's position and are ignored); 4OFF, nOFF and binary files are refused.
void checkOffKeyword(const std::string& word, const fs::path& path)
{
    std::string rest = word;
    for (const char* prefix : {"ST", "C", "N"}) {
        if (rest.rfind(prefix, 0) == 0) rest = rest.substr(std::string(prefix).size());
    }
    if (rest == "OFF") return;
    if (rest == "4OFF" || rest == "nOFF")
        throw InputError(path.string() + ": " + word + " holds points of more than 3 dimensions");
    throw InputError(path.string() + ": not an OFF file (it must start with OFF, COFF, NOFF or STOFF)");
}

/// OFF: the keyword, then "V F E", V vertex lines "x y z ...", F face lines "n i0 ... i(n-1) ..."
/// (fanned into triangles); '#' starts a comment.
TriangleMesh readOff(const fs::path& path)
{
    std::ifstream in(path);
    if (!in) throw InputError(path.string() + ": cannot read the mesh");
    OffLines lines(in, path);
    std::vector<std::string> header = lines.next();
    if (header.empty()) throw InputError(path.string() + ": empty OFF file");
    checkOffKeyword(header[0], path);
    if (header.size() > 1 && header[1] == "BINARY") throw InputError(path.string() + ": binary OFF is not supported");
    header.erase(header.begin());
    if (header.empty()) header = lines.next();  // the counts on the next line, as usual
    if (header.size() < 2) throw InputError(path.string() + ": corrupt OFF header (expected vertex and face counts)");
    const double vertices = lines.number(header[0], "the vertex count"),
                 faces = lines.number(header[1], "the face count");
    // Each vertex and face takes at least 6 characters of text: refuse counts the file cannot hold.
    const double size = double(fs::file_size(path));
    if (vertices < 0 || faces < 0 || vertices != std::floor(vertices) || faces != std::floor(faces) ||
        vertices * 6.0 > size || faces * 6.0 > size) {
        throw InputError(path.string() + ": the header claims " + header[0] + " vertices and " + header[1] +
                         " faces, which the file cannot hold");
    }
    TriangleMesh mesh;
    mesh.positions.resize(size_t(vertices));
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const std::vector<std::string> words = lines.next();
        if (words.size() < 3)
            throw InputError(path.string() + ": truncated vertex list (vertex " + std::to_string(v) + ")");
        for (int a = 0; a < 3; ++a)
            mesh.positions[v][size_t(a)] = float(lines.number(words[size_t(a)], "vertex " + std::to_string(v)));
    }
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (long long f = 0; f < (long long)faces; ++f) {
        const std::vector<std::string> words = lines.next();
        const std::string what = "face " + std::to_string(f);
        if (words.empty()) throw InputError(path.string() + ": truncated face list (" + what + ")");
        const double n = lines.number(words[0], what);
        if (n < 3 || n != std::floor(n) || double(words.size()) < n + 1)
            throw InputError(path.string() + ": corrupt " + what + " (a face needs 3 or more vertex indices)");
        std::vector<std::uint32_t> ids;
        for (std::size_t k = 1; k <= std::size_t(n); ++k) {
            const double id = lines.number(words[k], what);
            if (id < 0 || id >= vertices || id != std::floor(id))
                throw InputError(path.string() + ": " + what + " has vertex index " + words[k] + ", outside 0.." +
                                 std::to_string((long long)vertices - 1));
            ids.push_back(std::uint32_t(id));
        }
        for (std::size_t k = 1; k + 1 < ids.size(); ++k) triangles.push_back({ids[0], ids[k], ids[k + 1]});
    }
    mesh.triangles.resize(triangles.size());
    std::copy(triangles.begin(), triangles.end(), mesh.triangles.begin());
    return mesh;
}

}  // namespace

bool isMeshPath(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".off";
}

TriangleMesh readMesh(const fs::path& path)
{
    if (!fs::is_regular_file(path)) throw InputError(path.string() + ": no such file");
    const std::string ext = lowerExtension(path);
    TriangleMesh mesh = [&] {
        if (ext == ".off") return readOff(path);
        if (ext == ".obj") {
            vtkNew<vtkOBJReader> reader;
            reader->SetFileName(path.string().c_str());
            return readWithVtk(reader, path);
        }
        if (ext == ".ply") {
            checkPlyHeader(path);
            vtkNew<vtkPLYReader> reader;
            reader->SetFileName(path.string().c_str());
            return readWithVtk(reader, path);
        }
        if (ext == ".stl") {
            checkStlSize(path);
            vtkNew<vtkSTLReader> reader;
            reader->SetFileName(path.string().c_str());
            return readWithVtk(reader, path);
        }
        throw InputError(path.string() + ": unknown mesh format '" + ext + "' (expected .obj, .ply, .stl or .off)");
    }();
    if (mesh.triangles.empty()) throw InputError(path.string() + ": no triangles in the mesh");
    for (const auto& p : mesh.positions) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            throw InputError(path.string() + ": a vertex has non-finite coordinates");
        }
    }
    return mesh;
}

MeshImportReport inspectMesh(const TriangleMesh& mesh)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = t[size_t(e)], b = t[size_t((e + 1) % 3)];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    }
    MeshImportReport report;
    report.triangles = mesh.triangles.size();
    for (const auto& [edge, count] : edges) {
        if (count == 1) ++report.boundaryEdges;
        if (count > 2) ++report.nonManifoldEdges;
    }
    return report;
}

double voxelSizeFor(const TriangleMesh& mesh, double voxelsAcross)
{
    openvdb::BBoxd box;
    for (const auto& p : mesh.positions) box.expand(openvdb::Vec3d(p[0], p[1], p[2]));
    const double longest = box.extents()[box.maxExtent()];
    return longest > 0.0 ? longest / voxelsAcross : 1.0;
}

namespace {

/// OpenVDB's interrupter asking our Progress: MeshToVolume checks it between its passes and
/// inside its parallel loops (from several threads: hence the atomics).
struct ProgressInterrupter : openvdb::util::NullInterrupter {
    explicit ProgressInterrupter(const Progress& p) : progress(p) {}
    bool wasInterrupted(int percent = -1) override
    {
        if (percent >= 0) fraction = percent / 100.0;
        if (!stopped && progress && !progress(fraction)) stopped = true;
        return stopped;
    }
    const Progress& progress;
    std::atomic<double> fraction{0.0};
    std::atomic<bool> stopped{false};
};

}  // namespace

FieldImage meshToField(const TriangleMesh& mesh, double h, const Progress& progress)
{
    if (!(h > 0.0) || !std::isfinite(h))
        throw InputError("voxel size must be a positive number (got " + formatNumber(h) + ")");
    double area = 0.0;
    std::vector<openvdb::Vec3s> points(mesh.positions.size());
    for (size_t i = 0; i < points.size(); ++i)
        points[i] = openvdb::Vec3s(mesh.positions[i][0], mesh.positions[i][1], mesh.positions[i][2]);
    std::vector<openvdb::Vec3I> triangles(mesh.triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        triangles[i] = openvdb::Vec3I(t[0], t[1], t[2]);
        area += 0.5 * double((points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).length());
    }
    const double halfWidth = FieldImage::kDefaultHalfWidthVoxels;
    // The band holds about area / h^2 x (2 half width) voxels at ~5 bytes each, leaves included.
    requireMemory(area / (h * h) * 2.0 * halfWidth * 8.0, "the mesh at voxel size " + formatNumber(h));
    auto xform = openvdb::math::Transform::createLinearTransform(h);
    std::vector<openvdb::Vec4I> quads;
    ProgressInterrupter interrupter(progress);
    auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(interrupter, *xform, points, triangles, quads,
                                                                   float(halfWidth));
    if (interrupter.stopped) throw Cancelled();
    if (grid->activeVoxelCount() == 0)
        throw InputError("the mesh produced no surface at voxel size " + formatNumber(h));
    return FieldImage(grid);
}

}  // namespace sculpt
