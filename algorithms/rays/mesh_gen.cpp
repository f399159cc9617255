#include "rays/mesh_gen.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "core/rng.hpp"
#include "core/step.hpp"
#include "curves/bezier_patch.hpp"
#include "modelling/fractal_terrain.hpp"

namespace cg::mesh {

using glm::dvec2;
using glm::dvec3;

namespace {

constexpr double kMaxCoordinate = 1e12;  // as rt::kMaxCoordinate

void check_finite(double x, const std::string& field) {
    if (!std::isfinite(x) || std::fabs(x) > kMaxCoordinate)
        throw InputError(field,
                         "must be a finite number of magnitude at most 1e12 (got " + given(x) + ")");
}

void check_point(dvec3 p, const std::string& field) {
    for (int k = 0; k < 3; ++k) check_finite(p[k], field + "[" + std::to_string(k) + "]");
}

void check_count(int n, int lo, int hi, const std::string& field) {
    if (n < lo || n > hi)
        throw InputError(field, "must be between " + std::to_string(lo) + " and " +
                                    std::to_string(hi) + " (got " + std::to_string(n) + ")");
}

int sphere_rings(int segments) {
    return std::max(2, segments / 2);
}

}  // namespace

bool degenerate(dvec3 p0, dvec3 p1, dvec3 p2) {
    const dvec3 e1 = p1 - p0, e2 = p2 - p0;
    const double area2 = glm::length(glm::cross(e1, e2));
    return !(area2 > 1e-12 * glm::length(e1) * glm::length(e2)) || !(area2 > 0);
}

// ---- validation and counts ----------------------------------------------------------------

void validate(const SphereParams& p, const std::string& field) {
    check_point(p.center, field + ".center");
    check_finite(p.radius, field + ".radius");
    if (!(p.radius > 0))
        throw InputError(field + ".radius", "must be positive (got " + given(p.radius) + ")");
    check_count(p.segments, 3, kMaxSphereSegments, field + ".segments");
}

void validate(const TerrainParams& p, const std::string& field) {
    check_point(p.center, field + ".center");
    for (int k = 0; k < 2; ++k) {
        const std::string f = field + ".size[" + std::to_string(k) + "]";
        check_finite(p.size[k], f);
        if (!(p.size[k] > 0))
            throw InputError(f, "must be positive: the terrain's extent along " +
                                    std::string(k == 0 ? "x" : "z") + " (got " + given(p.size[k]) +
                                    ")");
    }
    check_count(p.resolution, 1, kMaxTerrainResolution, field + ".resolution");
    check_finite(p.height, field + ".height");
    if (!(p.height >= 0))
        throw InputError(field + ".height",
                         "must be at least 0: the largest |height| (got " + given(p.height) + ")");
    if (!(p.roughness >= 0 && p.roughness <= 1))
        throw InputError(field + ".roughness",
                         "must be between 0 (smooth) and 1 (rough): the amplitude's factor per "
                         "level (got " +
                             given(p.roughness) + ")");
}

void validate(const PatchParams& p, const std::string& field) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            check_point(p.control_points[i][j], field + ".control_points[" + std::to_string(i) +
                                                    "][" + std::to_string(j) + "]");
    check_count(p.segments, 1, kMaxPatchSegments, field + ".segments");
}

std::size_t sphere_triangles(int segments) {
    return 2 * static_cast<std::size_t>(segments) * (sphere_rings(segments) - 1);
}
std::size_t terrain_triangles(int resolution) {
    return 2 * static_cast<std::size_t>(resolution) * resolution;
}
std::size_t patch_triangles(int segments) {
    return 2 * static_cast<std::size_t>(segments) * segments;
}

// ---- sphere --------------------------------------------------------------------------------

Mesh sphere(const SphereParams& p) {
    const int n = p.segments, rings = sphere_rings(n);
    const std::size_t row = static_cast<std::size_t>(n) + 1;
    Mesh m;
    m.vertices.resize((rings + 1) * row);
    m.normals.resize(m.vertices.size());
    m.uv.resize(m.vertices.size());
    for (int i = 0; i <= rings; ++i) {
        const double theta = M_PI * (1 - static_cast<double>(i) / rings);
        // Exact poles, so that the pole's copies coincide.
        const double st = i == 0 || i == rings ? 0.0 : std::sin(theta);
        const double ct = i == 0 ? -1.0 : i == rings ? 1.0 : std::cos(theta);
        for (int k = 0; k <= n; ++k) {
            const double phi = 2 * M_PI * k / n;
            // The seam's last column repeats the first exactly.
            const double sp = k == n ? 0.0 : std::sin(phi), cp = k == n ? 1.0 : std::cos(phi);
            const dvec3 dir(st * sp, ct, st * cp);
            const std::size_t v = i * row + k;
            m.normals[v] = dir;
            m.vertices[v] = p.center + p.radius * dir;
            m.uv[v] = dvec2(static_cast<double>(k) / n, static_cast<double>(i) / rings);
        }
    }
    m.triangles.reserve(sphere_triangles(n));
    for (int i = 0; i < rings; ++i)
        for (int k = 0; k < n; ++k) {
            const auto a = static_cast<std::uint32_t>(i * row + k), b = a + 1,
                       c = static_cast<std::uint32_t>(b + row),
                       d = static_cast<std::uint32_t>(a + row);
            if (i > 0) m.triangles.push_back({a, b, c});          // not at the south pole
            if (i < rings - 1) m.triangles.push_back({a, c, d});  // not at the north pole
        }
    return m;
}

// ---- terrain -------------------------------------------------------------------------------

Mesh terrain(const TerrainParams& p) {
    const int n = p.resolution;
    int N = 1, levels = 0;
    while (N < n) N *= 2, ++levels;
    const std::size_t side = static_cast<std::size_t>(N) + 1;
    std::vector<double> h(side * side, 0.0);
    auto at = [&](int i, int j) -> double& { return h[static_cast<std::size_t>(j) * side + i]; };
    Rng rng(p.seed);
    at(0, 0) = rng.uniform(-1, 1);
    at(N, 0) = rng.uniform(-1, 1);
    at(0, N) = rng.uniform(-1, 1);
    at(N, N) = rng.uniform(-1, 1);
    // The amplitude ρ at the first level, ρ² at the second, … (modelling/fractal_terrain).
    fractal::diamond_square(h, levels, p.roughness, p.roughness, rng);
    double big = 0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) big = std::max(big, std::fabs(at(i, j)));
    const double scale = big > 0 ? p.height / big : 0.0;

    const std::size_t row = static_cast<std::size_t>(n) + 1;
    Mesh m;
    m.vertices.resize(row * row);
    m.normals.resize(row * row);
    m.uv.resize(row * row);
    const double dx = p.size.x / n, dz = p.size.y / n;
    auto y = [&](int i, int j) { return scale * at(i, j); };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const std::size_t v = j * row + i;
            const double u = static_cast<double>(i) / n, w = static_cast<double>(j) / n;
            m.vertices[v] = p.center + dvec3(p.size.x * (u - 0.5), y(i, j), p.size.y * (w - 0.5));
            m.uv[v] = dvec2(u, w);
            const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, n);
            const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, n);
            const double gx = (y(i1, j) - y(i0, j)) / ((i1 - i0) * dx);
            const double gz = (y(i, j1) - y(i, j0)) / ((j1 - j0) * dz);
            m.normals[v] = glm::normalize(dvec3(-gx, 1, -gz));
        }
    m.triangles.reserve(terrain_triangles(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto a0 = static_cast<std::uint32_t>(j * row + i), a1 = a0 + 1,
                       b0 = static_cast<std::uint32_t>(a0 + row), b1 = b0 + 1;
            // Counter-clockwise seen from above (+y).
            m.triangles.push_back({a0, b1, a1});
            m.triangles.push_back({a0, b0, b1});
        }
    return m;
}

// ---- patch ---------------------------------------------------------------------------------

Mesh patch(const PatchParams& p) {
    const auto& P = p.control_points;
    BezierPatch::Input net, ds, dt;
    net.control_points.assign(4, std::vector<dvec3>(4));
    ds.control_points.assign(3, std::vector<dvec3>(4));
    dt.control_points.assign(4, std::vector<dvec3>(3));
    double scale = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            net.control_points[i][j] = P[i][j];
            if (i < 3) ds.control_points[i][j] = 3.0 * (P[i + 1][j] - P[i][j]);
            if (j < 3) dt.control_points[i][j] = 3.0 * (P[i][j + 1] - P[i][j]);
            for (int k = 0; k < 3; ++k) scale = std::max(scale, std::fabs(P[i][j][k]));
        }
    const int n = p.segments;
    const std::size_t row = static_cast<std::size_t>(n) + 1;
    Mesh m;
    m.vertices = BezierPatch::tessellate(net, n);
    m.normals.resize(m.vertices.size());
    m.uv.resize(m.vertices.size());
    bool smooth = true;
    for (int a = 0; a <= n; ++a)
        for (int b = 0; b <= n; ++b) {
            const double s = static_cast<double>(a) / n, t = static_cast<double>(b) / n;
            const std::size_t v = a * row + b;
            m.uv[v] = dvec2(s, t);
            dvec3 normal;
            if (BezierPatch::unit_normal(BezierPatch::point_at(ds, s, t),
                                         BezierPatch::point_at(dt, s, t), scale, normal)) {
                m.normals[v] = normal;
                continue;
            }
            const double s2 = 0.5 + (s - 0.5) * (1 - 1e-4), t2 = 0.5 + (t - 0.5) * (1 - 1e-4);
            if (BezierPatch::unit_normal(BezierPatch::point_at(ds, s2, t2),
                                         BezierPatch::point_at(dt, s2, t2), scale, normal))
                m.normals[v] = normal;
            else
                smooth = false;
        }
    if (!smooth) m.normals.clear();
    m.triangles.reserve(patch_triangles(n));
    // The net's extent: a triangle with |e1 × e2| below 1e-20 of its square is rounding noise
    // of a collapsed edge (de Casteljau on equal points may differ from them in the last bit).
    dvec3 lo = P[0][0], hi = P[0][0];
    for (const auto& row_points : P)
        for (const dvec3& q : row_points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    auto add = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
        const dvec3 a = m.vertices[i], b = m.vertices[j], c = m.vertices[k];
        if (!(glm::length(glm::cross(b - a, c - a)) > 1e-20 * extent * extent)) return;
        if (!degenerate(m.vertices[i], m.vertices[j], m.vertices[k]))
            m.triangles.push_back({i, j, k});
    };
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const auto v00 = static_cast<std::uint32_t>(a * row + b), v01 = v00 + 1,
                       v10 = static_cast<std::uint32_t>(v00 + row), v11 = v10 + 1;
            add(v00, v10, v11);  // (a, b) (a+1, b) (a+1, b+1)
            add(v00, v11, v01);  // (a, b) (a+1, b+1) (a, b+1)
        }
    return m;
}

}  // namespace cg::mesh
