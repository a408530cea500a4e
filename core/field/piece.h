// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file piece.h
/// @brief One part of a document: a level set of its own that never blends with the others
///        (a head, an eye, a segmented organ), with the name, colour and visibility the user
///        gave it (Desbrun, Tsingos and Cani 1995, section 5: parts that must not blend).

#include "core/field/field_image.h"

#include <array>
#include <string>
#include <utility>

namespace sculpt {

/// What a piece is besides its voxels: what the user calls it, sees of it, and where it stands.
struct PieceLook {
    std::string name;                         ///< unique in its document; a single-piece document's is "surface"
    openvdb::Vec3f colour{0.8f, 0.8f, 0.8f};  ///< sRGB, 0..1
    bool visible = true;
    /// World from the field's own world (row vectors, as OpenVDB: p * placement): moving,
    /// turning or scaling a piece edits this, never a voxel.
    openvdb::Mat4d placement = openvdb::Mat4d::identity();
    /// Its value in a label map (a segmentation): the label it was imported from, kept for the
    /// export back to one; 0 for none yet (the export numbers it).
    int label = 0;
};
/// The largest label value a piece may carry (a 16-bit label map's).
inline constexpr int kMaxPieceLabel = 65535;

struct Piece : PieceLook {
    Piece(PieceLook look, FieldImage voxels) : PieceLook(std::move(look)), field(std::move(voxels)) {}
    FieldImage field;
};

/// The colour a new piece gets: the i-th of a palette whose neighbours tell apart (a label map's
/// pieces side by side), starting from the clay's grey.
inline openvdb::Vec3f paletteColour(std::size_t index)
{
    static constexpr std::array<std::array<float, 3>, 8> kPalette{{{0.80f, 0.80f, 0.80f},
                                                                   {0.86f, 0.49f, 0.40f},
                                                                   {0.45f, 0.66f, 0.85f},
                                                                   {0.55f, 0.78f, 0.48f},
                                                                   {0.91f, 0.78f, 0.42f},
                                                                   {0.70f, 0.55f, 0.82f},
                                                                   {0.45f, 0.80f, 0.78f},
                                                                   {0.88f, 0.60f, 0.75f}}};
    const auto& c = kPalette[index % kPalette.size()];
    return {c[0], c[1], c[2]};
}

}  // namespace sculpt
