// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dicom_directory.h
/// @brief Which files of a directory are DICOM image slices: those its DICOMDIR names, when it
///        has one, else the files in it that are DICOM images.
///
/// Discs from hospitals hold a DICOMDIR (the index of every image on the disc, in folders below
/// it), a README, a viewer and its files beside the images. A file is an image slice when it is
/// a DICOM Part 10 file ("DICM" after the 128-byte preamble) whose Media Storage SOP Class is an
/// image one, or carries a DICOM extension (.dcm, .dicom, .ima: old files without the
/// preamble); anything else is skipped and counted. Internal to scan/.

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct DicomDirectoryListing {
    std::vector<std::filesystem::path> images;  ///< sorted by path
    std::vector<std::string> skipped;           ///< names of files that are not DICOM images
    bool fromDicomdir = false;                  ///< the images are those a DICOMDIR names
};

/// True for a DICOM Part 10 file ("DICM" after the preamble), whatever its name: discs name
/// their images IM000001, without an extension.
bool hasDicomMarker(const std::filesystem::path& file);

/// @throws InputError naming the directory if its DICOMDIR names a file that is not there.
DicomDirectoryListing listDicomDirectory(const std::filesystem::path& dir);

/// Where the images came from (a DICOMDIR) or what was skipped, as one line for the user;
/// empty when the directory held images only.
std::string listingNote(const std::filesystem::path& dir, const DicomDirectoryListing& listing);

}  // namespace sculpt
