// Vertex normals: hand-checked meshes (a cube of quads and of triangles, a square pyramid, the
// long thin face where the three weightings part); thousands of seeded random meshes —
// triangles and non-planar, concave polygons with integer coordinates, zero-area faces,
// repeated indices, isolated vertices, faces wound both ways — against an independent
// long-double computation (Newell's classic Σ P_i × P_(i+1), angles by acos); the degenerate
// cases and bad input; shading's link (its vertex normals are this algorithm's area weighting);
// replay, exam problems, the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "affine/vertex_normals.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "shading/shading.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"

using cg::VertexNormals;
using glm::dvec3;
using Input = VertexNormals::Input;
using W = VertexNormals::Weighting;

namespace {

constexpr long double kPiL = 3.141592653589793238462643383279502884L;

Input mesh(std::vector<dvec3> vertices, std::vector<std::vector<long long>> faces) {
    Input in;
    in.vertices = std::move(vertices);
    in.faces = std::move(faces);
    return in;
}

void check_near(const std::optional<dvec3>& got, dvec3 want, double tol = 1e-12) {
    REQUIRE(got.has_value());
    CAPTURE(got->x, got->y, got->z, want.x, want.y, want.z);
    CHECK(glm::length(*got - want) <= tol);
}

dvec3 unit(dvec3 v) {
    return v / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

// ---- the reference: long double, written apart from the algorithm ----

struct L3 {
    long double x = 0, y = 0, z = 0;
};
L3 operator+(L3 a, L3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
L3 operator-(L3 a, L3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
L3 operator*(long double s, L3 a) {
    return {s * a.x, s * a.y, s * a.z};
}
long double dot(L3 a, L3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
L3 cross(L3 a, L3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
long double len(L3 a) {
    return std::sqrt(dot(a, a));
}
L3 L(dvec3 p) {
    return {p.x, p.y, p.z};
}

struct RefFace {
    std::vector<long long> c;
    L3 N;
    bool defined = false;
    std::vector<long double> angle;
    bool ill = false;  // a corner's reflex test is ill-conditioned
};
struct RefVertex {
    int faces = 0;
    L3 sum[3];
    long double scale[3] = {0, 0, 0};
};

// Newell's classic form, N_x = Σ (y_i − y_j)(z_i + z_j) and its shifts, over the cleaned
// corners; the angle by acos, reflex where the corner turns against N.
RefFace ref_face(const std::vector<dvec3>& P, const std::vector<long long>& raw) {
    RefFace f;
    for (long long v : raw)
        if (f.c.empty() || f.c.back() != v) f.c.push_back(v);
    while (f.c.size() > 1 && f.c.back() == f.c.front()) f.c.pop_back();
    const std::size_t n = f.c.size();
    f.angle.assign(n, 0);
    if (n < 3) return f;
    for (std::size_t i = 0; i < n; ++i) {
        const L3 a = L(P[f.c[i]]), b = L(P[f.c[(i + 1) % n]]);
        f.N.x += (a.y - b.y) * (a.z + b.z);
        f.N.y += (a.z - b.z) * (a.x + b.x);
        f.N.z += (a.x - b.x) * (a.y + b.y);
    }
    f.defined = len(f.N) > 0;
    for (std::size_t i = 0; i < n; ++i) {
        const L3 p = L(P[f.c[i]]);
        const L3 a = L(P[f.c[(i + 1) % n]]) - p, b = L(P[f.c[(i + n - 1) % n]]) - p;
        const long double la = len(a), lb = len(b);
        if (la == 0 || lb == 0) continue;
        long double c = dot(a, b) / (la * lb);
        c = std::max(-1.0L, std::min(1.0L, c));
        long double t = std::acos(c);
        if (n > 3 && f.defined) {
            const long double s = dot(f.N, cross(a, b)) / len(f.N);
            if (std::fabs(s) < 1e-9L * la * lb) f.ill = true;
            if (s < 0) t = 2 * kPiL - t;
        }
        f.angle[i] = t;
    }
    return f;
}

struct Ref {
    std::vector<RefFace> faces;
    std::vector<RefVertex> vertices;
};

Ref reference(const Input& in) {
    Ref r;
    for (const auto& f : in.faces) r.faces.push_back(ref_face(in.vertices, f));
    r.vertices.resize(in.vertices.size());
    for (const RefFace& f : r.faces) {
        if (!f.defined) continue;
        const L3 n = (1 / len(f.N)) * f.N;
        const long double area = len(f.N) / 2;
        for (std::size_t i = 0; i < f.c.size(); ++i) {
            RefVertex& v = r.vertices[f.c[i]];
            ++v.faces;
            const long double w[3] = {1, area, f.angle[i]};
            for (int k = 0; k < 3; ++k) {
                v.sum[k] = v.sum[k] + w[k] * n;
                v.scale[k] += w[k];
            }
        }
    }
    return r;
}

// A random mesh: integer coordinates (so cross products and Newell sums are exact), triangles
// and polygons of 4 to 6 corners (non-planar, often concave), some collinear or coincident,
// some with an index repeated in a row, some wound backwards, and vertices no face uses.
Input random_mesh(cg::Rng& rng) {
    Input in;
    const int nv = int(rng.integer(3, 12));
    for (int v = 0; v < nv; ++v)
        in.vertices.push_back(
            {double(rng.integer(-5, 5)), double(rng.integer(-5, 5)), double(rng.integer(-5, 5))});
    if (rng.chance(0.3)) {  // three collinear vertices, a sure zero-area triangle
        const dvec3 a = in.vertices[0], d{double(rng.integer(-2, 2)), double(rng.integer(-2, 2)),
                                          double(rng.integer(-2, 2))};
        in.vertices[1] = a + d;
        in.vertices[2] = a + 2.0 * d;
        in.faces.push_back({0, 1, 2});
    }
    const int nf = int(rng.integer(1, 10));
    for (int k = 0; k < nf; ++k) {
        const int n = rng.chance(0.6) ? 3 : int(rng.integer(4, 6));
        std::vector<long long> pool;
        for (int v = 0; v < nv; ++v) pool.push_back(v);
        std::vector<long long> face;
        for (int i = 0; i < n && !pool.empty(); ++i) {
            const auto j = static_cast<std::size_t>(rng.integer(0, (long long)pool.size() - 1));
            face.push_back(pool[j]);
            pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(j));
        }
        if (face.size() < 3) continue;
        if (rng.chance(0.1)) face.insert(face.begin() + 1, face[1]);  // a repeat in a row
        if (rng.chance(0.05)) face.push_back(face[0]);                // ... cyclically
        in.faces.push_back(face);
        if (rng.chance(0.1))  // the same face wound the other way
            in.faces.push_back(std::vector<long long>(face.rbegin(), face.rend()));
    }
    return in;
}

cg::test::JsonTraced run(const std::string& text) {
    return cg::test::run_json("vertex-normals", text);
}
cg::json res(const std::string& text) {
    return cg::test::result_of("vertex-normals", text);
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("vertex-normals");
    if (!l) throw std::runtime_error("no lesson for vertex-normals");
    return *l;
}

Input cube_quads() {
    std::vector<dvec3> v;
    for (int i = 0; i < 8; ++i)
        v.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
    // Counter-clockwise seen from outside.
    return mesh(
        v, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

}  // namespace

TEST_CASE("vertex-normals: a cube of quads gives (±1, ±1, ±1)/√3 under every weighting",
          "[affine][vertex-normals]") {
    const Input in = cube_quads();
    const auto r = VertexNormals::compute(in);
    for (const auto& f : r.faces) {
        CHECK(f.newell);
        CHECK(f.area == 4.0);
        for (double t : f.angles) CHECK(t == Approx(M_PI / 2).epsilon(1e-14));
        // Outward: along the face's centroid.
        dvec3 c(0.0);
        for (long long v : f.corners) c += in.vertices[v];
        CHECK(glm::dot(f.normal, c) == Approx(4.0));
    }
    for (std::size_t v = 0; v < 8; ++v) {
        CAPTURE(v);
        for (int w = 0; w < 3; ++w)
            check_near(r.vertices[v].normal[w], unit(in.vertices[v]), 1e-15);
        CHECK(r.vertices[v].faces.size() == 3);
    }
}

TEST_CASE("vertex-normals: a triangulated cube — only the angle weighting stays symmetric",
          "[affine][vertex-normals]") {
    const Input q = cube_quads();
    Input in = q;
    in.faces.clear();
    for (const auto& f : q.faces) {  // split each quad along its first diagonal
        in.faces.push_back({f[0], f[1], f[2]});
        in.faces.push_back({f[0], f[2], f[3]});
    }
    const auto r = VertexNormals::compute(in);
    int asymmetric = 0;
    for (std::size_t v = 0; v < 8; ++v) {
        CAPTURE(v);
        // The angles of one square's triangles at a corner add up to 90°, whatever the split.
        check_near(r.vertices[v].normal[2], unit(in.vertices[v]), 1e-15);
        const dvec3 d = unit(in.vertices[v]);
        if (glm::length(*r.vertices[v].normal[0] - d) > 1e-3) ++asymmetric;
        // Area weighting sees two half-squares of one square and one of another.
        if (glm::length(*r.vertices[v].normal[1] - d) > 1e-3) ++asymmetric;
    }
    CHECK(asymmetric >= 4);
    // V0 is in both triangles of each of its three squares (each split from V0): diagonal
    // again. Any corner: the unweighted sum counts each axis once per triangle there.
    check_near(r.vertices[0].normal[0], unit(dvec3(-1, -1, -1)), 1e-15);
    int count[3] = {0, 0, 0};  // triangles at V1 whose normal is ±z, ±y, ±x
    for (const auto& f : r.faces)
        if (std::find(f.corners.begin(), f.corners.end(), 1) != f.corners.end())
            for (int d = 0; d < 3; ++d) count[d] += std::fabs(f.normal[d]) == 1.0;
    const dvec3 want = unit(dvec3(count[0], -count[1], -count[2]));
    check_near(r.vertices[1].normal[0], want, 1e-15);
}

TEST_CASE("vertex-normals: a square pyramid, worked by hand", "[affine][vertex-normals]") {
    // Base (±1, ±1, 0) facing down, apex (0, 0, 1).
    const Input in = mesh({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}},
                          {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2, 1}});
    const auto r = VertexNormals::compute(in);
    // Side y = −1: (P1 − P0) × (P2 − P0) = (2, 0, 0) × (1, 1, 1) = (0, −2, 2); area √2.
    CHECK(r.faces[0].N == dvec3(0, -2, 2));
    CHECK(r.faces[0].area == Approx(std::sqrt(2.0)));
    CHECK(r.faces[4].N == dvec3(0, 0, -8));
    CHECK(r.faces[4].area == 4.0);
    // The apex: four equal sides, symmetric.
    for (int w = 0; w < 3; ++w) check_near(r.vertices[4].normal[w], dvec3(0, 0, 1), 1e-15);
    // V2 = (1, 1, 0): sides (1, 0, 1)/√2 and (0, 1, 1)/√2 (area √2, angle acos(1/√3) each),
    // the base (0, 0, −1) (area 4, angle 90°).
    const double s = 1 / std::sqrt(2.0);
    check_near(r.vertices[2].normal[0], unit(dvec3(s, s, 2 * s - 1)));
    check_near(r.vertices[2].normal[1], unit(dvec3(1, 1, -2)));  // √2·n1 + √2·n2 + 4·n_base
    const double theta = std::acos(1 / std::sqrt(3.0));
    check_near(r.vertices[2].normal[2],
               unit(dvec3(theta * s, theta * s, 2 * theta * s - M_PI / 2)));
    CHECK(r.faces[1].angles[1] == Approx(theta));
}

TEST_CASE("vertex-normals: the long thin face parts the three weightings",
          "[affine][vertex-normals]") {
    // The example: F0 = (V0, V1, V2) in z = 0, area 2, 90° at V0; F1 = (V0, V2, V3) the sliver
    // in x = 0, N = (0, 2, 0) × (0, −8, 0.5) = (1, 0, 0), area ½, angle π − atan(1/16) at V0.
    const auto r =
        cg::test::result_of("vertex-normals", cg::test::algorithm("vertex-normals").example());
    const auto& vn = r["vertex_normals"];
    auto at = [](const cg::json& j) { return dvec3(j[0], j[1], j[2]); };
    const double big = M_PI - std::atan(1.0 / 16);
    CHECK(glm::length(at(vn["unweighted"][0]) - unit(dvec3(1, 0, 1))) < 1e-15);
    CHECK(glm::length(at(vn["area"][0]) - unit(dvec3(1, 0, 4))) < 1e-15);  // 2(0,0,1)·2 + (1,0,0)
    CHECK(glm::length(at(vn["angle"][0]) - unit(dvec3(big, 0, M_PI / 2))) < 1e-15);
    CHECK(r["face_areas"][1] == 0.5);
    CHECK(double(r["corner_angles_deg"][1][0]) == Approx(180 - std::atan(1.0 / 16) * 180 / M_PI));
    // The three directions are far apart: about 14°, 45° and 63° from +z.
    auto tilt = [&](const char* w) { return std::acos(double(vn[w][0][2])) * 180 / M_PI; };
    CHECK(tilt("area") == Approx(std::atan(0.25) * 180 / M_PI));
    CHECK(tilt("unweighted") == Approx(45.0));
    CHECK(tilt("angle") == Approx(std::atan(big / (M_PI / 2)) * 180 / M_PI));
    CHECK(tilt("angle") - tilt("unweighted") > 15);
    CHECK(tilt("unweighted") - tilt("area") > 25);
}

TEST_CASE("vertex-normals: 4,000 random meshes against a long-double reference",
          "[affine][vertex-normals]") {
    long long compared = 0, undefined_faces = 0, nulls = 0, polygons = 0;
    for (std::uint64_t seed = 0; seed < 4000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const Input in = random_mesh(rng);
        VertexNormals::Result r;
        try {
            r = VertexNormals::compute(in);
        } catch (const cg::InputError& e) {
            // Only a vertex listed twice apart in a polygon is refused here.
            CHECK_THAT(e.what(), Catch::Contains("apart from it"));
            continue;
        }
        const Ref ref = reference(in);
        REQUIRE(r.faces.size() == ref.faces.size());
        for (std::size_t k = 0; k < ref.faces.size(); ++k) {
            const auto& f = r.faces[k];
            const RefFace& g = ref.faces[k];
            CAPTURE(k);
            CHECK(f.corners == g.c);
            REQUIRE(f.defined == g.defined);
            polygons += f.newell;
            if (!g.defined) {
                ++undefined_faces;
                continue;
            }
            // Integer coordinates: N is exact in both.
            CHECK((long double)f.N.x == g.N.x);
            CHECK((long double)f.N.y == g.N.y);
            CHECK((long double)f.N.z == g.N.z);
            CHECK(f.area == Approx(double(len(g.N) / 2)).epsilon(1e-15));
            if (g.ill) continue;
            for (std::size_t i = 0; i < g.angle.size(); ++i)
                CHECK(std::fabs(f.angles[i] - double(g.angle[i])) < 1e-9);
        }
        for (std::size_t v = 0; v < in.vertices.size(); ++v) {
            CAPTURE(v);
            const RefVertex& g = ref.vertices[v];
            const auto& vs = r.vertices[v];
            CHECK(int(vs.faces.size()) == g.faces);
            for (int w = 0; w < 3; ++w) {
                CAPTURE(w);
                const long double l = len(g.sum[w]);
                if (g.faces == 0 || l == 0) {
                    CHECK_FALSE(vs.normal[w].has_value());
                    ++nulls;
                    continue;
                }
                if (l < 1e-6L * g.scale[w]) continue;  // a near-cancellation: ill-conditioned
                bool ill = false;
                for (int k : vs.faces) ill = ill || ref.faces[k].ill;
                if (w == 2 && ill) continue;
                REQUIRE(vs.normal[w].has_value());
                const dvec3 want(double(g.sum[w].x / l), double(g.sum[w].y / l),
                                 double(g.sum[w].z / l));
                CHECK(glm::length(*vs.normal[w] - want) < 1e-9);
                ++compared;
            }
        }
    }
    CHECK(compared > 40000);
    CHECK(undefined_faces > 500);
    CHECK(nulls > 500);
    CHECK(polygons > 5000);
}

TEST_CASE("vertex-normals: stepping equals compute, copies finish alike, traces repeat",
          "[affine][vertex-normals]") {
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed + 10'000);
        const Input in = random_mesh(rng);
        VertexNormals::State s;
        try {
            s = VertexNormals::start(in);
        } catch (const cg::InputError&) {
            continue;
        }
        const auto steps = in.faces.size() + in.vertices.size();
        std::size_t n = 0;
        VertexNormals::State copy;
        while (!VertexNormals::done(s)) {
            cg::StepInfo info;
            VertexNormals::step(s, &info);
            CHECK_FALSE(info.event.empty());
            if (++n == steps / 2) copy = s;
        }
        CHECK(n == steps);
        CHECK(VertexNormals::result(s) == VertexNormals::compute(in));
        CHECK(cg::run_to_end<VertexNormals>(copy) == VertexNormals::result(s));
    }
    const cg::Algorithm& a = cg::test::algorithm("vertex-normals");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    std::set<std::string> seen;
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
        for (const auto& step : cg::test::run_json("vertex-normals", p.input).steps)
            seen.insert(step.event);
    }
    for (const auto& e : VertexNormals::spec().events) {
        CAPTURE(e.id);
        CHECK(seen.count(e.id));
    }
}

TEST_CASE(
    "vertex-normals: degenerate meshes — zero area, isolated vertices, repeats, opposite "
    "windings",
    "[affine][vertex-normals]") {
    SECTION("a zero-area face has no normal and adds nothing") {
        const auto t =
            run(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0],[2,0,0]], "faces": [[0,1,2],[0,1,3]]})");
        CHECK(t.result["face_normals"][1].is_null());
        CHECK(t.result["face_areas"][1] == 0.0);
        CHECK(t.result["undefined_faces"] == cg::json::parse("[1]"));
        CHECK(t.steps[1].event == "face-degenerate");
        CHECK_THAT(t.steps[1].narration, Catch::Contains("undefined"));
        // V3 is only on the collinear face: no normal under any weighting, null not NaN.
        for (const char* w : {"unweighted", "area", "angle"}) {
            CHECK(t.result["vertex_normals"][w][3].is_null());
            CHECK(t.result["vertex_normals"][w][0] == cg::json::parse("[0.0, 0.0, 1.0]"));
        }
        CHECK(t.result["isolated_vertices"] == cg::json::parse("[3]"));
        CHECK(t.steps.back().event == "vertex-isolated");
    }
    SECTION("an isolated vertex is null") {
        const auto r =
            res(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0],[5,5,5]], "faces": [[0,1,2]]})");
        CHECK(r["vertex_normals"]["angle"][3].is_null());
        CHECK(r["vertex_normals"]["area"][2] == cg::json::parse("[0.0, 0.0, 1.0]"));
        const auto none = res(R"({"vertices": [[1,2,3]], "faces": []})");
        CHECK(none["vertex_normals"]["unweighted"][0].is_null());
    }
    SECTION("repeats in a row are dropped; a repeat apart is refused") {
        const auto r =
            run(R"({"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "faces": [[0,1,1,2,3,0]]})");
        CHECK(r.result["corner_angles_deg"][0].size() == 4);
        CHECK(r.result["face_normals"][0] == cg::json::parse("[0.0, 0.0, 1.0]"));
        CHECK_THAT(r.steps[0].narration, Catch::Contains("2 repeated indexes dropped"));
        const auto tri = res(R"({"vertices": [[0,0,0],[1,0,0],[1,1,0]], "faces": [[0,1,0]]})");
        CHECK(tri["face_normals"][0].is_null());
        CHECK_THAT(
            cg::test::error_of("vertex-normals",
                               R"({"vertices": [[0,0,0],[1,0,0],[1,1,0]], "faces": [[0,1,0,2]]})"),
            Catch::StartsWith("faces[0][2]: repeats vertex 0 of faces[0][0] apart from it"));
    }
    SECTION("opposite windings cancel") {
        const auto t =
            run(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2],[0,2,1]]})");
        CHECK(t.result["face_normals"][1] == cg::json::parse("[-0.0, -0.0, -1.0]"));
        for (const char* w : {"unweighted", "area", "angle"})
            CHECK(t.result["vertex_normals"][w][0].is_null());
        CHECK(t.steps[2].event == "vertex-cancelled");
        CHECK_THAT(t.steps[2].narration, Catch::Contains("cancels"));
    }
}

TEST_CASE("vertex-normals: bad input names the field", "[affine][vertex-normals]") {
    auto error = [](const std::string& text) { return cg::test::error_of("vertex-normals", text); };
    CHECK_THAT(error(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2],[0,1,7]]})"),
               Catch::StartsWith("faces[1][2]: vertex index 7 is out of range (the mesh has 3 "
                                 "vertices, 0 to 2)"));
    CHECK_THAT(error(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,-1,2]]})"),
               Catch::StartsWith("faces[0][1]: vertex index -1 is out of range"));
    CHECK_THAT(error(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1]]})"),
               Catch::StartsWith("faces[0]: a face needs at least 3 vertices (got 2)"));
    CHECK_THAT(error(R"({"vertices": [], "faces": []})"),
               Catch::StartsWith("vertices: must list at least one vertex"));
    CHECK_THAT(error(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1.5,2]]})"),
               Catch::StartsWith("faces[0][1]: must be a vertex index"));
    CHECK_THAT(error(R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [3]})"),
               Catch::StartsWith("faces[0]: must be a face"));
    CHECK_THAT(error(R"({"vertices": [[0,0,0],[1e101,0,0],[0,1,0]], "faces": [[0,1,2]]})"),
               Catch::StartsWith("vertices[1][0]: must be within ±1e100"));
    CHECK_THAT(
        error(
            R"({"vertices": [[0,0,0]], "faces": [], "focus": {"vertex": 1, "weighting": "area"}})"),
        Catch::StartsWith("focus.vertex: must be a vertex index"));
    CHECK_THAT(
        error(
            R"({"vertices": [[0,0,0]], "faces": [], "focus": {"vertex": 0, "weighting": "mean"}})"),
        Catch::StartsWith("focus.weighting: must be"));
    CHECK_THAT(error(R"({"vertices": [[0,0,0]], "faces": [], "normals": []})"),
               Catch::Contains("normals"));
    // NaN and infinity cannot be written in JSON; the typed input refuses them too.
    for (double bad : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
        Input in = mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, bad}}, {{0, 1, 2}});
        try {
            VertexNormals::start(in);
            FAIL("accepted a non-finite coordinate");
        } catch (const cg::InputError& e) {
            CHECK(e.field() == "vertices[2][2]");
            CHECK_THAT(e.reason(), Catch::StartsWith("must be a finite number"));
        }
    }
}

TEST_CASE("vertex-normals: huge and far-off coordinates stay finite and exact in direction",
          "[affine][vertex-normals]") {
    // The largest allowed coordinates: the cross products reach ~10²⁰⁰, still finite.
    const double b = 1e100;
    auto r = VertexNormals::compute(
        mesh({{-b, -b, 0}, {b, -b, 0}, {b, b, 0}, {-b, b, 0}}, {{0, 1, 2, 3}}));
    check_near(r.vertices[0].normal[1], dvec3(0, 0, 1), 0);
    CHECK(std::isfinite(r.faces[0].area));
    // A unit square far from the origin: P0 is moved to the origin first, so no digits are lost.
    const double o = 1e12;
    r = VertexNormals::compute(
        mesh({{o, o, o}, {o + 1, o, o}, {o + 1, o + 1, o}, {o, o + 1, o}}, {{0, 1, 2, 3}}));
    CHECK(r.faces[0].area == 1.0);
    check_near(r.vertices[2].normal[2], dvec3(0, 0, 1), 0);
}

TEST_CASE("vertex-normals: shading's vertex normals are this algorithm's area weighting",
          "[affine][vertex-normals][shading]") {
    // The shared function against the per-vertex sums, on random triangle meshes: bit for bit.
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed + 50'000);
        Input in;
        const int nv = int(rng.integer(3, 10));
        for (int v = 0; v < nv; ++v)
            in.vertices.push_back({rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)});
        std::vector<std::array<long long, 3>> tris;
        for (int k = int(rng.integer(1, 8)); k > 0; --k) {
            std::array<long long, 3> t{rng.integer(0, nv - 1), rng.integer(0, nv - 1),
                                       rng.integer(0, nv - 1)};
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
            tris.push_back(t);
            in.faces.push_back({t[0], t[1], t[2]});
        }
        const auto r = VertexNormals::compute(in);
        std::vector<dvec3> N;
        for (const auto& f : r.faces) N.push_back(f.N);
        const auto shared = VertexNormals::area_weighted(in.vertices.size(), tris, N);
        for (std::size_t v = 0; v < in.vertices.size(); ++v)
            if (r.vertices[v].normal[1]) CHECK(shared[v] == *r.vertices[v].normal[1]);
    }
    // Shading (Gouraud, no normals given) on a tent facing the viewer (z < 0 toward it): its
    // vertex normals are vertex-normals' area-weighted ones.
    const char* mesh_json =
        R"({"vertices": [[2, 2, 0], [14, 2, 0], [8, 14, -4], [2, 14, 0]],
            "faces": [[0, 2, 1], [0, 3, 2]]})";
    const auto vn = res(mesh_json);
    cg::json sh = cg::test::algorithm("shading").example();
    sh["mesh"] = cg::json::parse(
        R"({"vertices": [[2, 2, 0], [14, 2, 0], [8, 14, -4], [2, 14, 0]], "triangles": [[0, 2, 1], [0, 3, 2]]})");
    sh["model"] = "gouraud";
    sh.erase("pixel");
    cg::Shading::Input in = cg::test::input_of<cg::Shading>("shading", sh);
    const auto out = cg::Shading::render(in);
    for (std::size_t v = 0; v < 4; ++v) {
        CAPTURE(v);
        const auto& n = vn["vertex_normals"]["area"][v];
        CHECK(out.normals[v] == dvec3(n[0], n[1], n[2]));
    }
}

TEST_CASE("vertex-normals: exam problems — a pyramid, one vertex, one weighting",
          "[affine][vertex-normals]") {
    const cg::Algorithm& a = cg::test::algorithm("vertex-normals");
    std::set<std::string> asked;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        REQUIRE(p.answers.size() == 1);
        asked.insert(p.answers[0].substr(0, p.answers[0].rfind('/')));
        const Input in = cg::test::input_of<VertexNormals>("vertex-normals", p.input);
        const Ref ref = reference(in);
        const RefVertex& g = ref.vertices[in.focus_vertex];
        const int w = int(in.focus_weighting);
        const long double l = len(g.sum[w]);
        REQUIRE(l > 0);
        const cg::json& e = p.expected[p.answers[0]];
        CHECK(std::fabs(double(e[0]) - double(g.sum[w].x / l)) < 1e-12);
        CHECK(std::fabs(double(e[1]) - double(g.sum[w].y / l)) < 1e-12);
        CHECK(std::fabs(double(e[2]) - double(g.sum[w].z / l)) < 1e-12);
        CHECK_THAT(p.question, Catch::Contains("V" + std::to_string(in.focus_vertex)));
    }
    CHECK(asked.size() == 3);
}

TEST_CASE("vertex-normals: the picture — mesh, face normals, three vertex normals",
          "[affine][vertex-normals]") {
    const cg::Algorithm& a = cg::test::algorithm("vertex-normals");
    auto s = VertexNormals::start(cg::test::input_of<VertexNormals>("vertex-normals", a.example()));
    cg::Scene before;
    VertexNormals::draw(s, before);
    CHECK(before.has_3d());
    CHECK(before.faces3.size() == 2);
    CHECK(before.segments3.empty());
    VertexNormals::step(s, nullptr);
    cg::Scene first;
    VertexNormals::draw(s, first);
    CHECK(first.faces3[0].style.role == cg::Role::Active);
    REQUIRE(first.segments3.size() == 1);  // F0's normal
    CHECK(first.segments3[0].arrow);
    VertexNormals::step(s, nullptr);
    VertexNormals::step(s, nullptr);  // V0
    cg::Scene v0;
    VertexNormals::draw(s, v0);
    std::set<cg::Role> roles;
    for (const auto& seg : v0.segments3) roles.insert(seg.style.role);
    CHECK(roles.count(cg::Role::Entering));
    CHECK(roles.count(cg::Role::Kept));
    CHECK(roles.count(cg::Role::Leaving));
    CHECK(v0.segments3.size() == 2 + 3);
    CHECK(v0.points3[0].style.role == cg::Role::Active);
}
