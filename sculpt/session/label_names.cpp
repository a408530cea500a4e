#include "sculpt/session/label_names.h"

#include "core/base/errors.h"
#include "core/io/text_lines.h"

#include <fstream>
#include <iterator>
#include <limits>

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
            looks[int(value)].name = std::string((*words)[1]);
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
    for (int value = 0; value < 256; ++value)
        looks[value].colour = openvdb::Vec3f(channel(0, value), channel(1, value), channel(2, value));
}

}  // namespace

std::map<int, LabelLook> readLabelLooks(const fs::path& volume, std::vector<std::string>& warnings)
{
    std::map<int, LabelLook> looks;
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
