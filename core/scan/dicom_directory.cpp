// SPDX-License-Identifier: Apache-2.0
#include "core/scan/dicom_directory.h"

#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/scan/dicom_series.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <gdcmMediaStorage.h>
#include <gdcmReader.h>
#include <gdcmSequenceOfItems.h>
#include <optional>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kPreambleBytes = 128;
const gdcm::Tag kDirectoryRecords(0x0004, 0x1220);
const gdcm::Tag kRecordType(0x0004, 0x1430);
const gdcm::Tag kReferencedFile(0x0004, 0x1500);

/// The stream just past a Part 10 file's marker, or a failed stream.
std::ifstream afterMarker(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    if (!in.seekg(kPreambleBytes) || !in.read(magic, 4) || std::string(magic, 4) != "DICM")
        in.setstate(std::ios::failbit);
    return in;
}

/// The Media Storage SOP Class UID of a Part 10 file, read from its meta group (always
/// explicit VR little endian); nullopt if the file is not Part 10, the group does not say or
/// is damaged.
std::optional<std::string> mediaStorageUid(const fs::path& file)
{
    std::ifstream in = afterMarker(file);
    for (int element = 0; element < 64; ++element) {  // the meta group has about ten elements
        std::uint16_t group = 0, tag = 0;
        char vr[2] = {};
        if (!in.read(reinterpret_cast<char*>(&group), 2) || group != 0x0002) return std::nullopt;
        in.read(reinterpret_cast<char*>(&tag), 2).read(vr, 2);
        std::uint32_t length = 0;
        const std::string v(vr, 2);
        if (v == "OB" || v == "OW" || v == "OF" || v == "SQ" || v == "UT" || v == "UN") {
            in.ignore(2).read(reinterpret_cast<char*>(&length), 4);
        } else {
            std::uint16_t shortLength = 0;
            in.read(reinterpret_cast<char*>(&shortLength), 2);
            length = shortLength;
        }
        if (!in || length > 1024) return std::nullopt;
        std::string value(length, '\0');
        if (!in.read(value.data(), length)) return std::nullopt;
        if (tag == 0x0002) return value.substr(0, value.find_last_not_of(std::string(" \0", 2)) + 1);
    }
    return std::nullopt;
}

/// True for a file worth giving the DICOM reader as a slice.
bool isImageCandidate(const fs::path& file)
{
    if (!afterMarker(file)) return isDicomFile(file);  // old files have no preamble, only a name
    const std::optional<std::string> uid = mediaStorageUid(file);
    if (!uid) return true;  // a damaged or silent meta group: GDCM, in its child process, will say
    const gdcm::MediaStorage::MSType type = gdcm::MediaStorage::GetMSType(uid->c_str());
    return type == gdcm::MediaStorage::MS_END || gdcm::MediaStorage::IsImage(type);  // unknown: let GDCM say
}

/// `relative` under `root`, each component matched regardless of case where the exact name is
/// missing (discs are written in upper case, and some systems show them in lower).
std::optional<fs::path> findIgnoringCase(const fs::path& root, const fs::path& relative)
{
    fs::path at = root;
    for (const fs::path& part : relative) {
        if (fs::exists(at / part)) {
            at /= part;
            continue;
        }
        const auto lower = [](std::string s) {
            std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            return s;
        };
        std::error_code error;
        const auto match =
            std::find_if(fs::directory_iterator(at, error), fs::directory_iterator(),
                         [&](const auto& e) { return lower(e.path().filename().string()) == lower(part.string()); });
        if (error || match == fs::directory_iterator()) return std::nullopt;
        at = match->path();
    }
    return at;
}

/// The images a DICOMDIR names, or nullopt if GDCM cannot read it as one.
std::optional<std::vector<fs::path>> dicomdirImages(const fs::path& dicomdir)
{
    gdcm::Reader reader;
    reader.SetFileName(dicomdir.string().c_str());
    if (!reader.Read() || !reader.GetFile().GetDataSet().FindDataElement(kDirectoryRecords)) return std::nullopt;
    const auto records = reader.GetFile().GetDataSet().GetDataElement(kDirectoryRecords).GetValueAsSQ();
    if (!records) return std::nullopt;
    std::vector<fs::path> images;
    for (gdcm::SequenceOfItems::SizeType i = 1; i <= records->GetNumberOfItems(); ++i) {
        const gdcm::DataSet& record = records->GetItem(i).GetNestedDataSet();
        const auto text = [&](const gdcm::Tag& tag) -> std::string {
            const gdcm::ByteValue* value =
                record.FindDataElement(tag) ? record.GetDataElement(tag).GetByteValue() : nullptr;
            return value && value->GetPointer() ? std::string(value->GetPointer(), value->GetLength()) : "";
        };
        std::string type = text(kRecordType);
        type.erase(type.find_last_not_of(std::string(" \0", 2)) + 1);
        std::string file = text(kReferencedFile);
        file.erase(file.find_last_not_of(std::string(" \0", 2)) + 1);
        if (type != "IMAGE" || file.empty()) continue;
        std::replace(file.begin(), file.end(), '\\', '/');  // components are separated by backslashes
        const std::optional<fs::path> found = findIgnoringCase(dicomdir.parent_path(), file);
        if (!found)
            throw InputError(dicomdir.string() + ": names " + file + ", which is not on the disc (incomplete copy?)");
        images.push_back(*found);
    }
    return images;
}

}  // namespace

bool hasDicomMarker(const fs::path& file) { return fs::is_regular_file(file) && bool(afterMarker(file)); }

DicomDirectoryListing listDicomDirectory(const fs::path& dir)
{
    DicomDirectoryListing listing;
    std::optional<std::vector<fs::path>> indexed;
    if (const std::optional<fs::path> dicomdir = findIgnoringCase(dir, "DICOMDIR")) indexed = dicomdirImages(*dicomdir);
    if (indexed && !indexed->empty()) {
        listing.images = std::move(*indexed);
        listing.fromDicomdir = true;
    } else {
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            if (!entry.is_regular_file() || name.front() == '.') continue;  // hidden files are not the user's
            if (isImageCandidate(entry.path())) listing.images.push_back(entry.path());
            else listing.skipped.push_back(name);
        }
    }
    std::sort(listing.images.begin(), listing.images.end());
    std::sort(listing.skipped.begin(), listing.skipped.end());
    return listing;
}

std::string listingNote(const fs::path& dir, const DicomDirectoryListing& listing)
{
    if (listing.fromDicomdir)
        return dir.string() + ": read the " + std::to_string(listing.images.size()) + " images its DICOMDIR lists";
    if (listing.skipped.empty()) return {};
    std::string names;
    for (std::size_t i = 0; i < std::min<std::size_t>(3, listing.skipped.size()); ++i)
        names += (i ? ", " : "") + listing.skipped[i];
    if (listing.skipped.size() > 3) names += ", ...";
    return dir.string() + ": skipped " + std::to_string(listing.skipped.size()) + " file" +
           (listing.skipped.size() > 1 ? "s" : "") + " that " + (listing.skipped.size() > 1 ? "are" : "is") +
           " not a DICOM image (" + names + ")";
}

}  // namespace sculpt
