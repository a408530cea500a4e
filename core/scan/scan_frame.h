// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scan_frame.h
/// @brief The one frame documents are in: LPS millimetres (x grows to the patient's left, y to
///        the back, z up), as DICOM, ITK and the meshes Slicer writes. Each scan format declares
///        its own (a NIfTI's sform and qform map to RAS, a NRRD names its space and units, a
///        MetaImage is ITK's LPS); the readers convert what it declares, and say what they
///        assumed where it declares nothing. (FieldImage::kFrame names the documents' frame.)

#include <openvdb/Types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sculpt {

/// Where a scan's samples are: index (i, j, k) to LPS millimetres (row vectors, as OpenVDB:
/// p' = p * M), and what was assumed to place them (for the import's message).
struct ScanPlacement {
    openvdb::Mat4d worldFromIndex = openvdb::Mat4d::identity();
    std::vector<std::string> notes;
};

/// A frame's axes against LPS's: +1 where they agree, -1 where they point the other way.
/// RAS (NIfTI's) is (-1, -1, 1).
inline const openvdb::Vec3d kRasSigns{-1.0, -1.0, 1.0};

/// `worldFromIndex` in a frame of axes `signs` (against LPS) and units of `millimetresPerUnit`,
/// made LPS millimetres.
openvdb::Mat4d inLpsMillimetres(const openvdb::Mat4d& worldFromIndex, const openvdb::Vec3d& signs,
                                double millimetresPerUnit);
/// The signs of an anatomical space as NRRD names it ("right-anterior-superior", "RAS",
/// "left-posterior-superior-time", ...); nothing for a space of no anatomical meaning
/// ("scanner-xyz", "3D-right-handed") or one not known.
std::optional<openvdb::Vec3d> anatomicalSigns(const std::string& space);
/// Millimetres in one `unit` ("mm", "um", "µm", "micron", "m", "cm", "nm" and their long
/// names); nothing if it is not a length known here.
std::optional<double> millimetresPer(const std::string& unit);
/// Millimetres in one unit of a NIfTI's xyzt_units (its spatial bits: 1 metre, 2 millimetre,
/// 3 micrometre); 1 when it names none.
double niftiMillimetresPer(int xyztUnits);

/// A NRRD's placement from its header: `space directions` (else `spacings`) and `space origin`,
/// in the frame `space` names and the units `space units` gives.
/// @throws InputError naming the file if the header cannot place the samples in three dimensions.
ScanPlacement nrrdPlacement(const std::filesystem::path& path);
/// A MetaImage's placement from its header: Offset (Origin, Position), ElementSpacing and
/// TransformMatrix (Rotation, Orientation: a row per axis' direction), in ITK's LPS millimetres.
ScanPlacement metaImagePlacement(const std::filesystem::path& path);

}  // namespace sculpt
