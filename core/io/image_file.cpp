// SPDX-License-Identifier: Apache-2.0
#include "core/io/image_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/io/vtk_error_catcher.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>
#include <Imath/half.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <algorithm>
#include <cmath>
#include <vector>

namespace sculpt {

namespace {

Imath::V3f v3f(const openvdb::Vec3d& v) { return Imath::V3f(float(v.x()), float(v.y()), float(v.z())); }

Imf::Header exrHeader(const RenderedImage& image, const Camera& camera)
{
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : {"R", "G", "B", "A"}) header.channels().insert(name, Imf::Channel(Imf::HALF));
    for (const char* name : {"Z", "N.X", "N.Y", "N.Z"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    const openvdb::Mat4d cameraFromWorld = camera.worldFromCamera().inverse();
    Imath::M44f m;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) m[r][c] = float(cameraFromWorld[r][c]);  // both row-vector convention
    }
    Imf::addWorldToCamera(header, m);
    header.insert("cameraPosition", Imf::V3fAttribute(v3f(camera.position)));
    header.insert("cameraLookAt", Imf::V3fAttribute(v3f(camera.lookAt)));
    header.insert("cameraUp", Imf::V3fAttribute(v3f(camera.up)));
    header.insert("cameraFov", Imf::FloatAttribute(float(camera.fovDegrees)));
    return header;
}

void writeExr(const RenderedImage& image, const Camera& camera, const std::filesystem::path& path)
{
    std::vector<half> rgba(image.rgba.size());
    std::transform(image.rgba.begin(), image.rgba.end(), rgba.begin(), [](float v) { return half(v); });
    const std::size_t w = std::size_t(image.width);
    Imf::FrameBuffer frame;
    const char* colour[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        frame.insert(colour[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgba.data() + c), 4 * sizeof(half),
                                           4 * sizeof(half) * w));
    }
    frame.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(image.depth.data())),
                                 sizeof(float), sizeof(float) * w));
    const char* normal[] = {"N.X", "N.Y", "N.Z"};
    for (int c = 0; c < 3; ++c) {
        frame.insert(normal[c],
                     Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(image.normal.data() + c)),
                                3 * sizeof(float), 3 * sizeof(float) * w));
    }
    AtomicFile file(path);
    try {
        Imf::OutputFile out(file.temporaryPath().c_str(), exrHeader(image, camera));
        out.setFrameBuffer(frame);
        out.writePixels(image.height);
    } catch (const std::exception& e) {
        throw InputError(path.string() + ": cannot write (" + e.what() + ")");
    }
    file.commit();
}

/// Linear light to an 8-bit sRGB code value.
unsigned char srgb8(double linear)
{
    const double v = std::clamp(linear, 0.0, 1.0);
    const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<unsigned char>(std::lround(encoded * 255.0));
}

void writePng(const RenderedImage& image, const std::filesystem::path& path)
{
    bool transparent = false;
    for (std::size_t i = 3; i < image.rgba.size() && !transparent; i += 4) transparent = image.rgba[i] < 1.0f;
    const int components = transparent ? 4 : 3;
    vtkNew<vtkImageData> data;
    data->SetDimensions(image.width, image.height, 1);
    data->AllocateScalars(VTK_UNSIGNED_CHAR, components);
    auto* out = static_cast<unsigned char*>(data->GetScalarPointer());
    for (int y = 0; y < image.height; ++y) {
        const int row = image.height - 1 - y;  // VTK's first row is the bottom of the picture
        for (int x = 0; x < image.width; ++x) {
            const float* p = &image.rgba[4 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x))];
            unsigned char* q = out + components * (std::size_t(row) * std::size_t(image.width) + std::size_t(x));
            const double alpha = p[3];
            for (int c = 0; c < 3; ++c) q[c] = srgb8(alpha > 0.0 ? p[c] / alpha : 0.0);  // PNG alpha is straight
            if (transparent) q[3] = static_cast<unsigned char>(std::lround(std::clamp(alpha, 0.0, 1.0) * 255.0));
        }
    }
    AtomicFile file(path);
    vtkNew<vtkPNGWriter> writer;
    const VtkErrorCatcher catcher(writer);
    writer->SetInputData(data);
    writer->SetFileName(file.temporaryPath().c_str());
    writer->Write();
    if (catcher.caught() || writer->GetErrorCode() != 0) throw InputError(path.string() + ": cannot write");
    file.commit();
}

}  // namespace

ImageFormat imageFormatOf(const std::filesystem::path& path)
{
    const std::string ext = lowerExtension(path);
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".png") return ImageFormat::Png;
    throw InputError(path.string() + ": unknown image format '" + ext + "' (expected .exr or .png)");
}

void writeImage(const RenderedImage& image, const Camera& camera, const std::filesystem::path& path)
{
    switch (imageFormatOf(path)) {
    case ImageFormat::Exr: writeExr(image, camera, path); break;
    case ImageFormat::Png: writePng(image, path); break;
    }
}

}  // namespace sculpt
