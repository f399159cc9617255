// Toon shading against an independent reference: each face's normal from the cross product of
// its edges in long double, normalised, dotted with the normalised light, clamped at 0 and
// counted against the thresholds (thousands of random triangles, lights and threshold lists,
// with axis-aligned normals and lights among them so that N·L is exactly 0 or ±1). The tie rule
// on exact thresholds, back faces, the 1D texture lookup giving the same bands, the exam's
// exact-fraction answers, the state machine against the plain function, and refused input.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "npr/toon_shading.hpp"

using cg::ToonShading;

namespace {

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
L3 normalised(L3 a) {
    const long double l = std::sqrt(dot(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
}

// N̂·L̂ of a triangle (P0, P1, P2) in long double.
long double ndotl_ref(const ToonShading::Input& in, std::size_t k) {
    const auto& f = in.mesh.faces[k];
    const L3 p0 = ld(in.mesh.vertices[f[0]]), p1 = ld(in.mesh.vertices[f[1]]), p2 = ld(in.mesh.vertices[f[2]]);
    return dot(normalised(cross(sub(p1, p0), sub(p2, p0))), normalised(ld(in.light)));
}

ToonShading::Input triangle(glm::dvec3 light, std::vector<double> t) {
    ToonShading::Input in;
    in.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // N̂ = (0, 0, 1) exactly
    in.mesh.faces = {{0, 1, 2}};
    in.light = light;
    in.thresholds = std::move(t);
    return in;
}

ToonShading::Input pyramid() {
    ToonShading::Input in;
    in.mesh.vertices = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1.5, 0}};
    in.mesh.faces = {{0, 1, 2, 3}, {3, 2, 4}, {2, 1, 4}, {1, 0, 4}, {0, 3, 4}};
    in.light = {3, 3, 1};
    in.thresholds = {0.3, 0.7};
    return in;
}

}  // namespace

TEST_CASE("toon-shading: the pyramid worked by hand", "[npr][toon]") {
    // L̂ = (3, 3, 1)/√19; the sides' normals are (0, 2, 3), (3, 2, 0), (0, 2, −3), (−3, 2, 0)
    // over √13 and the base's (0, −1, 0): N̂·L̂ = 9, 15, 3, −3 over √247 and −3/√19.
    const auto r = ToonShading::compute(pyramid());
    const double s = std::sqrt(247.0);
    CHECK(r.ndotl[0] == Approx(-3 / std::sqrt(19.0)));
    CHECK(r.ndotl[1] == Approx(9 / s));   // 0.573: band 1
    CHECK(r.ndotl[2] == Approx(15 / s));  // 0.954: band 2
    CHECK(r.ndotl[3] == Approx(3 / s));   // 0.191: band 0
    CHECK(r.ndotl[4] == Approx(-3 / s));  // turned away: band 0
    CHECK(r.band == std::vector<int>{0, 1, 2, 0, 0});
    CHECK(r.counts == std::vector<int>{3, 1, 1});
}

TEST_CASE("toon-shading: d exactly on a threshold goes to the brighter band", "[npr][toon]") {
    // N̂ = (0, 0, 1); L = (a, 0, c) from a Pythagorean triple has |L| = an integer exactly, so
    // N̂·L̂ = fl(c/h), the very double the threshold is written as.
    const int triples[][3] = {{3, 4, 5}, {4, 3, 5}, {5, 12, 13}, {12, 5, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}};
    for (const auto& p : triples) {
        const double t = static_cast<double>(p[1]) / p[2];
        CAPTURE(t);
        auto r = ToonShading::compute(triangle({p[0], 0, p[1]}, {t}));
        REQUIRE(r.ndotl[0] == t);
        CHECK(r.band[0] == 1);
        r = ToonShading::compute(triangle({p[0], 0, p[1]}, {t / 2, t, (1 + t) / 2}));
        CHECK(r.band[0] == 2);
        // Just above the value: the darker side.
        r = ToonShading::compute(triangle({p[0], 0, p[1]}, {std::nextafter(t, 1.0)}));
        CHECK(r.band[0] == 0);
    }
    // The worked example's narration names the tie.
    ToonShading::State s = ToonShading::start(triangle({3, 0, 4}, {0.5, 0.8}));
    cg::StepInfo info;
    ToonShading::step(s, &info);
    CHECK(info.event == "on-threshold");
    CHECK(std::get<long long>(info.vars[5].value) == 2);
}

TEST_CASE("toon-shading: a face turned from the light is the darkest band", "[npr][toon]") {
    for (const glm::dvec3 l : {glm::dvec3{0, 0, -1}, glm::dvec3{1, 0, -1e-9}, glm::dvec3{1, 0, 0}}) {
        CAPTURE(l.x, l.z);
        const auto r = ToonShading::compute(triangle(l, {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}));
        CHECK(r.ndotl[0] <= 0);
        CHECK(r.band[0] == 0);
    }
    cg::StepInfo info;
    ToonShading::State s = ToonShading::start(triangle({0, 0, -1}, {0.5}));
    ToonShading::step(s, &info);
    CHECK(info.event == "unlit");
}

TEST_CASE("toon-shading: agrees with the long-double reference on thousands of random faces", "[npr][toon]") {
    int faces = 0, near_ties = 0, unlit = 0;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        ToonShading::Input in;
        auto coord = [&] {
            // One coordinate in five a small integer, so that axis-aligned and exact cases come up.
            return rng.chance(0.2) ? static_cast<double>(rng.integer(-1, 1)) : rng.uniform(-1, 1);
        };
        for (int k = 0; k < 10; ++k) {
            glm::dvec3 p[3];
            for (;;) {
                for (auto& q : p) q = {coord(), coord(), coord()};
                if (glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) > 1e-6) break;
            }
            const int base = static_cast<int>(in.mesh.vertices.size());
            for (const auto& q : p) in.mesh.vertices.push_back(q);
            in.mesh.faces.push_back({base, base + 1, base + 2});
        }
        do in.light = {coord(), coord(), coord()};
        while (glm::length(in.light) < 1e-3);
        const int n = static_cast<int>(rng.integer(1, 7));
        while (static_cast<int>(in.thresholds.size()) < n) {
            const double t = rng.chance(0.3) ? rng.integer(1, 9) / 10.0 : rng.uniform(0.001, 0.999);
            if (std::find(in.thresholds.begin(), in.thresholds.end(), t) == in.thresholds.end())
                in.thresholds.push_back(t);
        }
        std::sort(in.thresholds.begin(), in.thresholds.end());
        const auto r = ToonShading::compute(in);
        REQUIRE(r.band.size() == in.mesh.faces.size());
        std::vector<int> counts(in.thresholds.size() + 1, 0);
        for (std::size_t k = 0; k < in.mesh.faces.size(); ++k) {
            ++faces;
            const long double nl = ndotl_ref(in, k);
            const long double d = std::max(0.0L, nl);
            CHECK(std::fabs(r.ndotl[k] - static_cast<double>(nl)) < 1e-12);
            int band = 0;
            bool near = false;
            for (double t : in.thresholds) {
                band += d >= static_cast<long double>(t);
                near = near || std::fabs(d - t) < 1e-12L;
            }
            if (nl <= 0) ++unlit;
            if (near) {
                ++near_ties;
                CHECK(std::abs(r.band[k] - band) <= 1);
            } else {
                CHECK(r.band[k] == band);
            }
            ++counts[static_cast<std::size_t>(r.band[k])];
        }
        CHECK(r.counts == counts);
    }
    CHECK(faces == 10000);
    CHECK(unlit > 3000);      // about half the faces are turned away
    CHECK(near_ties < 200);   // axis-aligned lights on tenths: rare, and within one band
}

TEST_CASE("toon-shading: the 1D texture lookup gives the same bands", "[npr][toon]") {
    // A texture of W texels, u = d, texel j = min(⌊u W⌋, W − 1), holding the band of its left
    // edge j/W. With every threshold a multiple of 1/W the texture and the thresholds are the
    // same function of d.
    for (int W : {2, 3, 4, 8, 10}) {
        for (std::uint64_t seed = 0; seed < 50; ++seed) {
            cg::Rng rng(seed * 31 + W);
            std::vector<double> t;
            for (int j = 1; j < W; ++j)
                if (rng.chance(0.5) && t.size() < 7) t.push_back(static_cast<double>(j) / W);
            if (t.empty()) t.push_back(1.0 / W);
            std::vector<int> texture(static_cast<std::size_t>(W));
            for (int j = 0; j < W; ++j) {
                int b = 0;
                for (double x : t) b += static_cast<double>(j) / W >= x;
                texture[static_cast<std::size_t>(j)] = b;
            }
            for (int i = 0; i <= 400; ++i) {
                const double d = i / 400.0;  // includes every j/W exactly when W divides 400
                const int texel = std::min(static_cast<int>(std::floor(d * W)), W - 1);
                CAPTURE(W, d);
                CHECK(ToonShading::band_of(d, t) == texture[static_cast<std::size_t>(texel)]);
            }
        }
    }
}

TEST_CASE("toon-shading: the state machine equals the plain function, copies and traces repeat", "[npr][toon]") {
    ToonShading::Input in;
    in.mesh = cg::npr::generate("sphere", 16);
    in.light = {1, 2, 3};
    in.thresholds = {0.25, 0.5, 0.75};
    ToonShading::State s = ToonShading::start(in);
    for (int i = 0; i < 40; ++i) ToonShading::step(s, nullptr);
    ToonShading::State copy = s;
    std::vector<cg::StepInfo> a, b;
    cg::StepInfo info;
    while (!ToonShading::done(s)) ToonShading::step(s, &info), a.push_back(info);
    while (!ToonShading::done(copy)) ToonShading::step(copy, &info), b.push_back(info);
    CHECK(a == b);
    CHECK(copy == s);
    const auto r = ToonShading::compute(in);
    CHECK(ToonShading::result(s) == r);
    CHECK(r.band.size() == 128);  // 16 columns × 8 rings
    // Every band used on a sphere lit from anywhere; half the sphere dark.
    for (int c : r.counts) CHECK(c > 0);
    CHECK(r.counts[0] >= 50);
}

TEST_CASE("toon-shading: bad input is refused, naming the field", "[npr][toon][errors]") {
    static const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("toon-shading");
    REQUIRE(a);
    auto error_of = [&](const cg::json& j) -> std::string {
        try {
            a->create(j);
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "";
    };
    const cg::json base = a->example();
    CHECK(error_of(base).empty());
    auto with = [&](const char* key, cg::json v) {
        cg::json j = base;
        j[key] = std::move(v);
        return j;
    };
    CHECK_THAT(error_of(with("thresholds", cg::json::parse("[0.7, 0.3]"))),
               Catch::Contains("thresholds[1]") && Catch::Contains("greater"));
    CHECK_THAT(error_of(with("thresholds", cg::json::parse("[0.5, 0.5]"))), Catch::Contains("thresholds[1]"));
    CHECK_THAT(error_of(with("thresholds", cg::json::parse("[0, 0.5]"))),
               Catch::Contains("thresholds[0]") && Catch::Contains("between 0 and 1"));
    CHECK_THAT(error_of(with("thresholds", cg::json::parse("[0.5, 1]"))), Catch::Contains("thresholds[1]"));
    CHECK_THAT(error_of(with("thresholds", cg::json::array())), Catch::Contains("2 to 8 bands"));
    CHECK_THAT(error_of(with("thresholds", cg::json::parse("[0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8]"))),
               Catch::Contains("2 to 8 bands"));
    CHECK_THAT(error_of(with("light", cg::json::parse("[0, 0, 0]"))), Catch::Contains("light") && Catch::Contains("zero"));
    CHECK_THAT(error_of(with("light", cg::json::parse("[0, \"x\", 0]"))), Catch::Contains("light"));
    CHECK_THAT(error_of(with("faces", cg::json::parse("[[0, 1, 9]]"))),
               Catch::Contains("faces[0][2]") && Catch::Contains("out of range"));
    CHECK_THAT(error_of(with("faces", cg::json::parse("[[0, 1, 0]]"))), Catch::Contains("repeated"));
    CHECK_THAT(error_of(with("colours", cg::json::parse("[[1, 0, 0]]"))),
               Catch::Contains("colours") && Catch::Contains("one colour per band"));
    CHECK_THAT(error_of(with("colours", cg::json::parse("[[1, 0, 0], [0, 2, 0], [0, 0, 1]]"))),
               Catch::Contains("colours[1][1]"));
    CHECK_THAT(error_of(with("shape", "sphere")), Catch::Contains("not both"));
    cg::json made = cg::json::parse(R"({"shape": "cone", "segments": 8, "light": [0, 1, 0], "thresholds": [0.5]})");
    CHECK_THAT(error_of(made), Catch::Contains("shape"));
    made["shape"] = "torus";
    made["segments"] = 7;
    CHECK_THAT(error_of(made), Catch::Contains("segments") && Catch::Contains("even"));
    made["segments"] = 1000;
    CHECK_THAT(error_of(made), Catch::Contains("segments"));
    made["segments"] = 8;
    CHECK(error_of(made).empty());
}

TEST_CASE("toon-shading: exam answers match the exact fractions", "[npr][toon][exam]") {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const ToonShading::Input in = ToonShading::exam_input(rng);
        REQUIRE_NOTHROW(ToonShading::validate(in));
        const auto r = ToonShading::compute(in);
        // In integers: with N = Newell's (integer) normal and l the integer light, both of
        // integer length, d ≥ t = j/10 ⇔ 10 N·l ≥ j |N| |l| (and N·l > 0).
        const long long lx = std::llround(in.light.x), ly = std::llround(in.light.y), lz = std::llround(in.light.z);
        const long long ml = std::llround(std::sqrt(static_cast<double>(lx * lx + ly * ly + lz * lz)));
        REQUIRE(ml * ml == lx * lx + ly * ly + lz * lz);
        for (std::size_t k = 0; k < in.mesh.faces.size(); ++k) {
            const glm::dvec3 n = cg::npr::newell(in.mesh.vertices, in.mesh.faces[k]);
            const long long nx = std::llround(n.x), ny = std::llround(n.y), nz = std::llround(n.z);
            const long long mn = std::llround(std::sqrt(static_cast<double>(nx * nx + ny * ny + nz * nz)));
            REQUIRE(mn * mn == nx * nx + ny * ny + nz * nz);
            const long long d = nx * lx + ny * ly + nz * lz;
            int band = 0;
            for (double t : in.thresholds) {
                const long long j = std::llround(t * 10);
                REQUIRE(10 * d != j * mn * ml);  // no ties in the exam
                band += d > 0 && 10 * d > j * mn * ml;
            }
            CHECK(r.band[k] == band);
        }
        const std::string q = ToonShading::question(in);
        CHECK_THAT(q, Catch::Contains("N̂0") && Catch::Contains("t1 = "));
    }
    static const cg::Registry registry = cg::builtin_registry();
    const cg::ExamProblem p = cg::make_exam(*registry.find("toon-shading"), 7);
    CHECK(p.answers == std::vector<std::string>{"band"});
}

TEST_CASE("toon-shading: the picture — the face with N̂ and L̂ framed, the rule as a chart",
          "[npr][toon-shading]") {
    ToonShading::Input in;
    in.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // N̂ = (0, 0, 1)
    in.mesh.faces = {{0, 1, 2}};
    in.light = {0, 0, 1};
    in.thresholds = {0.5};
    auto s = ToonShading::start(in);
    ToonShading::step(s, nullptr);
    cg::Scene pic;
    ToonShading::draw(s, pic);
    // N̂ and L̂ from the face's centre, never shorter than 30 px, and the camera framed on them.
    int vectors = 0;
    for (const auto& seg : pic.segments3) vectors += seg.min_pixels >= 30;
    CHECK(vectors == 2);
    CHECK(pic.focus3.size() == 1);
    // The 1D texture as a chart: one cell per band, the face's d at its band.
    REQUIRE(pic.panels.size() == 1);
    const cg::Panel& chart = pic.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.y.step == 1);  // whole bands on the y axis, not 0.2 steps
    CHECK(chart.polygons.size() == 2);
    REQUIRE(chart.points.size() == 1);
    CHECK(chart.points[0].p == glm::dvec2(1, 1));  // d = 1, band 1
    CHECK(chart.points[0].style.role == cg::Role::Active);
}
