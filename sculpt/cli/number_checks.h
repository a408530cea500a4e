// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file number_checks.h
/// @brief CLI11 validators whose messages a user can read ("must be a positive number (got 0)"),
///        unlike CLI11's own, which print the whole range of a double.

#include <CLI/CLI.hpp>

namespace sculpt::cli {

/// A finite number > 0.
CLI::Validator positiveNumber();
/// A finite number >= 0.
CLI::Validator nonNegativeNumber();

}  // namespace sculpt::cli
