// SPDX-License-Identifier: Apache-2.0
#include "ui/view/placement_matrix.h"

#include <vtkMatrix4x4.h>

namespace sculpt::ui {

void setPlacementMatrix(vtkMatrix4x4& matrix, const openvdb::Mat4d& placement)
{
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) matrix.SetElement(i, j, placement(j, i));
}

}  // namespace sculpt::ui
