// checkNrrdHeader (header_checks.h): a NRRD's text header and the samples it says it has.
#include "core/base/errors.h"
#include "core/scan/header_checks.h"
#include "core/scan/header_text.h"
#include "core/scan/sample_files.h"

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

}  // namespace

void checkNrrdHeader(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot read the file");
    const std::string where = path.string() + ": ";
    std::string magic;
    std::getline(in, magic);
    if (magic.rfind("NRRD000", 0) != 0) throw InputError(where + "not a NRRD file (it must start with NRRD000)");
    std::size_t bytes = 0;
    std::vector<std::string> lines = headerLines(in, where, bytes, [](const std::string& l) { return l.empty(); });
    bytes += magic.size() + 1;
    lines.erase(std::remove_if(lines.begin(), lines.end(), [](const std::string& l) { return l[0] == '#'; }),
                lines.end());
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
