#pragma once
/// @file header_checks.h
/// @brief What a scan's header claims, checked against the file before a third-party reader
///        sees it: VTK's readers fill a short file with zeros (or garbage) without a word.

#include <filesystem>

namespace sculpt {

/// A MetaImage (.mha with its samples inside, .mhd naming a data file): the header readable
/// (text, no NUL byte, at most 64 KiB), its sizes and element type sane, and the samples it
/// declares present: the data file exists and, uncompressed, holds every byte.
/// @throws InputError naming the file and what is wrong.
void checkMetaImageHeader(const std::filesystem::path& path);

/// A NRRD (.nrrd, or .nhdr naming a data file): a text header (no NUL byte, at most 64 KiB,
/// ending in a blank line) with type, dimension and sizes sane; a raw encoding's samples all
/// present. @throws InputError naming the file and what is wrong.
void checkNrrdHeader(const std::filesystem::path& path);

/// A NIfTI-1 header (.nii; .nii.gz read through zlib to its end): sizeof_hdr 348, dimensions 1
/// to 7 of positive sizes, a datatype VTK reads with its bit depth, and every sample present.
/// @throws InputError naming the file and what is wrong.
void checkNiftiHeader(const std::filesystem::path& path);

}  // namespace sculpt
