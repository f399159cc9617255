// Solid textures and Perlin noise: the noise against its definition redone in long double on
// 10,000 random points; exactly 0 at lattice points; bit-reproducible from the seed, a
// permutation, different seeds different; continuous (C⁰, C¹ and C²) across cell faces on
// thousands of random points; the fade curve's values and flat ends; the four textures against
// their formulas; the state machine bit for bit against the plain function and its worked
// noise equal to the noise used; errors; exam problems; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <set>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/solid_texture.hpp"
#include "rays/texture_reference.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::SolidTextureAlgo;
using glm::dvec3;
namespace t = cg::test;

namespace {

const cg::Algorithm& algo() {
    return cg::test::algorithm("solid-texture");
}

SolidTextureAlgo::Input input_of(const cg::json& j) {
    return cg::test::input_of<SolidTextureAlgo>("solid-texture", j);
}

std::string error_of(const std::string& text) {
    return cg::test::error_of("solid-texture", text);
}

dvec3 random_point(cg::Rng& rng, double L) {
    return {rng.uniform(-L, L), rng.uniform(-L, L), rng.uniform(-L, L)};
}

}  // namespace

TEST_CASE("solid-texture: Perlin noise agrees with its definition in long double",
          "[rays][solid-texture][reference]") {
    cg::Rng rng(21);
    double largest = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        const cg::Perlin n = cg::make_perlin(trial % 17);
        const dvec3 p = random_point(rng, trial % 3 == 0 ? 1000 : 10);
        CAPTURE(trial, p.x, p.y, p.z);
        const double got = cg::perlin_noise(n, p);
        const t::LD want = t::noise_ref(n, t::lv(p));
        CHECK(std::fabs(got - want) <
              1e-12L * (1 + std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z)));
        largest = std::max(largest, std::fabs(got));
        // The detailed evaluation is the same arithmetic.
        const cg::NoiseDetail d = cg::perlin_detail(n, p);
        CHECK(d.value == got);
    }
    CHECK(largest < 1.1);
    CHECK(largest > 0.5);
}

TEST_CASE("solid-texture: noise is 0 at lattice points and reproducible from its seed",
          "[rays][solid-texture]") {
    cg::Rng rng(22);
    for (int trial = 0; trial < 2000; ++trial) {
        const cg::Perlin n = cg::make_perlin(rng.next());
        const dvec3 p(static_cast<double>(rng.integer(-500, 500)),
                      static_cast<double>(rng.integer(-500, 500)),
                      static_cast<double>(rng.integer(-500, 500)));
        CHECK(cg::perlin_noise(n, p) == 0);
    }
    // π is a permutation of 0…255; a seed gives the same one every time, another seed another.
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const cg::Perlin a = cg::make_perlin(seed), b = cg::make_perlin(seed),
                         c = cg::make_perlin(seed + 1);
        CHECK(a == b);
        CHECK(a.perm != c.perm);
        std::set<int> values(a.perm.begin(), a.perm.end());
        CHECK(values.size() == 256);
    }
    // The first values of seed 0 are pinned: a change to the generator or the hash shows here.
    const cg::Perlin n0 = cg::make_perlin(0);
    const double v = cg::perlin_noise(n0, {0.3, 0.7, 0.2});
    CHECK(v == cg::perlin_noise(cg::make_perlin(0), {0.3, 0.7, 0.2}));
    CHECK(v != cg::perlin_noise(cg::make_perlin(1), {0.3, 0.7, 0.2}));
}

TEST_CASE("solid-texture: noise is smooth across cell faces (value, slope and curvature)",
          "[rays][solid-texture][reference]") {
    cg::Rng rng(23);
    const double e = 1e-4;
    int curved = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const cg::Perlin n = cg::make_perlin(trial % 7);
        dvec3 p = random_point(rng, 20);
        const int axis = trial % 3;
        p[axis] = std::round(p[axis]);  // on a cell face
        dvec3 step(0.0);
        step[axis] = e;
        CAPTURE(trial, axis, p.x, p.y, p.z);
        auto f = [&](double s) { return cg::perlin_noise(n, p + (s / e) * step); };
        // C⁰: the values on both sides meet.
        CHECK(std::fabs(f(1e-12) - f(-1e-12)) < 1e-10);
        // C¹: one-sided slopes agree (differences of f on each side, to O(e)).
        const double left = (f(0) - f(-e)) / e, right = (f(e) - f(0)) / e;
        CHECK(std::fabs(left - right) < 60 * e);
        // C²: one-sided second differences agree too. The quintic fade has f'' = 0 at 0 and 1,
        // so across a face the noise's second derivative along the face normal is 0 on both
        // sides (the classic 3t² − 2t³ would jump by 6 × the difference of the ramps there).
        const double c_left = (f(0) - 2 * f(-e) + f(-2 * e)) / (e * e),
                     c_right = (f(2 * e) - 2 * f(e) + f(0)) / (e * e);
        CHECK(std::fabs(c_left - c_right) < 0.1);
        CHECK(std::fabs(c_left) < 0.1);
        // Inside the cell the noise does curve: the check above is not trivially passed.
        const double mid = (f(0.5 + e) - 2 * f(0.5) + f(0.5 - e)) / (e * e);
        curved += std::fabs(mid) > 0.1;
    }
    CHECK(curved > 1000);
}

TEST_CASE("solid-texture: the fade curve 6t⁵ − 15t⁴ + 10t³", "[rays][solid-texture]") {
    CHECK(cg::fade(0) == 0);
    CHECK(cg::fade(1) == 1);
    CHECK(cg::fade(0.5) == 0.5);
    CHECK(cg::fade(0.25) == 0.103515625);
    CHECK(cg::fade(0.75) == 0.896484375);
    for (int k = 0; k <= 100; ++k) {
        const double x = k / 100.0;
        CHECK(std::fabs(cg::fade(x) - t::fade_ref(x)) < 1e-14L);
    }
    const double h = 1e-5;
    CHECK(std::fabs((cg::fade(h) - cg::fade(0)) / h) < 1e-8);                // f'(0) = 0
    CHECK(std::fabs((cg::fade(1) - cg::fade(1 - h)) / h) < 1e-8);            // f'(1) = 0
    CHECK(std::fabs((cg::fade(2 * h) - 2 * cg::fade(h)) / (h * h)) < 1e-3);  // f''(0) = 0
}

TEST_CASE("solid-texture: the four textures follow their formulas",
          "[rays][solid-texture][reference]") {
    cg::Rng rng(24);
    for (int trial = 0; trial < 4000; ++trial) {
        cg::SolidTexture tx;
        tx.kind = static_cast<cg::SolidKind>(trial % 4);
        tx.colors = {dvec3(rng.uniform(0, 1), 0.2, 0.3), dvec3(0.1, rng.uniform(0, 1), 0.9)};
        tx.size = rng.uniform(0.2, 3);
        tx.axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), 1};
        tx.period = rng.uniform(0.2, 3);
        tx.amplitude = rng.uniform(0, 5);
        tx.frequency = rng.uniform(0.5, 4);
        tx.octaves = static_cast<int>(rng.integer(1, 6));
        tx.seed = static_cast<std::uint64_t>(trial);
        const cg::Perlin n = cg::make_perlin(tx.seed);
        const dvec3 p = random_point(rng, 5);
        CAPTURE(trial, p.x, p.y, p.z);
        const cg::SolidSample s = cg::solid_sample(tx, n, p);
        const t::LVec P = t::lv(p), A = t::normalized(t::lv(tx.axis));
        t::LD want = 0;
        switch (tx.kind) {
            case cg::SolidKind::Checker: {
                const long long k =
                    static_cast<long long>(std::floor(P.x / tx.size) + std::floor(P.y / tx.size) +
                                           std::floor(P.z / tx.size));
                want = ((k % 2) + 2) % 2;
                break;
            }
            case cg::SolidKind::Stripes:
                want = 0.5L * (1 + std::sin(2 * t::kPiL * t::dot(P, A) / tx.period));
                break;
            case cg::SolidKind::Wood: {
                const t::LD r = t::len(P - t::dot(P, A) * A);
                const t::LD rings =
                    r / tx.period + tx.amplitude * t::noise_ref(n, tx.frequency * P);
                want = rings - std::floor(rings);
                break;
            }
            case cg::SolidKind::Marble: {
                t::LD turb = 0;
                for (int k = 0; k < tx.octaves; ++k)
                    turb += std::fabs(t::noise_ref(n, std::ldexp(1.0L, k) * tx.frequency * P)) /
                            std::ldexp(1.0L, k);
                CHECK(std::fabs(s.noise - turb) < 1e-11L);
                want = 0.5L *
                       (1 + std::sin(2 * t::kPiL * t::dot(P, A) / tx.period + tx.amplitude * turb));
                break;
            }
        }
        // frac() jumps from 1 to 0: compare wood's t on the circle.
        t::LD diff = std::fabs(s.t - want);
        if (tx.kind == cg::SolidKind::Wood) diff = std::min(diff, 1 - diff);
        CHECK(diff < 1e-9L);
        const dvec3 c = (1 - s.t) * tx.colors[0] + s.t * tx.colors[1];
        CHECK(s.color == c);
    }
}

TEST_CASE("solid-texture: the worked steps and the plain function agree bit for bit",
          "[rays][solid-texture]") {
    const auto tr = cg::test::run_traced<SolidTextureAlgo>(input_of(algo().example()));
    CHECK(cg::test::events(tr) == std::vector<std::string>{"lattice", "gradients", "fade",
                                                           "interpolate", "turbulence", "colour",
                                                           "point", "point"});
    const SolidTextureAlgo::Input in = input_of(algo().example());
    const cg::Perlin n = cg::make_perlin(in.texture.seed);
    // The worked noise is the noise at f p, and the octaves add up to the turbulence used.
    CHECK(tr.result.detail.value == cg::perlin_noise(n, in.texture.frequency * in.points[0]));
    double sum = 0;
    for (double o : tr.result.octaves) sum += o;
    CHECK(sum == tr.result.samples[0].noise);
    CHECK(tr.result.detail.cell == std::array<long long, 3>{0, 1, 0});

    cg::Rng rng(25);
    std::set<std::string> events;
    for (int trial = 0; trial < 500; ++trial) {
        SolidTextureAlgo::Input r;
        r.texture.kind = static_cast<cg::SolidKind>(trial % 4);
        r.texture.seed = rng.next() >> 12;
        r.texture.octaves = static_cast<int>(rng.integer(1, 5));
        for (int k = 0; k < 1 + trial % 5; ++k) r.points.push_back(random_point(rng, 4));
        r.detail = static_cast<int>(rng.integer(0, static_cast<long long>(r.points.size()) - 1));
        CAPTURE(trial);
        const auto want = SolidTextureAlgo::solve(r);
        auto s = SolidTextureAlgo::start(r);
        const auto got = cg::run_to_end<SolidTextureAlgo>(s);
        CHECK(got.samples == want.samples);
        const auto traced = cg::test::run_traced<SolidTextureAlgo>(r);
        CHECK(traced.result.samples == want.samples);
        for (const auto& st : traced.steps) events.insert(st.event);
    }
    for (const auto& e : SolidTextureAlgo::spec().events) {
        CAPTURE(e.id);
        CHECK(events.count(e.id) == 1);
    }
}

TEST_CASE("solid-texture: bad input is refused with the field named",
          "[rays][solid-texture][errors]") {
    const std::string pts = R"("points": [[0, 0, 0]])";
    CHECK_THAT(error_of(R"({"texture": {"type": "marble", "octaves": 0}, )" + pts + "}"),
               Catch::StartsWith("texture.octaves: must be a number of octaves from 1 to 16"));
    CHECK_THAT(error_of(R"({"texture": {"type": "marble", "octaves": 17}, )" + pts + "}"),
               Catch::StartsWith("texture.octaves: must be a number of octaves from 1 to 16"));
    CHECK_THAT(error_of(R"({"texture": {"type": "wood", "period": 0}, )" + pts + "}"),
               Catch::StartsWith("texture.period: must be a length between 1e-9 and 1e12"));
    CHECK_THAT(error_of(R"({"texture": {"type": "stripes", "axis": [0, 0, 0]}, )" + pts + "}"),
               Catch::StartsWith("texture.axis: must be a nonzero finite direction"));
    CHECK_THAT(error_of(R"({"texture": {"type": "checker", "size": -1}, )" + pts + "}"),
               Catch::StartsWith("texture.size: must be a length"));
    CHECK_THAT(error_of(R"({"texture": {"type": "checker", "octaves": 3}, )" + pts + "}"),
               Catch::StartsWith("texture.octaves: is not a field of a checker solid texture"));
    CHECK_THAT(error_of(R"({"texture": {"type": "granite"}, )" + pts + "}"),
               Catch::StartsWith(
                   "texture.type: must be \"checker\", \"stripes\", \"wood\" or \"marble\""));
    CHECK_THAT(error_of(R"({"texture": {"type": "wood", "frequency": 1e7}, )" + pts + "}"),
               Catch::StartsWith("texture.frequency: must be between 1e-9 and 1e6"));
    CHECK_THAT(error_of(R"({"texture": {"type": "wood", "colors": [1]}, )" + pts + "}"),
               Catch::StartsWith("texture.colors: must be two colours"));
    CHECK_THAT(error_of(R"({"texture": {"type": "wood"}, "points": []})"),
               Catch::StartsWith("points: must list at least one point"));
    CHECK_THAT(error_of(R"({"texture": {"type": "wood"}, "points": [[1e300, 0, 0]]})"),
               Catch::StartsWith("points[0][0]: is too large for the texture's lattice"));
    CHECK_THAT(
        error_of(
            R"({"texture": {"type": "marble", "octaves": 16, "frequency": 1}, "points": [[1e5, 0, 0]]})"),
        Catch::StartsWith("points[0][0]: is too large for the texture's lattice"));
    CHECK_THAT(error_of(R"({"texture": {"type": "wood"}, )" + pts + R"(, "detail": 1})"),
               Catch::StartsWith("detail: must be the index of a point, 0 to 0"));
}

TEST_CASE("solid-texture: exam problems are answered as the reference says",
          "[rays][solid-texture][exam]") {
    int corners = 0, noisy = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(algo(), seed);
        const SolidTextureAlgo::Input in = input_of(p.input);
        const dvec3 q = in.texture.frequency * in.points[0];
        if (cg::uses_noise(in.texture.kind)) {
            ++noisy;
            const cg::Perlin n = cg::make_perlin(in.texture.seed);
            const t::LD ref = t::noise_ref(n, t::lv(q));
            const double got = p.expected["noise"][0].get<double>();
            if (in.texture.kind == cg::SolidKind::Wood)
                CHECK(std::fabs(got - ref) < 1e-12L);
            else
                CHECK(std::fabs(got - std::fabs(ref)) < 1e-12L);
            corners += q == glm::floor(q);
            // The fractions are quarters: the question's numbers stay short.
            const dvec3 f = q - glm::floor(q);
            for (int k = 0; k < 3; ++k) CHECK(f[k] * 4 == std::round(f[k] * 4));
            CHECK(p.question.find("gradients") != std::string::npos);
        } else {
            CHECK(p.expected["noise"][0].is_null());
        }
        CHECK(cg::grade(p, p.expected)[2].correct);
    }
    CHECK(noisy > 150);
    CHECK(corners > 5);
}

TEST_CASE("solid-texture: traces are deterministic and stepping back reproduces them",
          "[rays][solid-texture]") {
    cg::test::check_replay(algo(), algo().example(), cg::test::kEveryStep);
    cg::test::check_replay(algo(), cg::parse_json(R"({"texture": {"type": "wood", "seed": 2},
                                              "points": [[0.25, 0.5, 0.75], [0.6, 0.1, 0.2]], "detail": 1})"),
                           cg::test::kEveryStep);
}

TEST_CASE("solid-texture: the picture shows the points, the lattice cell and the fade curve",
          "[rays][solid-texture]") {
    auto s = SolidTextureAlgo::start(input_of(algo().example()));
    cg::StepInfo info;
    SolidTextureAlgo::step(s, &info);  // lattice
    SolidTextureAlgo::step(s, &info);  // gradients
    SolidTextureAlgo::step(s, &info);  // fade
    cg::Scene scene;
    SolidTextureAlgo::draw(s, scene);
    int edges = 0, gradients = 0;
    for (const auto& seg : scene.segments3) {
        edges += seg.style.role == cg::Role::Window;
        gradients += seg.arrow && !seg.label.empty();
    }
    CHECK(edges == 12);
    CHECK(gradients == 8);
    // The fade curve is a chart: the quintic and the cubic, x, y, z on it.
    CHECK_FALSE(scene.has_2d());
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& chart = scene.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.polygons.size() == 2);
    CHECK(chart.legend.size() == 2);
    CHECK(chart.points.size() == 3);
    // The camera frames the lattice cell; the block's walls show the texture (not one colour).
    CHECK(scene.focus3.size() == 1);
    std::set<std::uint32_t> colours;
    for (const auto& f : scene.faces3) colours.insert(f.style.rgba);
    CHECK(colours.size() > 20);
}
