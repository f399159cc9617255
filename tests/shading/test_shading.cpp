// Flat, Gouraud and Phong shading: exam cases worked by hand (a right triangle with 3-4-5
// normals, a folded square); the area-weighted vertex normals; thousands of random meshes —
// height-field grids, overlapping soups, degenerate triangles — against an independent
// reference in long double (barycentric coordinates from the definition at every pixel centre,
// the lighting model term by term, coverage from scan-triangle's own pixels and the depth test
// from its definition); run-to-end against the plain function; errors naming the field;
// determinism and the picture.
//
// Sections: [reference] [hand cases] [normals] [random meshes] [errors] [determinism] [picture]
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <set>

#include "io/registry.hpp"
#include "raster/scan_triangle.hpp"
#include "rays/phong_reference.hpp"  // tests/rays: the lighting model in long double
#include "shading/shading.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Shading;
using glm::dvec2;
using glm::dvec3;
using Model = Shading::Model;
using cg::test::L3;

namespace {

// ---- [reference] ----------------------------------------------------------------------------

struct LV {
    long double x = 0, y = 0, z = 0;
};
LV operator+(LV a, LV b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
LV operator*(long double s, LV a) {
    return {s * a.x, s * a.y, s * a.z};
}
LV lv(dvec3 v) {
    return {v.x, v.y, v.z};
}
long double llen(LV a) {
    return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}
LV lunit(LV a) {
    const long double n = llen(a);
    return n == 0 ? LV{} : LV{a.x / n, a.y / n, a.z / n};
}
dvec3 dv(LV a) {
    return {double(a.x), double(a.y), double(a.z)};
}
LV lcross(LV a, LV b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The lighting at a point with a normal, in long double (tests/rays/phong_reference.hpp).
LV light(const Shading::Input& in, LV P, LV n) {
    cg::PhongLighting::Input L = in.lighting;
    L.point = dv(P);
    L.normal = dv(n);
    const cg::test::LongShade s = cg::test::reference_shade(L);
    return {s.intensity[0], s.intensity[1], s.intensity[2]};
}

// Twice the signed area of (a, b, c) in (x, y), from the definition.
long double area2(LV a, LV b, LV c) {
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

struct Reference {
    std::vector<LV> normals;  // unit
    std::vector<bool> lit;
    std::vector<LV> vertex_colors;  // Gouraud
    std::vector<int> ids;           // per pixel: the visible triangle (−1 none)
    std::vector<bool> tie;          // the two nearest triangles there are within 1e-9 in z
    long long evaluations = 0;
};

// Everything from the definitions: coverage is scan-triangle's own pixels for each triangle (the
// fill rule is tested there), depth the barycentric interpolation at the centre, the nearest
// (then the lowest index) visible; vertex normals the normalised sum of the faces' cross products
// turned to face −z.
Reference reference(const Shading::Input& in) {
    Reference r;
    const auto& mesh = in.mesh;
    const std::size_t nv = mesh.vertices.size();
    r.normals.assign(nv, LV{});
    r.lit.assign(nv, false);
    std::vector<bool> has_area(mesh.triangles.size(), false);
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& t = mesh.triangles[k];
        cg::ScanTriangle::Input st{in.width, in.height, {}, {}};
        for (long long v : t) st.triangle.push_back({mesh.vertices[v].x, mesh.vertices[v].y});
        if (!cg::ScanTriangle::scan(st).split) continue;  // collinear: no area
        has_area[k] = true;
        const LV a = lv(mesh.vertices[t[0]]), b = lv(mesh.vertices[t[1]]),
                 c = lv(mesh.vertices[t[2]]);
        LV n = lcross(b + (-1.0L) * a, c + (-1.0L) * a);
        if (n.z > 0) n = (-1.0L) * n;
        for (long long v : t) {
            r.lit[v] = true;
            r.normals[v] = r.normals[v] + n;
        }
    }
    for (std::size_t v = 0; v < nv; ++v)
        if (r.lit[v])
            r.normals[v] = lunit(mesh.normals.empty() ? r.normals[v] : lv(mesh.normals[v]));
    if (in.model == Model::Gouraud) {
        r.vertex_colors.assign(nv, LV{});
        for (std::size_t v = 0; v < nv; ++v)
            if (r.lit[v]) {
                r.vertex_colors[v] = light(in, lv(mesh.vertices[v]), r.normals[v]);
                ++r.evaluations;
            }
    }
    if (in.model == Model::Flat)
        for (bool b : has_area) r.evaluations += b;
    const std::size_t W = std::size_t(in.width), H = std::size_t(in.height);
    std::vector<long double> best(W * H, std::numeric_limits<long double>::infinity()),
        second(W * H, std::numeric_limits<long double>::infinity());
    r.ids.assign(W * H, -1);
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& t = mesh.triangles[k];
        cg::ScanTriangle::Input st{in.width, in.height, {}, {}};
        for (long long v : t) st.triangle.push_back({mesh.vertices[v].x, mesh.vertices[v].y});
        for (const glm::ivec2 p : cg::ScanTriangle::scan(st).pixels) {
            const LV a = lv(mesh.vertices[t[0]]), b = lv(mesh.vertices[t[1]]),
                     c = lv(mesh.vertices[t[2]]);
            const LV q{p.x + 0.5L, p.y + 0.5L, 0};
            const long double d = area2(a, b, c);
            const long double z =
                (area2(q, b, c) * a.z + area2(a, q, c) * b.z + area2(a, b, q) * c.z) / d;
            const std::size_t at = std::size_t(p.y) * W + std::size_t(p.x);
            if (z < best[at]) {
                second[at] = best[at];
                best[at] = z;
                r.ids[at] = int(k);
            } else if (z < second[at]) {
                second[at] = z;
            }
        }
    }
    r.tie.assign(W * H, false);
    for (std::size_t at = 0; at < W * H; ++at) r.tie[at] = second[at] - best[at] < 1e-9L;
    return r;
}

// The colour the model gives triangle k at pixel (i, j), from the reference's normals.
LV expected_color(const Shading::Input& in, const Reference& ref, int k, int i, int j) {
    const auto& t = in.mesh.triangles[std::size_t(k)];
    const LV a = lv(in.mesh.vertices[t[0]]), b = lv(in.mesh.vertices[t[1]]),
             c = lv(in.mesh.vertices[t[2]]);
    const LV q{i + 0.5L, j + 0.5L, 0};
    const long double d = area2(a, b, c);
    const long double l0 = area2(q, b, c) / d, l1 = area2(a, q, c) / d, l2 = area2(a, b, q) / d;
    switch (in.model) {
        case Model::Flat: {
            LV n = lcross(b + (-1.0L) * a, c + (-1.0L) * a);
            if (n.z > 0) n = (-1.0L) * n;
            return light(in, (1.0L / 3) * (a + b + c), lunit(n));
        }
        case Model::Gouraud:
            return l0 * ref.vertex_colors[t[0]] + l1 * ref.vertex_colors[t[1]] +
                   l2 * ref.vertex_colors[t[2]];
        case Model::Phong: {
            const LV P{q.x, q.y, l0 * a.z + l1 * b.z + l2 * c.z};
            const LV n = l0 * ref.normals[t[0]] + l1 * ref.normals[t[1]] + l2 * ref.normals[t[2]];
            return light(in, P, lunit(n));
        }
    }
    return {};
}

double diff(dvec3 a, LV b) {
    auto rel = [](double x, long double y) {
        return double(std::fabs(x - y) / std::max(1.0L, std::fabs(y)));
    };
    return std::max({rel(a.x, b.x), rel(a.y, b.y), rel(a.z, b.z)});
}

// Compares a result with the reference at every pixel; returns the pixels checked.
long long check_against_reference(const Shading::Input& in, const Shading::Result& r) {
    const Reference ref = reference(in);
    CHECK(r.evaluations >= 0);
    if (in.model != Model::Phong) CHECK(r.evaluations == ref.evaluations);
    long long checked = 0, written = 0;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const std::size_t at = std::size_t(j) * std::size_t(r.width) + std::size_t(i);
            const Shading::Sample& p = r.at(i, j);
            CAPTURE(i, j, ref.ids[at], p.triangle);
            if (ref.ids[at] < 0) {
                REQUIRE(p.triangle == -1);
                continue;
            }
            if (!ref.tie[at]) REQUIRE(p.triangle == ref.ids[at]);
            REQUIRE(p.triangle >= 0);
            const double d = diff(p.color, expected_color(in, ref, p.triangle, i, j));
            CAPTURE(d);
            REQUIRE(d < 1e-9);
            ++checked;
        }
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) written += r.at(i, j).triangle >= 0;
    if (in.model == Model::Phong) CHECK(r.evaluations >= written);
    if (in.model != Model::Flat)
        for (std::size_t v = 0; v < in.mesh.vertices.size(); ++v) {
            REQUIRE(r.lit[v] == ref.lit[v]);
            if (ref.lit[v]) REQUIRE(diff(r.normals[v], ref.normals[v]) < 1e-12);
        }
    return checked;
}

cg::PhongLighting::Input simple_lighting(double ka, double kd) {
    cg::PhongLighting::Input L;
    L.model = cg::PhongLighting::Model::Phong;
    L.eye = {6, 5, -20};
    L.ambient = dvec3(1);
    L.material.ka = dvec3(ka);
    L.material.kd = dvec3(kd);
    L.material.ks = dvec3(0);
    L.material.shininess = 1;
    cg::PhongLighting::Light light;
    light.directional = true;
    light.direction = {0, 0, 1};
    L.lights.push_back(light);
    return L;
}

// The right triangle (2, 1), (10, 1), (2, 9) with 3-4-5 normals, k_a = 0.1, k_d = 0.8.
Shading::Input right_triangle(Model model) {
    Shading::Input in;
    in.width = 12, in.height = 10;
    in.model = model;
    in.mesh.vertices = {{2, 1, 5}, {10, 1, 7}, {2, 9, 9}};
    in.mesh.normals = {{0, 0, -1}, {3, 0, -4}, {0, 0.6, -0.8}};
    in.mesh.triangles = {{0, 1, 2}};
    in.lighting = simple_lighting(0.1, 0.8);
    in.has_pixel = true;
    in.pixel = {4, 3};
    return in;
}

using Traced = cg::test::Traced<Shading>;

const Shading::Sample& at(const Shading::Result& r, int i, int j) {
    return r.at(i, j);
}

}  // namespace

// ---- [hand cases] ---------------------------------------------------------------------------

TEST_CASE("shading: Gouraud on a right triangle, worked by hand", "[shading]") {
    // Vertex colours k_a + k_d (−n_z): 0.1 + 0.8 = 0.9, 0.1 + 0.8·0.8 = 0.74 twice. Pixel (4, 3)
    // has its centre (4.5, 3.5) at u = 2.5/8 along each leg: λ = (0.375, 0.3125, 0.3125).
    const Traced t = cg::test::run_traced<Shading>(right_triangle(Model::Gouraud));
    REQUIRE(t.result.vertex_colors.size() == 3);
    CHECK(t.result.vertex_colors[0].x == Approx(0.9));
    CHECK(t.result.vertex_colors[1].x == Approx(0.74));
    CHECK(t.result.vertex_colors[2].x == Approx(0.74));
    CHECK(at(t.result, 4, 3).color.x == Approx(0.375 * 0.9 + 0.625 * 0.74).epsilon(1e-12));
    CHECK(at(t.result, 4, 3).color.x == Approx(0.8).epsilon(1e-12));
    CHECK(t.result.evaluations == 3);
    const auto e = cg::test::events(t);
    CHECK(e.front() == "normals-given");
    CHECK(e[1] == "vertex-colors");
    CHECK(e[2] == "triangle");
    CHECK(e.back() == "done");
    CHECK(std::count(e.begin(), e.end(), "pixel-gouraud") == 1);
    for (const auto& s : t.steps)
        if (s.event == "pixel-gouraud") {
            CHECK_THAT(s.narration, Catch::Contains("λ = (0.375, 0.3125, 0.3125)"));
            CHECK_THAT(s.narration, Catch::Contains("= 0.8."));
        }
    // The centres strictly inside have u + v < 8 along the legs: 28 of them. The 8 centres on
    // the hypotenuse are out: it is a right edge (the inside lies to its left, −x).
    long long covered = 0;
    for (int j = 0; j < t.result.height; ++j)
        for (int i = 0; i < t.result.width; ++i) covered += at(t.result, i, j).triangle >= 0;
    CHECK(covered == 28);
}

TEST_CASE("shading: Phong at the same pixel normalises the interpolated normal", "[shading]") {
    // n = 0.375 (0, 0, −1) + 0.3125 (0.6, 0, −0.8) + 0.3125 (0, 0.6, −0.8)
    //   = (0.1875, 0.1875, −0.875), |n|² = 0.8359375: I = 0.1 + 0.8 · 0.875/|n| = 0.86562.
    const Traced t = cg::test::run_traced<Shading>(right_triangle(Model::Phong));
    const double expected = 0.1 + 0.8 * 0.875 / std::sqrt(0.8359375);
    CHECK(at(t.result, 4, 3).color.x == Approx(expected).epsilon(1e-12));
    CHECK(expected == Approx(0.865616).epsilon(1e-6));
    CHECK(t.result.evaluations == 28);  // one per pixel written
    bool seen = false;
    for (const auto& s : t.steps)
        if (s.event == "pixel-phong") {
            seen = true;
            CHECK_THAT(s.narration, Catch::Contains("n = Σ λ_k n_k = (0.1875, 0.1875, −0.875)"));
            CHECK_THAT(s.narration, Catch::Contains("|n| = 0.9143"));
        }
    CHECK(seen);
    // Gouraud's 0.8 is darker: interpolating colours flattens what the normals would give.
    CHECK(at(t.result, 4, 3).color.x > 0.8 + 0.06);
}

TEST_CASE("shading: flat shading of a folded square, one evaluation per face", "[shading]") {
    // The square (2, 1)–(10, 9) cut along its diagonal: the lower-right face rises 0.75 per pixel
    // along x (normal (0.6, 0, −0.8): 0.1 + 0.8·0.8 = 0.74), the upper-left along y (the same
    // light by symmetry); a flat face (0, 0, −1) would give 0.9.
    Shading::Input in;
    in.width = 12, in.height = 10;
    in.model = Model::Flat;
    in.mesh.vertices = {{2, 1, 10}, {10, 1, 16}, {10, 9, 16}, {2, 9, 16}};
    in.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    in.lighting = simple_lighting(0.1, 0.8);
    in.has_pixel = true;
    in.pixel = {8, 3};
    const Traced t = cg::test::run_traced<Shading>(in);
    CHECK(t.result.evaluations == 2);
    CHECK(at(t.result, 8, 3).color.x == Approx(0.74).epsilon(1e-12));
    CHECK(at(t.result, 8, 3).triangle == 0);
    CHECK(at(t.result, 3, 7).triangle == 1);
    CHECK(at(t.result, 3, 7).color.x == Approx(0.74).epsilon(1e-12));
    const auto e = cg::test::events(t);
    CHECK(e.front() == "flat-face");  // flat needs no vertex normals
    CHECK(std::count(e.begin(), e.end(), "flat-face") == 2);
    CHECK(std::count(e.begin(), e.end(), "pixel-flat") == 1);
    // A steeper lower face: dz/dx = 0.75 → 1 (normal (1, 0, −1)/√2): darker, 0.1 + 0.8/√2.
    in.mesh.vertices = {{2, 1, 10}, {10, 1, 18}, {10, 9, 18}, {2, 9, 18}};
    const Shading::Result r = Shading::render(in);
    CHECK(at(r, 8, 3).color.x == Approx(0.1 + 0.8 / std::sqrt(2.0)).epsilon(1e-12));
}

TEST_CASE("shading: overlapping triangles keep the nearer, as the z-buffer does", "[shading]") {
    Shading::Input in = right_triangle(Model::Gouraud);
    in.mesh.vertices.push_back({0, 0, 1});  // a big triangle in front (z = 1 < 5 … 9)
    in.mesh.vertices.push_back({12, 0, 1});
    in.mesh.vertices.push_back({0, 10, 1});
    in.mesh.normals.push_back({0, 0, -1});
    in.mesh.normals.push_back({0, 0, -1});
    in.mesh.normals.push_back({0, 0, -1});
    in.mesh.triangles.push_back({3, 4, 5});
    const Traced t = cg::test::run_traced<Shading>(in);
    CHECK(at(t.result, 4, 3).triangle == 1);
    CHECK(at(t.result, 4, 3).z == Approx(1));
    CHECK(at(t.result, 4, 3).color.x == Approx(0.9));
    // Drawn the other way round, the far triangle loses the depth test at the chosen pixel.
    std::swap(in.mesh.triangles[0], in.mesh.triangles[1]);
    const Traced u = cg::test::run_traced<Shading>(in);
    CHECK(at(u.result, 4, 3).triangle == 0);
    const auto e = cg::test::events(u);
    CHECK(std::count(e.begin(), e.end(), "pixel-hidden") == 1);
    CHECK(std::count(e.begin(), e.end(), "pixel-gouraud") == 1);
    // Equal depth: the earlier triangle stays (only a strictly nearer z replaces).
    Shading::Input same = in;
    for (auto& v : same.mesh.vertices) v.z = 3;
    const Shading::Result r = Shading::render(same);
    CHECK(at(r, 4, 3).triangle == 0);
}

// ---- [normals] ------------------------------------------------------------------------------

TEST_CASE("shading: vertex normals are area-weighted averages turned to the viewer", "[shading]") {
    // Two faces meet at V0 = V1's edge: a big flat one (area 32, normal (0, 0, −1)) and a small
    // tilted one (area 2 on the screen). Their cross products, twice their 3D areas long, add.
    Shading::Input in;
    in.width = 12, in.height = 10;
    in.model = Model::Gouraud;
    in.mesh.vertices = {{2, 1, 5}, {10, 1, 5}, {2, 9, 5}, {6, 0, 7}};
    in.mesh.triangles = {
        {0, 1, 2},   // (P1 − P0) × (P2 − P0) = (0, 0, 64): turned to (0, 0, −64)
        {1, 0, 3}};  // (−8, 0, 0) × (−4, −1, 2) = (0, 16, 8): turned to (0, −16, −8)
    in.lighting = simple_lighting(0.1, 0.8);
    const Shading::Result r = Shading::render(in);
    // Both are counter-clockwise on the screen, so both cross products are turned; V0 and V1
    // belong to both faces and take the sum, V2 and V3 one face each.
    const dvec3 n0 = glm::normalize(dvec3(0, 0, -64) + dvec3(0, -16, -8));
    CHECK(glm::length(r.normals[0] - n0) < 1e-15);
    CHECK(glm::length(r.normals[1] - n0) < 1e-15);
    CHECK(glm::length(r.normals[2] - dvec3(0, 0, -1)) < 1e-15);
    CHECK(glm::length(r.normals[3] - glm::normalize(dvec3(0, -16, -8))) < 1e-15);
    // A degenerate face adds nothing, and a vertex only it uses is not lit.
    in.mesh.vertices.push_back({4, 4, 0});
    in.mesh.vertices.push_back({8, 8, 0});
    in.mesh.triangles.push_back({0, 4, 5});  // (2, 1), (4, 4), (8, 8): not collinear
    in.mesh.triangles.back() = {2, 2, 4};    // a repeated index: no area
    const Shading::Result d = Shading::render(in);
    CHECK(glm::length(d.normals[2] - dvec3(0, 0, -1)) < 1e-15);
    CHECK_FALSE(d.lit[4]);
    CHECK(d.evaluations == 4);  // Gouraud: the four lit vertices
}

// ---- [random meshes] ------------------------------------------------------------------------

namespace {

double quarter(cg::Rng& rng, double lo, double hi) {
    return std::round(rng.uniform(lo, hi) * 4) / 4;
}

cg::PhongLighting::Input random_lighting(cg::Rng& rng, double cx, double cy) {
    cg::PhongLighting::Input L;
    L.model =
        rng.chance(0.5) ? cg::PhongLighting::Model::Phong : cg::PhongLighting::Model::BlinnPhong;
    L.rgb = rng.chance(0.3);
    auto colour = [&] {
        return L.rgb ? dvec3(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1))
                     : dvec3(rng.uniform(0, 1));
    };
    L.eye = {cx + rng.uniform(-10, 10), cy + rng.uniform(-10, 10), rng.uniform(-40, -15)};
    L.ambient = colour();
    L.material.ka = colour();
    L.material.kd = colour();
    L.material.ks = colour();
    L.material.shininess = rng.chance(0.1) ? 0 : std::round(rng.uniform(1, 60));
    const int n = int(rng.integer(1, 2));
    for (int i = 0; i < n; ++i) {
        cg::PhongLighting::Light light;
        light.intensity = colour();
        if (rng.chance(0.3)) {
            light.directional = true;
            light.direction = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.2, 1)};
        } else {
            light.position = {cx + rng.uniform(-20, 20), cy + rng.uniform(-20, 20),
                              rng.uniform(-40, -12)};
            if (rng.chance(0.3))
                light.attenuation = {1, rng.uniform(0, 0.05), rng.uniform(0, 0.002)};
        }
        L.lights.push_back(light);
    }
    return L;
}

// A height field on a grid (triangles share edges: each pixel covered once), an overlapping soup,
// or either with degenerate triangles mixed in.
Shading::Input random_mesh(cg::Rng& rng) {
    Shading::Input in;
    in.width = rng.integer(4, 24);
    in.height = rng.integer(4, 20);
    const double W = double(in.width), H = double(in.height);
    auto& m = in.mesh;
    if (rng.chance(0.5)) {
        const int nx = int(rng.integer(2, 4)), ny = int(rng.integer(2, 4));
        for (int b = 0; b < ny; ++b)
            for (int a = 0; a < nx; ++a) {
                const double x = quarter(rng, -1, W + 1) * 0 + (W + 2) * a / (nx - 1) - 1;
                const double y = (H + 2) * b / (ny - 1) - 1;
                const double jx = (a > 0 && a < nx - 1) ? quarter(rng, -0.75, 0.75) : 0;
                const double jy = (b > 0 && b < ny - 1) ? quarter(rng, -0.75, 0.75) : 0;
                m.vertices.push_back({std::round((x + jx) * 4) / 4, std::round((y + jy) * 4) / 4,
                                      quarter(rng, 0, 10)});
            }
        for (int b = 0; b + 1 < ny; ++b)
            for (int a = 0; a + 1 < nx; ++a) {
                const long long v00 = b * nx + a, v10 = v00 + 1, v01 = v00 + nx, v11 = v01 + 1;
                if (rng.chance(0.5)) {
                    m.triangles.push_back({v00, v10, v11});
                    m.triangles.push_back({v00, v11, v01});
                } else {
                    m.triangles.push_back({v00, v10, v01});
                    m.triangles.push_back({v10, v11, v01});
                }
            }
    } else {
        const int n = int(rng.integer(1, 6));
        for (int k = 0; k < n; ++k) {
            const long long base = static_cast<long long>(m.vertices.size());
            for (int c = 0; c < 3; ++c)
                m.vertices.push_back(
                    {quarter(rng, -3, W + 3), quarter(rng, -3, H + 3), quarter(rng, 0, 20)});
            m.triangles.push_back({base, base + 1, base + 2});
        }
    }
    if (rng.chance(0.3)) {  // degenerate: collinear, coincident, repeated index
        const long long base = static_cast<long long>(m.vertices.size());
        const dvec3 a{quarter(rng, 0, W), quarter(rng, 0, H), 1};
        const dvec3 d{quarter(rng, -2, 2), quarter(rng, -2, 2), 0.5};
        m.vertices.push_back(a);
        m.vertices.push_back(a + d);
        m.vertices.push_back(a + 2.0 * d);
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base, base + 1});
    }
    if (rng.chance(0.3))
        for (std::size_t v = 0; v < m.vertices.size(); ++v)
            m.normals.push_back(
                {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-1, -0.3)});
    in.model = static_cast<Model>(rng.integer(0, 2));
    in.lighting = random_lighting(rng, W / 2, H / 2);
    if (rng.chance(0.5)) {
        in.has_pixel = true;
        in.pixel = {rng.integer(0, in.width - 1), rng.integer(0, in.height - 1)};
    }
    return in;
}

}  // namespace

TEST_CASE("shading: 3,000 random meshes agree with the long-double reference at every pixel",
          "[shading][random]") {
    long long pixels = 0, meshes = 0;
    for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
        cg::Rng rng(seed);
        const Shading::Input in = random_mesh(rng);
        CAPTURE(seed, Shading::model_id(in.model), in.width, in.height);
        const Shading::Result plain = Shading::render(in);
        pixels += check_against_reference(in, plain);
        ++meshes;
        // The state machine run to the end gives the plain function's result exactly.
        if (seed % 10 == 0) {
            const Shading::Result machine = cg::run_to_end<Shading>(Shading::start(in));
            REQUIRE(machine == plain);
        }
    }
    CHECK(meshes == 3000);
    CHECK(pixels > 200'000);
    WARN("random meshes: " << meshes << " meshes, " << pixels << " pixels checked");
}

TEST_CASE("shading: a single triangle covers exactly scan-triangle's pixels", "[shading][random]") {
    for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
        cg::Rng rng(seed);
        Shading::Input in;
        in.width = rng.integer(3, 16);
        in.height = rng.integer(3, 16);
        in.model = static_cast<Model>(rng.integer(0, 2));
        in.lighting = simple_lighting(0.2, 0.7);
        cg::ScanTriangle::Input st{in.width, in.height, {}, {}};
        for (int c = 0; c < 3; ++c) {
            // Whole and half coordinates: centres on edges and vertices, collinear now and then.
            const dvec2 p{std::round(rng.uniform(-2, double(in.width) + 2) * 2) / 2,
                          std::round(rng.uniform(-2, double(in.height) + 2) * 2) / 2};
            st.triangle.push_back(p);
            in.mesh.vertices.push_back({p.x, p.y, rng.uniform(0, 5)});
        }
        in.mesh.triangles = {{0, 1, 2}};
        CAPTURE(seed);
        const Shading::Result r = Shading::render(in);
        std::set<std::pair<int, int>> mine, theirs;
        for (int j = 0; j < r.height; ++j)
            for (int i = 0; i < r.width; ++i)
                if (at(r, i, j).triangle == 0) mine.insert({i, j});
        for (const glm::ivec2 p : cg::ScanTriangle::scan(st).pixels) theirs.insert({p.x, p.y});
        REQUIRE(mine == theirs);
    }
}

// ---- [errors] -------------------------------------------------------------------------------

namespace {

cg::json base() {
    return cg::test::algorithm("shading").example();
}

std::string error_with(const std::function<void(cg::json&)>& edit) {
    cg::json j = base();
    edit(j);
    return cg::test::error_of("shading", j.dump());
}

}  // namespace

TEST_CASE("shading: bad input is refused with the field named", "[shading]") {
    CHECK(error_with([](cg::json& j) { j["mesh"]["triangles"][1][2] = 9; }) ==
          "mesh.triangles[1][2]: must be a vertex index from 0 to 8 (got 9)");
    CHECK(error_with([](cg::json& j) { j["mesh"]["triangles"][0][0] = -1; }) ==
          "mesh.triangles[0][0]: must be a vertex index from 0 to 8 (got -1)");
    CHECK(error_with([](cg::json& j) { j["mesh"]["triangles"][0][1] = 1.5; }) ==
          "mesh.triangles[0][1]: must be a vertex index (an integer), got 1.5");
    CHECK(error_with([](cg::json& j) {
              j["mesh"]["triangles"][2] = {1, 2};
          }) ==
          "mesh.triangles[2]: must be a triangle [i, j, k] of 3 vertex indices, got an array "
          "([1,2])");
    CHECK(error_with([](cg::json& j) {
              j["mesh"]["normals"] = {{0, 0, -1}};
          }) == "mesh.normals: must give one normal per vertex, 9 in all (got 1)");
    CHECK(error_with([](cg::json& j) {
              j["mesh"]["normals"] = cg::json::array();
              for (int v = 0; v < 9; ++v) j["mesh"]["normals"].push_back({0, 0, v == 4 ? 0 : -1});
          }) == "mesh.normals[4]: must not be the zero vector: a vertex needs a direction");
    CHECK(error_with([](cg::json& j) { j["mesh"]["vertices"][3][2] = 2e9; }) ==
          "mesh.vertices[3][2]: must lie within ±1e9 (got 2000000000)");
    CHECK(error_with([](cg::json& j) { j["model"] = "toon"; }) ==
          "model: must be \"flat\", \"gouraud\" or \"phong\" (got \"toon\")");
    CHECK(error_with([](cg::json& j) { j["lighting"]["model"] = "gouraud"; }) ==
          "lighting.model: must be \"phong\" or \"blinn-phong\" (got \"gouraud\")");
    CHECK(error_with([](cg::json& j) { j["lighting"]["material"]["kd"] = -0.5; }) ==
          "lighting.material.kd: must not be negative: a reflection coefficient (got −0.5)");
    CHECK(error_with([](cg::json& j) { j["lighting"]["lights"] = "sun"; }) ==
          "lighting.lights: must be a list of lights, got a string (\"sun\")");
    CHECK(error_with([](cg::json& j) { j["lighting"]["lights"][0]["intensity"] = 1e300; }) ==
          "lighting.lights[0].intensity: is too large (got 10³⁰⁰)");
    CHECK(error_with([](cg::json& j) {
              j["lighting"]["eye"] = {0, 0, 1e200};
          }) == "lighting.eye[2]: must lie within ±1e100 (got 10²⁰⁰)");
    CHECK_THAT(error_with([](cg::json& j) {
                   j["lighting"]["point"] = {0, 0, 0};
               }),
               Catch::StartsWith("lighting.point: is not a known field"));
    CHECK_THAT(error_with([](cg::json& j) {
                   j["lighting"]["lights"][0] = {
                       {"position", {8, 6, 4}}, {"intensity", 1}, {"attenuation", {0, 0, 1}}};
               }),
               Catch::StartsWith("lighting.lights[0].attenuation: makes the light too bright "
                                 "near the mesh"));
    CHECK(error_with([](cg::json& j) {
              j["pixel"] = {16, 0};
          }) == "pixel[0]: must be a column of the image, 0 to 15 (got 16)");
    CHECK(error_with([](cg::json& j) {
              j["pixel"] = {0, -1};
          }) == "pixel[1]: must be a row of the image, 0 to 11 (got -1)");
    CHECK(error_with([](cg::json& j) { j["width"] = 5000; }) ==
          "width: must be a whole number of pixels from 1 to 4096 (got 5000)");
    CHECK(error_with([](cg::json& j) { j["width"] = 4096, j["height"] = 4096; }) ==
          "width: the image would have 16777216 pixels, more than the limit of 1048576 (4096 × "
          "4096)");
    CHECK_THAT(error_with([](cg::json& j) {
                   // 17 triangles over the whole of a 1024² image: 17 × 1024 × 1025 > 2^24.
                   j["width"] = 1024, j["height"] = 1024;
                   j["mesh"]["vertices"][0] = {0, 0, 8}, j["mesh"]["vertices"][2] = {1024, 0, 8};
                   j["mesh"]["vertices"][8] = {1024, 1024, 8};
                   j["mesh"]["triangles"] = cg::json::array();
                   for (int k = 0; k < 17; ++k) j["mesh"]["triangles"].push_back({0, 2, 8});
               }),
               Catch::StartsWith("mesh.triangles: the triangles' bounding boxes hold"));
    CHECK_THAT(error_with([](cg::json& j) { j["mesh"]["colour"] = 1; }),
               Catch::StartsWith("mesh.colour: is not a known field"));
    // An empty mesh is no error: nothing is drawn.
    cg::json empty = base();
    empty["mesh"]["vertices"] = cg::json::array();
    empty["mesh"]["triangles"] = cg::json::array();
    const cg::json r = cg::test::result_of("shading", empty);
    CHECK(r["evaluations"] == 0);
    CHECK(r["pixel_color"].is_null());
    CHECK(r["image"][0][0].is_null());
}

TEST_CASE("shading: the JSON result has the documented fields", "[shading]") {
    cg::json in = base();
    for (const char* model : {"flat", "gouraud", "phong"}) {
        CAPTURE(model);
        in["model"] = model;
        const cg::json r = cg::test::result_of("shading", in);
        CHECK(r["image"].size() == 12);
        CHECK(r["image"][0].size() == 16);
        CHECK(r["ids"].size() == 12);
        CHECK(r["depth"].size() == 12);
        CHECK(r["pixel"] == cg::json::array({7, 6}));
        CHECK(r["pixel_color"].is_number());  // every colour of the lighting was a number
        CHECK(r.contains("normals") == (std::string(model) != "flat"));
        CHECK(r.contains("vertex_colors") == (std::string(model) == "gouraud"));
    }
    // The input survives the round trip through its JSON adapter.
    const cg::Algorithm& a = cg::test::algorithm("shading");
    const auto typed = cg::test::input_of<Shading>("shading", base());
    CHECK(a.exam_input != nullptr);
    CHECK(typed.mesh.triangles.size() == 8);
}

// ---- [determinism] --------------------------------------------------------------------------

TEST_CASE("shading: traces are deterministic, resumable, and copies share the image", "[shading]") {
    const cg::Algorithm& a = cg::test::algorithm("shading");
    cg::json in = base();
    for (const char* model : {"flat", "gouraud", "phong"}) {
        in["model"] = model;
        cg::test::check_replay(a, in, cg::test::kEveryStep);
    }
    // Every preset of the lesson: the same trace twice, the timeline back and forth, a copy
    // taken at step 7 finishing as the timeline does.
    std::ifstream file(CG_SOURCE_DIR "/lessons/215-shading.json");
    const cg::json lesson = cg::json::parse(file);
    for (const auto& preset : lesson.at("presets")) {
        CAPTURE(preset.at("name").get<std::string>());
        cg::test::check_replay(a, preset.at("input"), 7);
    }
    // A copy taken mid-run is a snapshot: stepping the original does not change it.
    Shading::State s = Shading::start(right_triangle(Model::Phong));
    for (int k = 0; k < 6; ++k) Shading::step(s, nullptr);
    const Shading::State copy = s;
    const Shading::Result before = Shading::result(copy);
    while (!Shading::done(s)) Shading::step(s, nullptr);
    CHECK(Shading::result(copy) == before);
    CHECK_FALSE(Shading::result(s) == before);
    // What a copy holds beyond the shared rows: the row pointers and one row.
    CHECK(Shading::bytes(s) < 10 * sizeof(void*) * 2 + 12 * sizeof(Shading::Sample) + 64);
}

// ---- [picture] ------------------------------------------------------------------------------

TEST_CASE("shading: the picture shows the run beside the other two models and the profile",
          "[shading]") {
    const cg::Algorithm& a = cg::test::algorithm("shading");
    auto run = a.create(base());
    for (int k = 0; k < 4; ++k) run->step(nullptr);  // normals, then into the first triangle
    cg::Scene scene;
    run->draw(scene);
    REQUIRE(scene.grids.size() == 3);  // this run, and the two others finished
    // In the world: the run top left, the others top right and bottom left (gap 3).
    CHECK(scene.grids[1].origin == dvec2(19, 0));
    CHECK(scene.grids[2].origin == dvec2(0, -15));
    std::set<std::string> titles;
    for (const auto& l : scene.labels) titles.insert(l.text);
    CHECK(titles.count("Phong shading (this run)") == 1);
    CHECK(titles.count("flat shading (finished)") == 1);
    CHECK(titles.count("Gouraud shading (finished)") == 1);
    // The profile: a chart of its own, the image's columns against intensity 0 … 1.
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& chart = scene.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.title == "intensity along row 6");
    CHECK(chart.x.hi == 16);
    CHECK(chart.y.lo == 0);
    CHECK(chart.y.hi == 1);
    // The other two are complete: every pixel the mesh covers is coloured.
    long long filled = 0;
    for (std::uint32_t c : scene.grids[1].rgba) filled += c != Shading::kBackground;
    CHECK(filled == 14 * 10);  // the mesh covers x 1 … 15, y 1 … 11: 14 × 10 centres
    // Profile polylines, one thick one for this run.
    int profile_lines = 0, thick = 0;
    for (const auto& p : chart.polygons) {
        ++profile_lines;
        thick += p.style.width > 2.5f;
    }
    CHECK(profile_lines == 2);  // the finished flat and Gouraud rows; this run's row is empty
    CHECK(thick == 0);
    CHECK(chart.legend.size() == 2);
    CHECK(scene.handles.size() == 9);  // one per vertex
    CHECK(scene.handles[4].x_field == "/mesh/vertices/4/0");
    // Finished: this run's profile is there too, and the run's image is complete.
    while (!run->done()) run->step(nullptr);
    cg::Scene end;
    run->draw(end);
    long long mine = 0;
    for (std::uint32_t c : end.grids[0].rgba) mine += c != Shading::kBackground;
    CHECK(mine == filled);
    REQUIRE(end.panels.size() == 1);
    int thick_end = 0;
    for (const auto& p : end.panels[0].polygons) thick_end += p.style.width > 2.5f;
    CHECK(thick_end == 1);
    REQUIRE(end.panels[0].legend.size() == 3);
    CHECK(end.panels[0].legend[0].text == "Phong (this run)");  // this run first
}

// Found by fuzz_algorithm_input (tests/fuzz/regressions/fuzz_algorithm_input/
// shading-normal-1e300-length): a given normal of length 1e300 was normalised right, but the
// narration divided by |n| computed as √(x² + y² + z²), which overflowed to "inf".
TEST_CASE("shading: a huge given normal narrates its true length, not inf", "[shading]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::json input = cg::json::parse(R"({"width":12,"height":10,
        "mesh":{"vertices":[[2,1,5],[10,1,7],[2,9,9]],
                "normals":[[0,0,-1],[0.6,0,-0.8],[-1e+300,0.6,-0.8]],"triangles":[[0,1,2]]},
        "model":"phong","lighting":{"model":"phong","eye":[6,5,-19],"ambient":1,
        "material":{"ka":0.1,"kd":1.0,"ks":0,"shininess":1},
        "lights":[{"direction":[0,0,1],"intensity":1}]},"pixel":[4,3]})");
    auto run = registry.find("shading")->create(input);
    cg::StepInfo info;
    run->step(&info);
    CHECK(info.event == "normals-given");
    CHECK_THAT(info.narration, Catch::Contains("n_2 = (−10³⁰⁰, 0.6, −0.8)/10³⁰⁰ = (−1, 0, 0)"));
    CHECK(info.narration.find("inf") == std::string::npos);
}
