// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file band_rule.h
/// @brief What the narrow band stores of a value: the one rule every writer of the field follows.
///
/// A value with |value| < background is stored as it is, active; any other is stored inactive as
/// +-background, its sign only (FieldImage). Writers compute a value, then store it by this rule,
/// so the band never holds a voxel that claims a distance it does not know.

#include <cmath>

namespace sculpt {

struct BandValue {
    float value = 0.0f;
    bool active = false;
};

/// `value` as the band stores it. T is float or double: the test is made in T, before rounding.
template <typename T>
BandValue toBand(T value, T background)
{
    if (std::abs(value) < background) return {float(value), true};
    return {float(value < T(0) ? -background : background), false};
}

/// Stores `band` at `where` in `target`: an accessor and a Coord, or a leaf and an offset.
template <typename Target, typename Where>
void setBandValue(Target& target, const Where& where, const BandValue& band)
{
    if (band.active) {
        target.setValueOn(where, band.value);
    } else {
        target.setValueOff(where, band.value);
    }
}

}  // namespace sculpt
