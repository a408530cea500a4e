// SPDX-License-Identifier: Apache-2.0
#include "ui/view/surface_look.h"

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkPlaneCollection.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>
#include <vtkUniforms.h>

#include <cstdio>
#include <string>

namespace sculpt::ui {

namespace {

/// Soft key light from the upper left, wrapped diffuse (clay scatters), a rim from behind and a
/// highlight of the given tightness: the look of the studio matcaps sculptors know.
constexpr const char* kMatcapFunction = R"(
//VTK::Light::Dec
vec3 matcapColour(vec3 n)
{
  float len = length(n);
  n = len > 1e-6 ? n / len : vec3(0.0, 0.0, 1.0);  // a degenerate normal: no black speck
  vec3 key = normalize(vec3(-0.45, 0.55, 0.70));
  float wrap = clamp((dot(n, key) + matcapWrap) / (1.0 + matcapWrap), 0.0, 1.0);
  vec3 colour = mix(matcapShadow, matcapBase, wrap * wrap * (3.0 - 2.0 * wrap));
  vec3 halfway = normalize(key + vec3(0.0, 0.0, 1.0));
  colour += matcapSpecular * pow(max(dot(n, halfway), 0.0), matcapGloss);
  // The rim lights silhouettes only: normals turned away (inside a nostril) get none.
  colour += matcapRim * pow(1.0 - clamp(n.z, 0.0, 1.0), 3.0) * clamp(1.0 + 4.0 * n.z, 0.0, 1.0);
  colour *= 0.85 + 0.15 * clamp(0.5 + 0.5 * n.y, 0.0, 1.0);
  return colour;
}
)";

/// The clay's colour as a GLSL constant.
std::string clayLiteral()
{
    char text[64];
    std::snprintf(text, sizeof text, "vec3(%.4f, %.4f, %.4f)", kClayColour[0], kClayColour[1], kClayColour[2]);
    return text;
}

/// The matcap replaces VTK's lit colour, tinted as the points are (pointTint, below); with the
/// wireframe on, VTK's edge term (emix, only declared then) darkens it near the triangles' edges.
std::string matcapImpl(bool wireframe)
{
    return std::string("//VTK::Light::Impl\n  if (matcapOn == 1) {\n"
                       "    vec3 matcap = matcapColour(normalVCVSOutput);\n") +
           "    matcap *= pointTint;\n" +
           (wireframe ? "    matcap = mix(matcap, vec3(0.08, 0.08, 0.1), emix);\n" : "") +
           "    gl_FragData[0] = vec4(matcap, opacity);\n  }\n";
}

struct Matcap {
    float base[3], shadow[3], rim[3];
    float specular, gloss, wrap;
};

Matcap matcapOf(Shading shading)
{
    switch (shading) {
    case Shading::White:
        return {{0.92f, 0.92f, 0.90f}, {0.30f, 0.31f, 0.34f}, {0.18f, 0.18f, 0.20f}, 0.10f, 24.f, 0.30f};
    case Shading::RedWax:
        return {{0.78f, 0.16f, 0.12f}, {0.20f, 0.03f, 0.03f}, {0.30f, 0.10f, 0.08f}, 0.45f, 60.f, 0.55f};
    default: return {{0.80f, 0.62f, 0.48f}, {0.26f, 0.17f, 0.13f}, {0.16f, 0.13f, 0.12f}, 0.06f, 12.f, 0.40f};
    }
}

}  // namespace

SurfaceLook::SurfaceLook()
{
    mProperty = vtkSmartPointer<vtkProperty>::New();
    mProperty->SetColor(kClayColour[0], kClayColour[1], kClayColour[2]);
    mProperty->SetSpecular(0.15);
    mProperty->SetSpecularPower(20.0);
    mProperty->SetEdgeColor(0.1, 0.1, 0.12);
    // The surface is closed: its back faces are never seen, except as single pixels poking past
    // a silhouette (specks), and drawing them costs fill rate.
    mProperty->BackfaceCullingOn();
    mShader = vtkSmartPointer<vtkShaderProperty>::New();
    setWireframe(false);
    setShading(Shading::Clay);
}

void SurfaceLook::setShading(Shading shading)
{
    mShading = shading;
    const Matcap m = matcapOf(shading);
    vtkUniforms* u = mShader->GetFragmentCustomUniforms();
    u->SetUniformi("matcapOn", shading == Shading::Lit ? 0 : 1);
    u->SetUniform3f("matcapBase", m.base);
    u->SetUniform3f("matcapShadow", m.shadow);
    u->SetUniform3f("matcapRim", m.rim);
    u->SetUniformf("matcapSpecular", m.specular);
    u->SetUniformf("matcapGloss", m.gloss);
    u->SetUniformf("matcapWrap", m.wrap);
}

void SurfaceLook::setFlat(bool flat)
{
    mFlat = flat;
    if (flat) mProperty->SetInterpolationToFlat();
    else mProperty->SetInterpolationToGouraud();
}

void SurfaceLook::setXRay(bool xray)
{
    constexpr double kXRayOpacity = 0.3;
    mXRay = xray;
    mProperty->SetOpacity(xray ? kXRayOpacity : 1.0);
}

void SurfaceLook::setWireframe(bool wireframe)
{
    mWireframe = wireframe;
    mProperty->SetEdgeVisibility(wireframe);
    mShader->ClearAllFragmentShaderReplacements();
    mShader->AddFragmentShaderReplacement("//VTK::Light::Dec", true, kMatcapFunction, false);
    mShader->AddFragmentShaderReplacement("//VTK::Light::Impl", true, matcapImpl(wireframe), false);
    // Points coloured other than the clay (the mask, a print check) tint every look alike; read
    // where VTK has just set the colour, before its lighting scales it.
    mShader->AddFragmentShaderReplacement(
        "//VTK::Color::Impl", true,
        "//VTK::Color::Impl\n  vec3 pointTint = clamp(diffuseColor / max(diffuseIntensity * " + clayLiteral() +
            ", vec3(1e-3)), 0.0, 1.0);\n",
        false);
}

void SurfaceLook::setClipping(vtkPlaneCollection* planes) { mClipping = planes; }

void SurfaceLook::apply(vtkActor* actor) const
{
    actor->SetProperty(mProperty);
    actor->SetShaderProperty(mShader);
    if (mClipping && actor->GetMapper()) actor->GetMapper()->SetClippingPlanes(mClipping);
}

}  // namespace sculpt::ui
