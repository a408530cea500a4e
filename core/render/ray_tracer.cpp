// SPDX-License-Identifier: Apache-2.0
#include "core/render/ray_tracer.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/field/central_difference.h"

#include <openvdb/tools/RayIntersector.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt {

namespace {

using openvdb::Vec3d;
using Intersector = openvdb::tools::LevelSetRayIntersector<openvdb::FloatGrid>;
using Ray = openvdb::math::Ray<double>;

constexpr int kTile = 16;           // pixels on a tile's side
const Vec3d kClay(0.72, 0.5, 0.4);  // albedo, linear
constexpr double kKeyLight = 1.05, kFillLight = 0.25, kAmbientLight = 0.25, kSpecular = 0.12;

/// SplitMix64: a well-mixed 64-bit hash, so every (pixel, sample, seed) draws its own numbers.
std::uint64_t mix(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// Uniform numbers in [0, 1) from a hashed counter.
class Random {
public:
    explicit Random(std::uint64_t key) : mState(mix(key)) {}
    double next()
    {
        mState = mix(mState);
        return double(mState >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t mState;
};

/// Lights fixed to the camera: key from the upper left, fill from the right, in world space.
struct Lighting {
    Vec3d key, fill;
    explicit Lighting(const Camera& camera)
    {
        const openvdb::Mat4d m = camera.worldFromCamera();
        key = m.transform3x3(Vec3d(-0.45, 0.6, 0.65).unit()).unit();
        fill = m.transform3x3(Vec3d(0.7, 0.05, 0.7).unit()).unit();
    }
};

/// A direction about unit `n`, cosine-distributed (Malley's method).
Vec3d cosineDirection(const Vec3d& n, double u1, double u2)
{
    const Vec3d helper = std::abs(n.x()) < 0.9 ? Vec3d(1.0, 0.0, 0.0) : Vec3d(0.0, 1.0, 0.0);
    const Vec3d t = n.cross(helper).unit(), b = n.cross(t);
    const double r = std::sqrt(u1), phi = 2.0 * M_PI * u2;
    return (t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0, 1.0 - u1))).unit();
}

struct Scene {
    const PinholeProjection& projection;
    const Lighting& lighting;
    const RenderOptions& options;
    int strata;               // samples per pixel = strata^2
    int occlusionRaysPerHit;  // the pixel's occlusion rays shared among its samples
    double escapeWorld;       // an occlusion ray starts this far out, past the surface's crossing
    double occlusionReachWorld;
};

/// What one thread traces with: its own intersector and accessor (neither is thread-safe).
struct Tracer {
    Intersector intersector;
    openvdb::FloatGrid::ConstAccessor accessor;
    const openvdb::math::Transform& xform;
};

/// The surface normal at `world`: the voxels' central-difference gradients interpolated
/// trilinearly, so shading varies smoothly across cells (the intersector's own normal is the
/// gradient of one cell's trilinear interpolant, which shows every cell face as a facet).
Vec3d smoothNormal(Tracer& tracer, const Vec3d& world, const Vec3d& fallback)
{
    const Vec3d p = tracer.xform.worldToIndex(world);
    const openvdb::Coord base = openvdb::Coord::floor(p);
    const Vec3d f = p - base.asVec3d();
    // The 4^3 voxels around the cell (index -1 .. 2 from its corner), read once; the central
    // difference at each of the cell's corners takes its six neighbours from them.
    float v[4][4][4];
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k) {
                const int outer = (i == 0 || i == 3) + (j == 0 || j == 3) + (k == 0 || k == 3);
                v[i][j][k] = outer > 1 ? 0.0f : tracer.accessor.getValue(base.offsetBy(i - 1, j - 1, k - 1));
            }
        }
    }
    const auto at = [&v](int x, int y, int z) { return v[x + 1][y + 1][z + 1]; };
    Vec3d sum(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
        const double w = (dx ? f.x() : 1.0 - f.x()) * (dy ? f.y() : 1.0 - f.y()) * (dz ? f.z() : 1.0 - f.z());
        sum += centralDifference(at, dx, dy, dz) * w;
    }
    return sum.lengthSqr() > 0.0 ? sum.unit() : fallback;
}

/// What the samples of one pixel saw.
struct PixelResult {
    Vec3d colour{0.0}, normalSum{0.0};
    int hits = 0;
    double nearest = std::numeric_limits<double>::infinity();
};

double ambientOcclusion(Tracer& tracer, const Scene& scene, const Vec3d& point, const Vec3d& n, Random& random)
{
    if (scene.occlusionRaysPerHit == 0) return 1.0;
    int blocked = 0;
    for (int i = 0; i < scene.occlusionRaysPerHit; ++i) {
        const double u1 = random.next(), u2 = random.next();
        // OpenVDB's rays start past t = 0 (Ray asserts t0 > 0): the smallest time it allows.
        const Ray ray(point + n * scene.escapeWorld, cosineDirection(n, u1, u2), openvdb::math::Delta<double>::value(),
                      scene.occlusionReachWorld);
        if (tracer.intersector.intersectsWS(ray)) ++blocked;
    }
    return 1.0 - double(blocked) / scene.occlusionRaysPerHit;
}

/// x^24, the highlight's Blinn exponent, by squaring (std::pow costs more than the rest of the shading).
double shininess24(double x)
{
    const double x3 = x * x * x, x6 = x3 * x3, x12 = x6 * x6;
    return x12 * x12;
}

Vec3d shade(const Scene& scene, const Vec3d& n, const Vec3d& towardsViewer, double occlusion)
{
    const Lighting& l = scene.lighting;
    const double diffuse =
        kAmbientLight * occlusion + kKeyLight * std::max(0.0, n.dot(l.key)) + kFillLight * std::max(0.0, n.dot(l.fill));
    const Vec3d half = (l.key + towardsViewer).unitSafe();
    const double specular = kSpecular * shininess24(std::max(0.0, n.dot(half))) * occlusion;
    return kClay * diffuse + Vec3d(specular);
}

PixelResult tracePixel(Tracer& tracer, const Scene& scene, int x, int y)
{
    PixelResult result;
    const int n = scene.strata;
    const std::uint64_t pixel = (std::uint64_t(y) << 32) | std::uint64_t(x);
    for (int s = 0; s < n * n; ++s) {
        Random random(mix(pixel ^ mix(scene.options.seed)) + std::uint64_t(s));
        const double sx = (s % n + random.next()) / n, sy = (s / n + random.next()) / n;
        const Ray ray = scene.projection.ray(x + sx, y + sy);
        Vec3d point, normal;
        double t = 0.0;
        if (!tracer.intersector.intersectsWS(ray, point, normal, t)) {
            if (scene.options.background) result.colour += *scene.options.background;
            continue;
        }
        normal = smoothNormal(tracer, point, normal.unitSafe());
        result.colour += shade(scene, normal, -ray.dir(), ambientOcclusion(tracer, scene, point, normal, random));
        result.normalSum += normal;
        result.nearest = std::min(result.nearest, t);
        ++result.hits;
    }
    return result;
}

void store(RenderedImage& image, const Scene& scene, int x, int y, const PixelResult& r)
{
    const std::size_t i = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
    const double count = scene.strata * scene.strata;
    for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = float(r.colour[c] / count);
    image.rgba[4 * i + 3] = scene.options.background ? 1.0f : float(r.hits / count);
    image.depth[i] = float(r.nearest);
    const Vec3d n = r.hits ? r.normalSum.unitSafe() : Vec3d(0.0);
    for (int c = 0; c < 3; ++c) image.normal[3 * i + c] = float(n[c]);
}

bool cameraInside(const FieldImage& field, const Camera& camera)
{
    const auto& xform = field.grid().transform();
    return field.grid().tree().getValue(xform.worldToIndexCellCentered(camera.position)) < 0.0f;
}

}  // namespace

void RenderOptions::validate() const
{
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
        throw InputError("image size " + std::to_string(width) + " x " + std::to_string(height) +
                         " is out of range (1 to " + std::to_string(kMaxSide) + " pixels a side)");
    }
    if (samples < 1 || samples > 1024) throw InputError("samples per pixel must be between 1 and 1024");
    if (occlusionRays < 0 || occlusionRays > 256) throw InputError("occlusion rays must be between 0 and 256");
    if (!(occlusionReach >= 0.0) || !std::isfinite(occlusionReach)) {
        throw InputError("occlusion reach must be a non-negative number");
    }
    if (background) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite((*background)[c])) throw InputError("background colour must be finite numbers");
        }
    }
}

RenderedImage renderField(const FieldImage& field, const Camera& camera, const RenderOptions& options,
                          RenderReport& summary, const Progress& progress)
{
    options.validate();
    camera.validate();
    RenderedImage image;
    image.width = options.width;
    image.height = options.height;
    const double pixels = double(options.width) * double(options.height);
    requireMemory(pixels * sizeof(float) * (4 + 1 + 3) * 1.25,
                  "a " + std::to_string(options.width) + " x " + std::to_string(options.height) + " image");
    image.rgba.assign(image.pixelCount() * 4, 0.0f);
    image.depth.assign(image.pixelCount(), 0.0f);
    image.normal.assign(image.pixelCount() * 3, 0.0f);
    if (cameraInside(field, camera)) summary.warnings.push_back("the camera is inside the surface");

    const PinholeProjection projection(camera, options.width, options.height);
    const Lighting lighting(camera);
    const openvdb::BBoxd bounds = SurfaceExtent(field).bounds;
    const double size = bounds.empty() ? 0.0 : bounds.extents().length();
    const int strata = int(std::ceil(std::sqrt(double(options.samples)) - 1e-9));
    const int perHit =
        options.occlusionRays == 0 ? 0 : (options.occlusionRays + strata * strata - 1) / (strata * strata);
    const Scene scene{
        projection, lighting, options, strata, perHit, 2.0 * field.voxelSize(), options.occlusionReach * size};
    const Tracer exemplar{Intersector(field.grid()), field.grid().getConstAccessor(), field.grid().transform()};
    tbb::enumerable_thread_specific<Tracer> tracers(exemplar);
    const int tilesX = (options.width + kTile - 1) / kTile, tilesY = (options.height + kTile - 1) / kTile;
    std::vector<std::size_t> covered(std::size_t(tilesX) * std::size_t(tilesY), 0);
    for (int ty = 0; ty < tilesY; ++ty) {
        tbb::parallel_for(tbb::blocked_range<int>(0, tilesX), [&](const tbb::blocked_range<int>& range) {
            Tracer& tracer = tracers.local();
            for (int tx = range.begin(); tx < range.end(); ++tx) {
                for (int y = ty * kTile; y < std::min(options.height, (ty + 1) * kTile); ++y) {
                    for (int x = tx * kTile; x < std::min(options.width, (tx + 1) * kTile); ++x) {
                        const PixelResult r = tracePixel(tracer, scene, x, y);
                        store(image, scene, x, y, r);
                        covered[std::size_t(ty) * std::size_t(tilesX) + std::size_t(tx)] += r.hits > 0;
                    }
                }
            }
        });
        report(progress, double(ty + 1) / tilesY);
    }
    for (const std::size_t n : covered) summary.coveredPixels += n;
    if (summary.coveredPixels == 0) summary.warnings.push_back("the camera sees nothing of the surface");
    return image;
}

}  // namespace sculpt
