// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file header_checks.h
/// @brief What a scan's header claims, checked against the file before a third-party reader
///        sees it: VTK's readers fill a short file with zeros (or garbage) without a word, and
///        loop or allocate on absurd numbers.
///
/// Every check honours the same classes: every number that sizes or places the samples finite;
/// dimensions, sizes, spacings and file counts within the limits of header_text.h and
/// sample_files.h (README, "Limits"); every sample the header declares present, in every data
/// file it names; compressed samples inflating to exactly the size declared.

#include <filesystem>

namespace sculpt {

/// A MetaImage (.mha with its samples inside, .mhd naming a data file, a LIST or a %d
/// pattern of them): NDims 1 to 4 with as many DimSize entries, the element type and channels
/// known, spacings, offsets and matrices finite.
/// @throws InputError naming the file and what is wrong.
void checkMetaImageHeader(const std::filesystem::path& path);

/// A NRRD (.nrrd, or .nhdr naming a data file, a LIST or a %d pattern of them): a text header
/// (ending in a blank line) with type, dimension and sizes sane, spacings, directions and
/// origin finite. @throws InputError naming the file and what is wrong.
void checkNrrdHeader(const std::filesystem::path& path);

/// A NIfTI-1 header (.nii; .nii.gz read through zlib): sizeof_hdr 348, dimensions 1 to 7 of
/// positive sizes, a datatype VTK reads with its bit depth, pixdim, scaling, quaternion, qoffset
/// and srow finite, spacings usable. @throws InputError naming the file and what is wrong.
void checkNiftiHeader(const std::filesystem::path& path);

}  // namespace sculpt
