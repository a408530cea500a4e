// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vtk_image_scan.h
/// @brief Inside a ScanVolume: the VTK image that holds its samples, and what every reader does
///        to make one (run the reader with its header checked first, place the image in the world).
///        Internal to scan/: the readers and ScanVolume share it, nothing else includes it.

#include "core/scan/scan_volume.h"

#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkMatrix4x4.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace sculpt {

struct ScanVolume::Impl {
    vtkSmartPointer<vtkImageData> image;  // extent starts at (0, 0, 0)
    openvdb::Mat4d worldFromIndex = openvdb::Mat4d::identity();
    std::string source;
    std::vector<std::string> warnings;
};

/// Runs a configured reader: header first (dimensions checked and memory reserved before the
/// samples are allocated), then the samples; any error the reader reports becomes an InputError
/// naming `source`, as does any warning but those holding one of `tolerated` (notes about a file
/// the reader still reads right), which are added to `toleratedSeen`.
vtkSmartPointer<vtkImageData> runReader(vtkImageReader2* reader, const std::string& source,
                                        const std::vector<std::string>& tolerated = {},
                                        std::vector<std::string>* toleratedSeen = nullptr);

/// World from index for a VTK image: world = M (origin + ijk * spacing), M a 4x4 (or identity).
openvdb::Mat4d placement(vtkImageData* image, vtkMatrix4x4* orientation);

/// The scan of an image: its extent moved to start at zero (readers may start elsewhere),
/// keeping its world placement. @throws InputError if a sample is not finite.
ScanVolume makeScan(vtkSmartPointer<vtkImageData> image, openvdb::Mat4d worldFromIndex, const std::string& source,
                    std::vector<std::string> warnings = {});

}  // namespace sculpt
