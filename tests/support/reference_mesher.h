// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file reference_mesher.h
/// @brief OpenVDB's own polygonizer (tools::volumeToMesh, adaptivity 0), triangulated.
///
/// One shared-vertex mesh of the zero iso-surface. Kept as the reference our own mesher is
/// measured against.

#include "core/field/field_image.h"
#include "core/mesh/triangle_mesh.h"

namespace sculpt::test {

/// Meshes the zero iso-surface with openvdb::tools::volumeToMesh; quads are split along their
/// shorter diagonal. Cost: linear in the band size.
TriangleMesh meshWithVolumeToMesh(const FieldImage& field);

}  // namespace sculpt::test
