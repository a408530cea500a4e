// SPDX-License-Identifier: Apache-2.0
// checkNrrdHeader (header_checks.h): a NRRD's text header and the samples it says it has; and
// nrrdPlacement (scan_frame.h): where the header places them.
#include "core/base/errors.h"
#include "core/scan/header_checks.h"
#include "core/scan/header_text.h"
#include "core/scan/sample_files.h"
#include "core/scan/scan_frame.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxNrrdDimension = 16;  // NRRD's own NRRD_DIM_MAX

double typeBytes(const std::string& type)
{
    static const std::map<std::string, double> bytes{
        {"uchar", 1},   {"unsigned char", 1}, {"uint8", 1},          {"uint8_t", 1}, {"signed char", 1},
        {"int8", 1},    {"int8_t", 1},        {"char", 1},           {"short", 2},   {"int16", 2},
        {"int16_t", 2}, {"ushort", 2},        {"unsigned short", 2}, {"uint16", 2},  {"uint16_t", 2},
        {"int", 4},     {"int32", 4},         {"int32_t", 4},        {"uint", 4},    {"unsigned int", 4},
        {"uint32", 4},  {"uint32_t", 4},      {"float", 4},          {"double", 8}};
    const auto found = bytes.find(type);
    return found == bytes.end() ? 0.0 : found->second;
}

/// A per-axis field without its "none" entries (axes that are not in space).
std::string withoutNone(std::string text)
{
    for (auto at = text.find("none"); at != std::string::npos; at = text.find("none")) text.replace(at, 4, " ");
    return text;
}

/// The numbers of every field that places the samples: all finite, spacings usable.
void checkPlacement(const HeaderFields& fields, const std::string& where)
{
    for (const char* key : {"spacings", "thicknesses", "axis mins", "axis maxs", "space origin", "old min", "old max"})
        finiteNumbers(withoutNone(fields.text(key)), where, key);
    requireSpacings(finiteNumbers(withoutNone(fields.text("spacings")), where, "spacings"), where, "spacings");
    const std::vector<double> directions =
        finiteNumbers(withoutNone(fields.text("space directions")), where, "space directions");
    if (directions.size() % 3 != 0 && directions.size() % 2 != 0)
        throw InputError(where + "space directions '" + fields.text("space directions") + "' are not vectors");
    const std::size_t n = directions.size() % 3 == 0 ? 3 : 2;
    for (std::size_t v = 0; v + n <= directions.size(); v += n) {
        double length = 0.0;
        for (std::size_t c = 0; c < n; ++c) length += directions[v + c] * directions[v + c];
        requireSpacings({std::sqrt(length)}, where, "space directions");
    }
}

/// A skip of bytes or lines: a whole number no larger than the data (-1 bytes: the samples
/// end the file). @return the bytes skipped, 0 for lines or -1.
double skipOf(const HeaderFields& fields, const std::string& key, double dataBytes, const std::string& where)
{
    const std::vector<double> skip = fields.numbers(key, where);
    if (skip.empty()) return 0.0;
    if (skip.size() != 1 || skip[0] != std::floor(skip[0]) || skip[0] < (key == "byte skip" ? -1.0 : 0.0) ||
        skip[0] > dataBytes)
        throw InputError(where + key + " '" + fields.text(key) + "' is not a skip within the data");
    return key == "byte skip" ? skip[0] : 0.0;
}

/// The lines after the `data file` line: where a LIST's names are.
std::vector<std::string> linesAfterDataFile(const std::vector<std::string>& lines)
{
    const auto at = std::find_if(lines.begin(), lines.end(), [](const std::string& line) {
        return line.rfind("data file:", 0) == 0 || line.rfind("datafile:", 0) == 0;
    });
    return at == lines.end() ? std::vector<std::string>{} : std::vector<std::string>(at + 1, lines.end());
}

/// The header's lines (comments left out) and its bytes, the magic line's included.
std::vector<std::string> nrrdHeaderLines(const fs::path& path, std::size_t& bytes)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the file");
    const std::string where = path.string() + ": ";
    std::string magic;
    std::getline(in, magic);
    if (magic.rfind("NRRD000", 0) != 0) throw InputError(where + "not a NRRD file (it must start with NRRD000)");
    std::vector<std::string> lines = headerLines(in, where, bytes, [](const std::string& l) { return l.empty(); });
    bytes += magic.size() + 1;
    lines.erase(std::remove_if(lines.begin(), lines.end(), [](const std::string& l) { return l[0] == '#'; }),
                lines.end());
    return lines;
}

/// The vectors of a `space directions` or `space origin` field, "(x,y,z)" (or "(x,y)") each;
/// "none" (an axis not in space) is left out.
std::vector<openvdb::Vec3d> vectorsOf(const std::string& text, const std::string& where, const std::string& field)
{
    std::vector<openvdb::Vec3d> vectors;
    for (std::size_t open = text.find('('); open != std::string::npos; open = text.find('(', open + 1)) {
        const std::size_t close = text.find(')', open);
        const std::vector<double> v = finiteNumbers(text.substr(open + 1, close - open - 1), where, field);
        if (close == std::string::npos || v.size() < 2 || v.size() > 3)
            throw InputError(where + field + " '" + text + "' are not vectors of two or three numbers");
        vectors.emplace_back(v[0], v[1], v.size() == 3 ? v[2] : 0.0);  // a 2D space lies in z = 0
    }
    return vectors;
}

/// The axes in space, each scaled by its spacing: `space directions`, else `spacings` along x,
/// y and z. Fewer than three (a slice) are completed by unit steps.
std::vector<openvdb::Vec3d> spatialAxes(const HeaderFields& fields, const std::string& where)
{
    std::vector<openvdb::Vec3d> axes;
    if (fields.has("space directions")) {
        axes = vectorsOf(fields.text("space directions"), where, "space directions");
    } else {
        const std::vector<double> spacings = finiteNumbers(withoutNone(fields.text("spacings")), where, "spacings");
        for (std::size_t a = 0; a < spacings.size() && a < 3; ++a) {
            openvdb::Vec3d axis(0.0);
            axis[int(a)] = spacings[a];
            axes.push_back(axis);
        }
    }
    if (axes.size() > 3) throw InputError(where + std::to_string(axes.size()) + " axes in space (expected 3)");
    while (axes.size() < 3) {
        openvdb::Vec3d axis(0.0);
        axis[int(axes.size())] = 1.0;
        axes.push_back(axis);
    }
    return axes;
}

/// Millimetres per unit of `space units` ("mm" "mm" "mm"): one length for all axes.
double spaceUnits(const HeaderFields& fields, const std::string& where, std::vector<std::string>& notes)
{
    if (!fields.has("space units")) return 1.0;
    std::vector<std::string> units;
    const std::string text = fields.text("space units");
    for (std::size_t open = text.find('"'); open != std::string::npos; open = text.find('"', open + 1)) {
        const std::size_t close = text.find('"', open + 1);
        if (close == std::string::npos) break;
        units.push_back(text.substr(open + 1, close - open - 1));
        open = close;
    }
    const std::optional<double> first = units.empty() ? std::nullopt : millimetresPer(units.front());
    const bool alike = std::all_of(units.begin(), units.end(), [&](const std::string& u) { return u == units[0]; });
    if (first && alike) return *first;
    notes.push_back(where + "space units '" + text + "' are not one known length: taken as millimetres");
    return 1.0;
}

}  // namespace

ScanPlacement nrrdPlacement(const fs::path& path)
{
    const std::string where = path.string() + ": ";
    std::size_t bytes = 0;
    const HeaderFields fields(nrrdHeaderLines(path, bytes), ":");
    ScanPlacement placed;
    const std::vector<openvdb::Vec3d> axes = spatialAxes(fields, where);
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) m[a][c] = axes[std::size_t(a)][c];
    if (fields.has("space origin")) {
        const std::vector<openvdb::Vec3d> origin = vectorsOf(fields.text("space origin"), where, "space origin");
        if (origin.size() != 1)
            throw InputError(where + "space origin '" + fields.text("space origin") + "' is not one point");
        m.setTranslation(origin.front());
    }
    const std::string space = fields.text("space");
    std::optional<openvdb::Vec3d> signs = anatomicalSigns(space);
    if (!signs) {
        placed.notes.push_back(
            where +
            (space.empty() ? std::string("no anatomical space declared") : "space '" + space + "' is not anatomical") +
            ": taken as left-posterior-superior (LPS)");
        signs = openvdb::Vec3d(1.0);
    }
    placed.worldFromIndex = inLpsMillimetres(m, *signs, spaceUnits(fields, where, placed.notes));
    return placed;
}

void checkNrrdHeader(const fs::path& path)
{
    const std::string where = path.string() + ": ";
    std::size_t bytes = 0;
    const std::vector<std::string> lines = nrrdHeaderLines(path, bytes);
    const HeaderFields fields(lines, ":");
    const double sample = typeBytes(fields.text("type"));
    if (sample == 0.0) throw InputError(where + "unknown or missing sample type '" + fields.text("type") + "'");
    if (!fields.has("sizes")) throw InputError(where + "the header has no 'sizes:' line");
    const std::vector<double> sizes = fields.numbers("sizes", where);
    const double samples = sampleCount(sizes, where, "sizes");
    const std::vector<double> dimension = fields.numbers("dimension", where);
    if (sizes.size() > std::size_t(kMaxNrrdDimension) ||
        (fields.has("dimension") && (dimension.size() != 1 || dimension[0] != double(sizes.size()))))
        throw InputError(where + "dimension " + fields.text("dimension") + " but " + std::to_string(sizes.size()) +
                         " sizes");
    checkPlacement(fields, where);

    const std::string spec = fields.has("data file") ? fields.text("data file") : fields.text("datafile");
    const bool attached = spec.empty();
    const std::vector<fs::path> files =
        attached ? std::vector<fs::path>{path}
                 : dataFiles(spec, linesAfterDataFile(lines), path.parent_path(), samples, where);
    const std::string encoding = fields.has("encoding") ? fields.text("encoding") : "raw";
    const double dataBytes = bytesIn(files, 0.0);
    skipOf(fields, "line skip", dataBytes, where);
    const double skip = std::max(0.0, skipOf(fields, "byte skip", dataBytes, where));
    const double needed = samples * sample;
    if ((encoding == "gzip" || encoding == "gz") && files.size() == 1) {
        requireInflatesTo(files[0], std::uint64_t(attached ? double(bytes) : 0.0), needed, where);
    } else if (encoding == "raw") {
        const double available = bytesIn(files, (attached ? double(bytes) : 0.0) + skip);
        if (available < needed) {
            throw InputError(where + "truncated: " + std::to_string((long long)std::max(0.0, available)) +
                             " bytes of samples where the header declares " + std::to_string((long long)needed));
        }
    }
}

}  // namespace sculpt
