// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file field_measures.h
/// @brief What `sculpt info` reports about a field image: size, storage and shape measures.

#include "core/field/field_image.h"

#include <cstdint>

namespace sculpt {

struct FieldMeasures {
    double voxelSize = 0.0;          ///< world units per voxel edge
    double halfWidthVoxels = 0.0;    ///< narrow-band half width
    std::uint64_t activeVoxels = 0;  ///< voxels stored in the band
    std::uint64_t memoryBytes = 0;   ///< in-core size of the grid's tree
    openvdb::Vec3d bboxMin{0.0};     ///< world bounding box of the surface (empty shape: 0)
    openvdb::Vec3d bboxMax{0.0};
    double volume = 0.0;          ///< enclosed volume, world units^3 (of the welded mesh)
    double area = 0.0;            ///< surface area, world units^2 (of the welded mesh)
    int eulerCharacteristic = 0;  ///< 2 - 2 genus per closed component (of the mesh)
    int components = 0;           ///< closed shells (of the mesh)
};

/// Measures a field image. Volume, area, Euler characteristic (V - E + F) and components (shells)
/// are those of the welded marching-cubes mesh (closed, exact topology); the bounding box is that
/// of the zero crossings found by linear interpolation between neighbouring voxels. Cost: linear
/// in the band size, parallel.
FieldMeasures measureField(const FieldImage& field);

/// Volume and area of the marching-cubes surface, as measureField gives them, without welding or
/// counting shells: what volume control holds. Cost: one meshing pass over the band.
struct MeshVolumeArea {
    double volume = 0.0;  ///< world units^3
    double area = 0.0;    ///< world units^2
};
MeshVolumeArea meshVolumeArea(const FieldImage& field);

}  // namespace sculpt
