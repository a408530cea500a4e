// SPDX-License-Identifier: Apache-2.0
// Rendered images written to OpenEXR and PNG, read back with the OpenEXR library and VTK.

#include "core/base/errors.h"
#include "core/io/image_file.h"
#include "core/primitives/analytic_shapes.h"
#include "core/render/ray_tracer.h"
#include "tests/support/temp_dir.h"

#include <Imath/ImathMatrix.h>
#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <set>
#include <string>
#include <vector>

namespace sculpt {
namespace {

using openvdb::Vec3d;

struct Rendered {
    Camera camera;
    RenderedImage image;
    Rendered(bool transparent)
    {
        camera.position = Vec3d(12.0, 8.0, 30.0);
        RenderOptions options;
        options.width = 48;
        options.height = 32;
        options.samples = 1;
        options.occlusionRays = 2;
        if (transparent) options.background.reset();
        RenderReport report;
        image = renderField(makeSphere(6.0, 0.5), camera, options, report);
    }
};

TEST(ImageFile, ExrHoldsExactlyTheLayersTheSizeAndTheCamera)
{
    test::TempDir dir;
    const Rendered r(true);
    writeImage(r.image, r.camera, dir / "sphere.exr");
    Imf::InputFile in((dir / "sphere.exr").c_str());
    const Imf::Header& header = in.header();
    std::set<std::string> channels;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
        channels.insert(c.name());
        const bool colour =
            std::string(c.name()).size() == 1 && std::string("RGBA").find(c.name()) != std::string::npos;
        EXPECT_EQ(c.channel().type, colour ? Imf::HALF : Imf::FLOAT) << c.name();
    }
    EXPECT_EQ(channels, (std::set<std::string>{"A", "B", "G", "N.X", "N.Y", "N.Z", "R", "Z"}));
    const Imath::Box2i window = header.dataWindow();
    EXPECT_EQ(window.max.x - window.min.x + 1, 48);
    EXPECT_EQ(window.max.y - window.min.y + 1, 32);

    const auto* position = header.findTypedAttribute<Imf::V3fAttribute>("cameraPosition");
    ASSERT_NE(position, nullptr);
    EXPECT_EQ(position->value(), Imath::V3f(12.0f, 8.0f, 30.0f));
    ASSERT_NE(header.findTypedAttribute<Imf::V3fAttribute>("cameraLookAt"), nullptr);
    ASSERT_NE(header.findTypedAttribute<Imf::V3fAttribute>("cameraUp"), nullptr);
    const auto* fov = header.findTypedAttribute<Imf::FloatAttribute>("cameraFov");
    ASSERT_NE(fov, nullptr);
    EXPECT_FLOAT_EQ(fov->value(), float(r.camera.fovDegrees));
    ASSERT_TRUE(Imf::hasWorldToCamera(header));
    // worldToCamera takes the camera's position to the origin and the look-at point down -z.
    const Imath::V3f origin = Imath::V3f(12.0f, 8.0f, 30.0f) * Imf::worldToCamera(header);
    EXPECT_NEAR(origin.length(), 0.0, 1e-4);
    const Imath::V3f target = Imath::V3f(0.0f) * Imf::worldToCamera(header);
    EXPECT_NEAR(target.z, -std::sqrt(12.0 * 12.0 + 8.0 * 8.0 + 30.0 * 30.0), 1e-3);

    // The depth layer reads back as written.
    std::vector<float> depth(r.image.pixelCount());
    Imf::FrameBuffer frame;
    frame.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(depth.data()), sizeof(float), 48 * sizeof(float)));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    EXPECT_EQ(depth, r.image.depth);
}

TEST(ImageFile, PngHasTheSizeAndAlphaOnlyWhenTransparent)
{
    test::TempDir dir;
    for (const bool transparent : {true, false}) {
        const Rendered r(transparent);
        const auto path = dir / (transparent ? "clear.png" : "opaque.png");
        writeImage(r.image, r.camera, path);
        vtkNew<vtkPNGReader> reader;
        reader->SetFileName(path.c_str());
        reader->Update();
        int dims[3];
        reader->GetOutput()->GetDimensions(dims);
        EXPECT_EQ(dims[0], 48);
        EXPECT_EQ(dims[1], 32);
        EXPECT_EQ(reader->GetOutput()->GetNumberOfScalarComponents(), transparent ? 4 : 3);
    }
}

TEST(ImageFile, RefusesUnknownFormatsAndUnwritablePathsLeavingNoFile)
{
    test::TempDir dir;
    const Rendered r(false);
    EXPECT_THROW(writeImage(r.image, r.camera, dir / "sphere.tiff"), InputError);
    EXPECT_THROW(writeImage(r.image, r.camera, dir / "missing" / "sphere.exr"), InputError);
    EXPECT_THROW(writeImage(r.image, r.camera, dir / "missing" / "sphere.png"), InputError);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace sculpt
