// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scan_transfer.h
/// @brief A ScanVolume taken across the pipe from the isolated reader's child process
///        (isolated_call.h): its placement, source and warnings in a header, its samples, in
///        their file type, as the body. Internal to scan/.

#include "core/base/isolated_call.h"
#include "core/scan/scan_volume.h"

namespace sculpt {

/// The child's side: `scan` packed; the reply keeps it alive until sent.
ChildReply packScan(const ScanVolume& scan);

/// The parent's side: the scan again, its samples adopted from the body without a copy.
/// @throws std::runtime_error if the bytes are not what packScan wrote.
ScanVolume unpackScan(IsolatedBytes bytes);

}  // namespace sculpt
