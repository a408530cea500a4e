// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file inrimage_file.h
/// @brief INRIA's INRIMAGE-4 format (.inr, .inr.gz: CGAL's sample segmentations, its mesher's
///        input): a text header in 256-byte blocks, `#INRIMAGE-4#{` ... `##}`, of KEY=value lines
///        (XDIM, YDIM, ZDIM, VDIM, TYPE, PIXSIZE, CPU, VX, VY, VZ), then the samples, x fastest;
///        the whole file may be gzipped. Ours: VTK has no reader for it. Internal to scan/.

#include "core/scan/scan_volume.h"

#include <filesystem>

namespace sculpt {

/// Checks the header (one channel, a sample type we read, sizes and spacings sane) and that the
/// file holds every sample it declares. @throws InputError naming the file and what is wrong.
void checkInrimageHeader(const std::filesystem::path& path);

/// Reads the samples of a file checkInrimageHeader passed.
ScanVolume readInrimage(const std::filesystem::path& path);

}  // namespace sculpt
