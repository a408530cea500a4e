#pragma once
/// @file largest_component.h
/// @brief Keeps the largest surface of a shape: removes the islands scans are full of.
///
/// Pieces are connected surfaces, as mesh tools count them and as `info` reports components: an
/// island goes, and so does a closed cavity's surface (the cavity is filled), leaving one closed
/// shell to print. Works in place: the only copies are bit masks of the band.

#include "field_image.h"

#include <cstddef>

namespace sculpt {

/// Keeps the surface with the most voxels next to it; the others, and the band voxels that
/// belong to them, are dropped and every voxel's side is that of the kept surface.
/// @return the number of surfaces dropped.
std::size_t keepLargestComponent(FieldImage& field);

} // namespace sculpt
