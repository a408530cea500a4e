// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file placement_matrix.h
/// @brief A piece's placement (world from its field's world, OpenVDB's row vectors) as the
///        matrix VTK's actors take (column vectors: the transpose).

#include <openvdb/Types.h>

class vtkMatrix4x4;

namespace sculpt::ui {

void setPlacementMatrix(vtkMatrix4x4& matrix, const openvdb::Mat4d& placement);

}  // namespace sculpt::ui
