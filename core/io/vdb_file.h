// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vdb_file.h
/// @brief Field images in OpenVDB's `.vdb` format, readable by Houdini, Blender and OpenVDB tools.
///
/// A document holds one float level-set grid (named "surface" in the files we make) and file
/// metadata:
///   sculpt.format_version (int)   — kVdbFormatVersion; newer files are refused
///   sculpt.units          (string)— length unit of world coordinates, e.g. "mm"
///   sculpt.voxel_size     (double)— redundant with the transform; a mismatch means damage
///   sculpt.checksum       (string)— gridChecksum() in hex; a mismatch means damage
///   sculpt.sealed         (string)— the seal over these fields (metadata_seal.h), on each grid too
/// A document of several pieces (piece.h) holds one level set per piece, named after it, the first
/// recorded as the edited grid so that every reader of one surface opens it; each piece grid
/// carries in its own metadata
///   sculpt.piece_colour   (vec3s) — sRGB 0..1; marks the grid as a piece
///   sculpt.piece_visible  (bool)
///   sculpt.piece_placement (mat4d)— world from the grid's world: a move that kept the voxels
///   sculpt.piece_label    (int)   — its value in a label map, 1..65535, when it came from one
///   sculpt.checksum       (string)— as above, for the pieces after the first (the file's is the first's)
/// A surface's mask (FieldImage::mask), when anything is masked, is a fog grid named after it
/// ("surface.mask"), written after it, carrying
///   sculpt.mask_of        (string)— the name of its surface
///   sculpt.checksum       (string)— as above, for the mask's voxels
/// Files from other programs are accepted: the grid named "surface" is edited, else the only
/// float level set, else the one the user names. Their other grids and metadata are kept and
/// written back on save; a float grid that is not a narrow band (a dense `phi`) is rebuilt into one.

#include "core/field/field_image.h"
#include "core/field/piece.h"

#include <openvdb/openvdb.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// Version of our metadata layout, written into every document.
constexpr int kVdbFormatVersion = 1;

/// What a file held besides the edited grid, written back unchanged on save.
struct VdbCompanions {
    openvdb::GridPtrVec grids;  ///< the other grids, decoded
    openvdb::MetaMap metadata;  ///< the file's metadata, less our own entries
};

struct VdbDocument {
    FieldImage field;
    VdbCompanions companions;
    /// Grids that cannot be kept (a type this OpenVDB cannot decode), a band rebuilt, ...
    std::vector<std::string> warnings;
};

/// Reads a document: the grid named `gridName`, or when that is empty the one chosen as above.
/// @throws InputError naming the file if it is missing, not an OpenVDB file, truncated or
///         corrupt, holds no usable grid (or several level sets and no choice), was written by
///         a newer format version, or would need more memory than is available.
VdbDocument readVdbDocument(const std::filesystem::path& path, const std::string& gridName = {});

/// readVdbDocument's field alone, for readers that do not write the file back.
FieldImage readFieldImage(const std::filesystem::path& path, const std::string& gridName = {});

/// Writes a field image atomically (temporary file, then rename): a failure or a crash leaves
/// any previous file untouched and no partial file behind. The grid keeps its name ("surface"
/// if it has none); `companions` are written after it.
/// @throws InputError naming the file if its directory does not exist, it cannot be written, or
///         it is a .vdb holding a grid this build cannot decode (writing would lose that grid).
void writeFieldImage(const FieldImage& field, const std::filesystem::path& path, const VdbCompanions& companions = {});

/// A document's pieces: the edited grid first, then every level set marked as a piece, in file
/// order; a document of one surface (every file written before pieces) is one piece named
/// after its grid.
struct VdbPieces {
    std::vector<Piece> pieces;
    VdbCompanions companions;  ///< the grids that are not pieces, and the file's metadata
    std::vector<std::string> warnings;
};

/// Reads every piece of a document, the first being readVdbDocument's choice (`gridName`, or the
/// edited grid).
/// @throws InputError as readVdbDocument, and naming the piece whose voxels do not match its checksum.
VdbPieces readVdbPieces(const std::filesystem::path& path, const std::string& gridName = {});

/// Writes pieces (at least one, unique non-empty names, the same units) atomically as above; a
/// single piece is written as writeFieldImage writes its field.
/// @throws InputError naming the file as writeFieldImage, or the piece whose name is empty or
///         taken twice.
void writeVdbPieces(const std::vector<Piece>& pieces, const std::filesystem::path& path,
                    const VdbCompanions& companions = {});

}  // namespace sculpt
