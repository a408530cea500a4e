// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file block_polydata.h
/// @brief Mesher blocks as VTK geometry: what every display of a surface uploads.

#include "core/mesh/block_mesh.h"

#include <glm/vec3.hpp>
#include <vtkSmartPointer.h>

#include <utility>

class vtkPolyData;

namespace sculpt::ui {

/// `part` appended to `whole`, its indices shifted (keys and ownership are not kept).
void append(BlockMesh& whole, const BlockMesh& part);

/// The box of `count` points (none: lo above hi).
std::pair<glm::dvec3, glm::dvec3> boundsOf(const std::array<float, 3>* points, std::size_t count);

/// The mesh's points, normals and triangles, copied into VTK arrays.
vtkSmartPointer<vtkPolyData> polyDataOf(const BlockMesh& mesh);
/// The points, normals and triangles of a polydata polyDataOf made, copied back (only reads it:
/// safe on another thread while the UI thread draws it).
BlockMesh blockMeshOf(const vtkPolyData* poly);

}  // namespace sculpt::ui
