// Back-face culling against an independent test: a face is a back face iff the eye and the
// solid's interior lie on the same side of the face's plane (long double, the plane through
// three of its corners, oriented by the interior point rather than by the vertex order). Cube,
// tetrahedron and octahedron from many eyes, random rotations and scales, parallel views, the
// edge-on case, the step machine against the plain function, and refused input.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "hsr/backface_cull.hpp"
#include "io/exam.hpp"
#include "io/registry.hpp"

using cg::BackfaceCull;

namespace {

using Mesh = BackfaceCull::Input;

cg::json P(const char* text) {
    return cg::json::parse(text);
}

Mesh cube() {
    Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    return m;
}
Mesh tetrahedron() {
    Mesh m;
    m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}
Mesh octahedron() {
    Mesh m;
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
               {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

using L3 = std::array<long double, 3>;
L3 ld(glm::dvec3 p) {
    return {p.x, p.y, p.z};
}
L3 sub(L3 a, L3 b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
L3 cross(L3 a, L3 b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
long double dot(L3 a, L3 b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Independent reference: the plane through the face's first three corners (valid for the
// convex test meshes), oriented so that the solid's centroid is on its negative side; the face
// is a back face iff the eye is strictly on that negative (inner) side. A parallel view is an
// eye infinitely far back along −view_dir: the sign of n·(−view_dir).
std::vector<bool> reference(const Mesh& m) {
    L3 c{0, 0, 0};
    for (auto v : m.vertices)
        for (int i = 0; i < 3; ++i) c[i] += ld(v)[i] / m.vertices.size();
    std::vector<bool> out;
    for (const auto& f : m.faces) {
        const L3 p0 = ld(m.vertices[f[0]]);
        L3 n = cross(sub(ld(m.vertices[f[1]]), p0), sub(ld(m.vertices[f[2]]), p0));
        if (dot(n, sub(c, p0)) > 0) n = {-n[0], -n[1], -n[2]};  // interior on the negative side
        const long double side =
            m.perspective ? dot(n, sub(ld(m.eye), p0)) : -dot(n, ld(m.view_dir));
        out.push_back(side < 0);
    }
    return out;
}

glm::dmat3 random_rotation(cg::Rng& rng) {
    // A random unit quaternion (rejection from the 4-ball).
    double q[4], len2;
    do {
        for (double& x : q) x = rng.uniform(-1, 1);
        len2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    } while (len2 > 1 || len2 < 1e-3);
    const double s = 1 / std::sqrt(len2), w = q[0] * s, x = q[1] * s, y = q[2] * s, z = q[3] * s;
    return glm::dmat3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),  //
                      2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x),  //
                      2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
}

std::vector<bool> culled(const Mesh& m) {
    return cg::run_to_end<BackfaceCull>(BackfaceCull::start(m)).culled;
}

int count(const std::vector<bool>& v) {
    int n = 0;
    for (bool b : v) n += b;
    return n;
}

}  // namespace

TEST_CASE("backface-cull: cube from hand-picked eyes", "[hsr][backface]") {
    Mesh m = cube();
    m.eye = {0.5, 0.5, 5};  // straight in front: only the front face (z = 1) kept
    CHECK(culled(m) == std::vector<bool>{true, false, true, true, true, true});
    m.eye = {3, 2.5, 4};  // front, top and right kept
    CHECK(culled(m) == std::vector<bool>{true, false, true, false, true, false});
    m.eye = {0.5, 0.5, 0.5};  // inside: every face's outside looks away
    CHECK(count(culled(m)) == 6);
    m.perspective = false;
    m.view_dir = {0, 0, -1};  // looking down −z: z = 0 culled, z = 1 seen, the sides edge-on (kept)
    CHECK(culled(m) == std::vector<bool>{true, false, false, false, false, false});
    m.view_dir = {-1, -1, -1};
    CHECK(culled(m) == std::vector<bool>{true, false, true, false, true, false});
}

TEST_CASE("backface-cull: an eye in a face's plane is edge-on and kept", "[hsr][backface]") {
    Mesh m = cube();
    m.eye = {0.5, 0, 4};  // in the plane y = 0 of face 2
    const auto r = cg::run_to_end<BackfaceCull>(BackfaceCull::start(m));
    CHECK(r.dots[2] == 0);
    CHECK_FALSE(r.culled[2]);
    BackfaceCull::State s = BackfaceCull::start(m);
    cg::StepInfo info;
    for (int k = 0; k < 3; ++k) BackfaceCull::step(s, &info);
    CHECK(info.event == "edge-on");
    m.perspective = false;
    m.view_dir = {1, 0, 0};  // parallel to the faces y = 0, y = 1, z = 0, z = 1
    const auto p = culled(m);
    CHECK(p == std::vector<bool>{false, false, false, false, false, true});
}

TEST_CASE("backface-cull: agrees with the plane-side reference on many eyes and meshes",
          "[hsr][backface]") {
    const Mesh bases[] = {cube(), tetrahedron(), octahedron()};
    for (std::uint64_t trial = 1; trial <= 3000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(trial);
        Mesh m = bases[trial % 3];
        const glm::dmat3 R = random_rotation(rng);
        const glm::dvec3 scale{rng.uniform(0.2, 5), rng.uniform(0.2, 5), rng.uniform(0.2, 5)};
        const glm::dvec3 shift{rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
        for (auto& v : m.vertices) v = R * (v * scale) + shift;
        m.perspective = rng.chance(0.7);
        if (m.perspective)
            m.eye = {rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)};
        else
            m.view_dir = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        const auto r = cg::run_to_end<BackfaceCull>(BackfaceCull::start(m));
        REQUIRE(r.culled == reference(m));
        REQUIRE(BackfaceCull::cull(m) == r);
        for (std::size_t k = 0; k < r.normals.size(); ++k)
            REQUIRE(glm::length(r.normals[k]) == Approx(1));
        // From far outside a convex closed mesh, not everything is culled and not everything kept.
        if (!m.perspective) {
            REQUIRE(count(r.culled) > 0);
            REQUIRE(count(r.culled) < static_cast<int>(r.culled.size()));
        }
    }
}

TEST_CASE("backface-cull: a copy taken mid-run finishes identically, and the same input gives the same trace",
          "[hsr][backface]") {
    Mesh m = octahedron();
    m.eye = {2, 3, 4};
    BackfaceCull::State s = BackfaceCull::start(m);
    for (int i = 0; i < 3; ++i) BackfaceCull::step(s, nullptr);
    BackfaceCull::State copy = s;
    while (!BackfaceCull::done(s)) BackfaceCull::step(s, nullptr);
    while (!BackfaceCull::done(copy)) BackfaceCull::step(copy, nullptr);
    CHECK(copy == s);
    CHECK(BackfaceCull::result(s) == BackfaceCull::cull(m));
    // Face s·X = 1 (s = (±1, ±1, ±1)) is culled iff s·E < 1: four of eight; (1, 1, −1)·E = 1 is
    // edge-on.
    CHECK(count(BackfaceCull::result(s).culled) == 4);
    CHECK(BackfaceCull::result(s).dots[4] == 0);
}

TEST_CASE("backface-cull: bad input is refused, naming the field", "[hsr][backface][errors]") {
    static const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("backface-cull");
    REQUIRE(a);
    auto error_of = [&](const cg::json& j) -> std::string {
        try {
            a->create(j);
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "";
    };
    cg::json base = a->example();
    auto with = [&](const char* key, cg::json v) {
        cg::json j = base;
        j[key] = std::move(v);
        return j;
    };
    CHECK_THAT(error_of(with("faces", P("[[0, 1, 8]]"))),
               Catch::Contains("faces[0][2]") && Catch::Contains("out of range"));
    CHECK_THAT(error_of(with("faces", P("[[0, 1]]"))),
               Catch::Contains("faces[0]") && Catch::Contains("at least 3"));
    CHECK_THAT(error_of(with("faces", P("[[0, 1, 0]]"))),
               Catch::Contains("faces[0][2]") && Catch::Contains("repeated"));
    CHECK_THAT(error_of(with("faces", P("[[0, 1, 4, 5]]"))),
               Catch::Contains("faces[0]") && Catch::Contains("degenerate"));
    CHECK_THAT(error_of(with("faces", P("[[0, 1, 2, 7]]"))),
               Catch::Contains("faces[0]") && Catch::Contains("not planar"));
    CHECK_THAT(error_of(with("faces", P("[[0, 1, 1.5]]"))),
               Catch::Contains("faces[0][2]") && Catch::Contains("integer"));
    CHECK_THAT(error_of(with("eye", P("[1, \"x\", 2]"))), Catch::Contains("eye"));
    cg::json both = with("view_dir", P("[0, 0, -1]"));
    CHECK_THAT(error_of(both), Catch::Contains("not both"));
    cg::json neither = base;
    neither.erase("eye");
    CHECK_THAT(error_of(neither), Catch::Contains("eye") && Catch::Contains("view_dir"));
    cg::json zero = neither;
    zero["view_dir"] = P("[0, 0, 0]");
    CHECK_THAT(error_of(zero), Catch::Contains("view_dir") && Catch::Contains("zero"));
    CHECK_THAT(error_of(with("vertices", cg::json::array())), Catch::Contains("vertices"));
}

TEST_CASE("backface-cull: exam answers match the plane-side reference", "[hsr][backface][exam]") {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const Mesh m = BackfaceCull::exam_input(rng);
        REQUIRE(culled(m) == reference(m));
    }
}
