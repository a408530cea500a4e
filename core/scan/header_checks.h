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

}  // namespace sculpt
