// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vdb_layout.h
/// @brief What a `.vdb` file declares (header, file metadata, the table of grids with each
///        grid's metadata), read with every length and count checked against the file's size.
///
/// OpenVDB's reader trusts the lengths it reads: one damaged string length makes it ask for
/// gigabytes before the read fails. Scanning the layout first, with nothing allocated beyond
/// what the file holds, bounds what OpenVDB is then given, lists the grids for the user, and
/// lets a reader decode one grid without touching the others.

#include "core/io/vdb_tree_check.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// One grid as the file's table describes it.
struct VdbGridEntry {
    std::string name;                 ///< the grid's name, as OpenVDB tools show it
    std::string type;                 ///< tree type, e.g. "Tree_float_5_4_3"
    std::string gridClass;            ///< "level set", "fog volume", ..., empty when unstated
    std::string instanceOf;           ///< the grid whose voxels this one shares, or empty
    std::int64_t memoryBytes = 0;     ///< in-core size the writer recorded, 0 when unstated
    VdbValueCoding coding;            ///< how its values are stored
    std::int64_t begin = 0;           ///< first byte of its descriptor
    std::int64_t transformBegin = 0;  ///< first byte of its transform, after its metadata
    std::int64_t buffersBegin = 0;    ///< first byte of its leaves' values; 0 when the file has no offsets
    /// One past its last byte; 0 when it cannot be located (a streamed file, without offsets,
    /// is walked grid by grid, and only float trees can be walked).
    std::int64_t end = 0;

    bool isFloat() const;
    bool isLevelSet() const { return gridClass == "level set"; }
    bool located() const { return end > 0; }
};

/// File metadata naming the grid a document edits (written by writeFieldImage).
inline constexpr const char* kVdbEditedGridKey = "sculpt.grid";
/// The file metadata naming the frame of the documents' world ("LPS", FieldImage::kFrame).
inline constexpr const char* kVdbFrameKey = "sculpt.frame";

struct VdbLayout {
    std::int64_t fileSize = 0;
    /// Where the grid count lies: the header and file metadata are the bytes before it.
    std::int64_t gridTableOffset = 0;
    /// The grids up to the first one that cannot be located (see VdbGridEntry::end).
    std::vector<VdbGridEntry> grids;
    /// Grids after that one: a streamed file's grids are found only by walking those before.
    int unlocatedGrids = 0;
    /// The file's `sculpt.grid`: the grid our programs edited when they wrote it.
    std::string editedGrid;
    /// The file's `sculpt.frame`; empty if it records none (another program's file, or ours
    /// from before frames were recorded).
    std::string frame;
};

/// @throws InputError (not naming the file: the caller does) if the file is not an OpenVDB
///         file, uses a format version this OpenVDB cannot read, or declares a length, count
///         or offset beyond its end.
VdbLayout scanVdbLayout(const std::filesystem::path& path);

/// The grid to edit when the user names none: the one our programs edited (`sculpt.grid`), else
/// the one named "surface", else the only float level set; nullptr when there is no such grid
/// or several level sets to choose from.
const VdbGridEntry* defaultGrid(const VdbLayout& layout);

/// The names of the file's float level sets: what a user chooses from.
std::vector<std::string> levelSetNames(const VdbLayout& layout);

/// "surface (level set), density (fog volume)": the grids as the user should see them.
std::string describeGrids(const VdbLayout& layout);

}  // namespace sculpt
