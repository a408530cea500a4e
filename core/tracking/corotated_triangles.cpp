// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/corotated_triangles.h"

#include <cmath>

namespace sculpt {

namespace {

using openvdb::Vec3d;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

constexpr double kPoisson = 0.3;

/// A 2 x 2 matrix, row major.
struct Mat2 {
    double a = 0.0, b = 0.0, c = 0.0, d = 0.0;  // [[a, b], [c, d]]
    Mat2 operator*(const Mat2& o) const
    {
        return {a * o.a + b * o.c, a * o.b + b * o.d, c * o.a + d * o.c, c * o.b + d * o.d};
    }
    Mat2 transposed() const { return {a, c, b, d}; }
};

/// The rest triangle's edge matrix inverse, Dm^-1 with Dm = [(e, 0), (e/2, e sqrt(3)/2)] as
/// columns, and its area.
struct RestShape {
    Mat2 inverse;
    double area;
    explicit RestShape(double e)
    {
        const double h = e * std::sqrt(3.0) / 2.0, det = e * h;
        inverse = {h / det, -0.5 * e / det, 0.0, e / det};
        area = 0.5 * det;
    }
};

/// A triangle's tangent frame and the rotation of its deformation gradient, held fixed through
/// one solve (the co-rotational linearisation).
struct Frame {
    Vec3d u{1, 0, 0}, v{0, 1, 0};  // orthonormal, in the triangle's plane
    Mat2 rotation{1, 0, 0, 1};
};

/// (the second column stays 0: 2 vectors of 2 as a matrix of columns)
Mat2 columns(double x0, double y0, double x1, double y1) { return {x0, x1, y0, y1}; }

/// dP = R (2 mu sym(R^T dF) + lambda tr(sym(R^T dF)) I): the stress of a displacement gradient.
Mat2 stress(const Mat2& rotation, const Mat2& gradient, double mu, double lambda)
{
    const Mat2 m = rotation.transposed() * gradient;
    const double exx = m.a, eyy = m.d, exy = 0.5 * (m.b + m.c), trace = exx + eyy;
    const Mat2 sigma{2 * mu * exx + lambda * trace, 2 * mu * exy, 2 * mu * exy, 2 * mu * eyy + lambda * trace};
    return rotation * sigma;
}

class Solver {
public:
    Solver(const std::vector<Vec3d>& x, const Triangles& triangles, const std::vector<Vec3d>& normals,
           const std::vector<std::uint8_t>& fixed, const RelaxOptions& o)
        : mX(x), mTriangles(triangles), mNormals(normals), mFixed(fixed), mRest(o.restEdge), mFrames(triangles.size())
    {
        // E dt as a gain: Lame's parameters of a unit modulus (plane stress), scaled.
        mMu = o.gain / (2.0 * (1.0 + kPoisson));
        mLambda = o.gain * kPoisson / (1.0 - kPoisson * kPoisson);
        for (std::size_t t = 0; t < triangles.size(); ++t) mFrames[t] = frameOf(t);
    }

    /// dt f: the forces pulling each triangle towards its turned rest shape, filtered.
    std::vector<Vec3d> forces() const
    {
        std::vector<Vec3d> f(mX.size(), Vec3d(0.0));
        for (std::size_t t = 0; t < mTriangles.size(); ++t) {
            const Frame& fr = mFrames[t];
            const Mat2 ds = edges(t, mX);
            const Mat2 r = fr.rotation, rtf = r.transposed() * (ds * mRest.inverse);
            // The strain of R^T F against I, as a displacement gradient R (R^T F - I).
            const Mat2 strain = r * Mat2{rtf.a - 1.0, rtf.b, rtf.c, rtf.d - 1.0};
            scatter(t, stress(r, strain, mMu, mLambda), f);
        }
        return filtered(f);
    }

    /// (I + dt K) dx, dx filtered; K the stiffness turned by each triangle's rotation.
    std::vector<Vec3d> apply(const std::vector<Vec3d>& dx) const
    {
        std::vector<Vec3d> k(mX.size(), Vec3d(0.0));
        for (std::size_t t = 0; t < mTriangles.size(); ++t)
            scatter(t, stress(mFrames[t].rotation, edges(t, dx) * mRest.inverse, mMu, mLambda), k);
        for (std::size_t i = 0; i < k.size(); ++i) k[i] = dx[i] - k[i];
        return filtered(k);
    }

    std::vector<Vec3d> filtered(std::vector<Vec3d> vectors) const
    {
        for (std::size_t i = 0; i < vectors.size(); ++i)
            vectors[i] = mFixed[i] ? Vec3d(0.0) : vectors[i] - mNormals[i] * mNormals[i].dot(vectors[i]);
        return vectors;
    }

private:
    Frame frameOf(std::size_t t) const
    {
        const auto& [a, b, c] = mTriangles[t];
        Frame fr;
        const Vec3d ab = mX[b] - mX[a], ac = mX[c] - mX[a], n = ab.cross(ac);
        if (ab.length() < 1e-12 || n.length() < 1e-12) return fr;  // degenerate: no force
        fr.u = ab.unitSafe();
        fr.v = n.unitSafe().cross(fr.u);
        const Mat2 f = edges(t, mX, fr) * mRest.inverse;
        const double angle = std::atan2(f.c - f.b, f.a + f.d);
        fr.rotation = {std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)};
        return fr;
    }

    Mat2 edges(std::size_t t, const std::vector<Vec3d>& y) const { return edges(t, y, mFrames[t]); }

    /// The triangle's two edges from its first vertex, of the vectors `y`, in the frame.
    Mat2 edges(std::size_t t, const std::vector<Vec3d>& y, const Frame& fr) const
    {
        const auto& [a, b, c] = mTriangles[t];
        const Vec3d ab = y[b] - y[a], ac = y[c] - y[a];
        return columns(ab.dot(fr.u), ab.dot(fr.v), ac.dot(fr.u), ac.dot(fr.v));
    }

    /// Adds the nodal forces -A P Dm^-T of the stress P to the triangle's vertices.
    void scatter(std::size_t t, const Mat2& p, std::vector<Vec3d>& out) const
    {
        const Mat2 h = p * mRest.inverse.transposed();
        const Frame& fr = mFrames[t];
        const Vec3d fb = -mRest.area * (fr.u * h.a + fr.v * h.c), fc = -mRest.area * (fr.u * h.b + fr.v * h.d);
        const auto& [a, b, c] = mTriangles[t];
        out[a] -= fb + fc;
        out[b] += fb;
        out[c] += fc;
    }

    const std::vector<Vec3d>& mX;
    const Triangles& mTriangles;
    const std::vector<Vec3d>& mNormals;
    const std::vector<std::uint8_t>& mFixed;
    RestShape mRest;
    std::vector<Frame> mFrames;
    double mMu = 0.0, mLambda = 0.0;
};

double dot(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += a[i].dot(b[i]);
    return sum;
}

}  // namespace

std::vector<Vec3d> relaxationStep(const std::vector<Vec3d>& positions, const Triangles& triangles,
                                  const std::vector<Vec3d>& normals, const std::vector<std::uint8_t>& fixed,
                                  const RelaxOptions& options)
{
    const Solver solver(positions, triangles, normals, fixed, options);
    // Conjugate gradient on (I + dt K) dx = dt f from dx = 0, every vector in the tangent planes.
    std::vector<Vec3d> dx(positions.size(), Vec3d(0.0)), r = solver.forces(), p = r;
    double rr = dot(r, r);
    for (int step = 0; step < options.conjugateGradientSteps && rr > 1e-24; ++step) {
        const std::vector<Vec3d> ap = solver.apply(p);
        const double pap = dot(p, ap);
        if (pap <= 0.0) break;
        const double alpha = rr / pap;
        for (std::size_t i = 0; i < dx.size(); ++i) {
            dx[i] += alpha * p[i];
            r[i] -= alpha * ap[i];
        }
        const double next = dot(r, r), beta = next / rr;
        rr = next;
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = r[i] + beta * p[i];
    }
    return dx;
}

}  // namespace sculpt
