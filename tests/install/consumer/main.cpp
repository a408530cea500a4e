// SPDX-License-Identifier: Apache-2.0
// Uses the installed engine as another program would: a ball rasterized, measured and saved.
// Prints its volume and Euler characteristic; exits 1 if they are not a sphere's.

#include "core/field/field_image.h"
#include "core/io/vdb_file.h"
#include "core/mesh/field_measures.h"
#include "core/primitives/analytic_shapes.h"

#include <cmath>
#include <cstdio>

int main(int argc, char** argv)
{
    const sculpt::FieldImage ball = sculpt::rasterizeSdf(sculpt::sphereSdf(10.0), 0.5);
    const sculpt::FieldMeasures m = sculpt::measureField(ball);
    if (argc > 1) sculpt::writeFieldImage(ball, argv[1]);
    std::printf("volume %.1f, euler characteristic %d\n", m.volume, m.eulerCharacteristic);
    const double expected = 4.0 / 3.0 * 3.14159265358979 * 1000.0;
    return std::abs(m.volume - expected) < 0.01 * expected && m.eulerCharacteristic == 2 ? 0 : 1;
}
