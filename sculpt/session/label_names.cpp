// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/label_names.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/field/document_text.h"
#include "core/io/text_lines.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// Sidecar files larger than this are not a label list.
constexpr std::uintmax_t kMaxSidecarBytes = 1u << 20;
constexpr std::size_t kLutBytes = 768;

bool present(const fs::path& path)
{
    std::error_code ec;
    return fs::is_regular_file(path, ec) && fs::file_size(path, ec) <= kMaxSidecarBytes;
}

/// The file beside `volume` with `extension`: "atlas.nii.gz" -> "atlas.nii.txt" (MRIcron's
/// way), else "atlas.txt"; empty if neither exists.
fs::path sidecar(const fs::path& volume, const std::string& extension)
{
    fs::path base = volume;
    if (base.extension() == ".gz") base.replace_extension();
    for (fs::path candidate : {fs::path(base.string() + extension), base.replace_extension(extension)})
        if (present(candidate)) return candidate;
    return {};
}

void readNames(const fs::path& path, std::map<int, LabelLook>& looks)
{
    const std::string text = readWholeFile(path);
    TextLines lines(text, path, '#');
    for (const auto* words = &lines.next(); !words->empty(); words = &lines.next()) {
        if (words->size() < 2) continue;
        try {
            const auto value = lines.integer((*words)[0], "a label");
            if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) continue;
            looks[int(value)].name = printableText(std::string((*words)[1]), kMaxPieceNameBytes);
        } catch (const InputError&) {
            continue;  // a heading, not a label
        }
    }
}

void readColours(const fs::path& path, std::map<int, LabelLook>& looks)
{
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() != kLutBytes) throw InputError(path.string() + ": not a colour table of 768 bytes");
    const auto channel = [&](int plane, int value) {
        return float(static_cast<unsigned char>(bytes[plane * 256 + value])) / 255.0f;
    };
    for (int value = 0; value < 256; ++value) {
        const openvdb::Vec3f colour(channel(0, value), channel(1, value), channel(2, value));
        // Black marks a value the table leaves uncoloured (JHU's 21 to 30): the palette's then.
        if (colour != openvdb::Vec3f(0.0f)) looks[value].colour = colour;
    }
}

/// The header of a NRRD file: up to its first empty line, read at most kMaxSidecarBytes.
std::string nrrdHeader(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::string header, line;
    while (header.size() < kMaxSidecarBytes && std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) break;
        header += line + '\n';
    }
    return header;
}

/// 3D Slicer's segments: "SegmentK_Field:=value" lines; a segment without a LabelValue (Slicer
/// before 4.11) is label K + 1.
void readSlicerSegments(const fs::path& path, std::map<int, LabelLook>& looks)
{
    struct Segment {
        std::string name, colour;
        std::optional<int> label;
    };
    std::map<int, Segment> segments;
    std::istringstream header(nrrdHeader(path));
    for (std::string line; std::getline(header, line);) {
        const auto underscore = line.find('_'), assign = line.find(":=");
        if (line.rfind("Segment", 0) != 0 || underscore == std::string::npos || assign == std::string::npos ||
            assign < underscore)
            continue;
        int index = 0;
        try {
            index = std::stoi(line.substr(7, underscore - 7));
        } catch (const std::exception&) {
            continue;
        }
        const std::string field = line.substr(underscore + 1, assign - underscore - 1), value = line.substr(assign + 2);
        Segment& segment = segments[index];
        if (field == "Name") segment.name = value;
        if (field == "Color") segment.colour = value;
        if (field == "LabelValue") segment.label = std::atoi(value.c_str());
    }
    for (const auto& [index, segment] : segments) {
        LabelLook& look = looks[segment.label.value_or(index + 1)];
        look.name = printableText(segment.name, kMaxPieceNameBytes);
        float r = 0.0f, g = 0.0f, b = 0.0f;
        if (std::sscanf(segment.colour.c_str(), "%f %f %f", &r, &g, &b) == 3) look.colour = openvdb::Vec3f(r, g, b);
    }
}

}  // namespace

std::map<int, LabelLook> readLabelLooks(const fs::path& volume, std::vector<std::string>& warnings)
{
    std::map<int, LabelLook> looks;
    const std::string format = lowerExtension(volume);
    if (format == ".nrrd" || format == ".nhdr") readSlicerSegments(volume, looks);
    const std::pair<const char*, void (*)(const fs::path&, std::map<int, LabelLook>&)> readers[] = {
        {".txt", &readNames}, {".lut", &readColours}};
    for (const auto& [extension, read] : readers) {
        const fs::path path = sidecar(volume, extension);
        if (path.empty()) continue;
        try {
            read(path, looks);
        } catch (const std::exception& e) {
            warnings.push_back(std::string(e.what()) + "; the labels keep their numbers and palette colours");
        }
    }
    return looks;
}

}  // namespace sculpt
