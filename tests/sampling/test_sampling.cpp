// Sampling a signal and an image: the course's exam case (7 kHz sampled at 10 kHz: 3 kHz) and
// other folds worked by hand; 3,000 random sines against the brute-force check — the sampled
// values of f and of its alias agree at every sample time, to 1e-9 — with the fold in [0, f_s/2]
// and the aliased flag from the definition; the reconstruction's error figures (nearest ∝ 1/f_s,
// linear ∝ 1/f_s², windowed sinc far smaller below Nyquist, all of them failing above it);
// the 2D images (a point-sampled edge is a staircase, supersampled its pixels equal the exact
// coverage on average; the zone plate aliases beyond ρ); run to the end == the plain function;
// errors naming the field; determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>

#include "io/registry.hpp"
#include "sampling/coverage.hpp"
#include "sampling/sampling.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::Sampling;

namespace {

Sampling::Input signal(std::vector<Sampling::Component> c, double rate, double duration,
                       Sampling::Reconstruction r = Sampling::Reconstruction::Linear) {
    Sampling::Input in;
    in.mode = Sampling::Mode::Signal;
    in.signal = std::move(c);
    in.rate = rate;
    in.duration = duration;
    in.reconstruction = r;
    return in;
}

using Traced = cg::test::Traced<Sampling>;
Traced run_traced(const Sampling::Input& in) {
    return cg::test::run_traced<Sampling>(in);
}

}  // namespace

TEST_CASE("sampling: folds worked by hand", "[sampling]") {
    SECTION("the course's question: 7 kHz sampled at 10 kHz looks like 3 kHz") {
        const Traced t = run_traced(signal({{7, 1, 0}}, 10, 1));
        REQUIRE(t.result.aliases.size() == 1);
        const auto& a = t.result.aliases[0];
        CHECK(a.alias == Approx(3).epsilon(1e-15));
        CHECK(a.k == 1);
        CHECK(a.aliased);
        CHECK(a.alias_phase == 180);  // 7 − 10 < 0: the fold mirrors the sine
        CHECK(t.result.nyquist_rate == 14);
        CHECK(t.result.samples.size() == 11);
        std::vector<std::string> ev = cg::test::events(t);
        CHECK(ev.front() == "sample");
        CHECK(ev[11] == "fold");
        CHECK(ev.back() == "reconstruct");
        CHECK_THAT(t.steps[11].narration, Catch::Contains("folds to |7 − 1·10| = 3"));
        // sin(2π 7 n/10) = −sin(2π 3 n/10) = sin(2π 3 n/10 + 180°) at every sample.
        for (const auto& s : t.result.samples)
            CHECK(s.y == Approx(std::sin(2 * M_PI * 3 * s.x + M_PI)).margin(1e-12));
    }
    SECTION("below Nyquist a frequency is its own alias") {
        const auto a = Sampling::fold(3, 30, 10);
        CHECK(a.alias == 3);
        CHECK(a.k == 0);
        CHECK_FALSE(a.aliased);
        CHECK(a.alias_phase == 30);
    }
    SECTION("exactly at f_s/2: aliased (its amplitude and phase are lost)") {
        const auto a = Sampling::fold(5, 0, 10);
        CHECK(a.alias == 5);
        CHECK(a.aliased);
    }
    SECTION("a multiple of the rate: a constant") {
        const auto a = Sampling::fold(20, 90, 10);
        CHECK(a.alias == 0);
        CHECK(a.k == 2);
        CHECK(a.alias_phase == 90);
    }
    SECTION("above the rate: 12 kHz at 10 kHz is 2 kHz, not mirrored") {
        const auto a = Sampling::fold(12, 45, 10);
        CHECK(a.alias == Approx(2).epsilon(1e-15));
        CHECK(a.k == 1);
        CHECK(a.alias_phase == 45);
    }
    SECTION("two sines: the Nyquist rate is twice the higher") {
        const Traced t = run_traced(signal({{2, 1, 0}, {9, 0.5, 90}}, 16, 0.5));
        CHECK(t.result.nyquist_rate == 18);
        CHECK_FALSE(t.result.aliases[0].aliased);
        CHECK(t.result.aliases[1].aliased);
        CHECK(t.result.aliases[1].alias == Approx(7));
        CHECK(t.result.aliases[1].alias_phase == 90);  // 180° − 90°
        CHECK(t.steps[9].event == "below-nyquist");
        CHECK(t.steps[10].event == "fold");
    }
}

TEST_CASE("sampling: 3,000 random sines — the alias has the same samples, to 1e-9", "[sampling]") {
    int aliased = 0, mirrored = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(trial);
        const double rate = trial % 5 == 0 ? double(rng.integer(2, 40)) : rng.uniform(0.5, 50);
        double f = rng.uniform(0, 5 * rate);
        switch (trial % 7) {  // the degenerate ones: multiples of f_s/2, zero
            case 0:
                f = rate / 2 * double(rng.integer(0, 8));
                break;
            case 1:
                f = 0;
                break;
            default:
                break;
        }
        const double phase = rng.uniform(-180, 180), amp = rng.uniform(-3, 3);
        const auto a = Sampling::fold(f, phase, rate);
        CAPTURE(f, rate, phase, a.alias, a.alias_phase, a.k);
        REQUIRE(a.alias >= 0);
        REQUIRE(a.alias <= rate / 2 * (1 + 1e-12));
        REQUIRE(a.aliased == (rate <= 2 * f));
        REQUIRE(a.alias_phase > -180);
        REQUIRE(a.alias_phase <= 180);
        if (!a.aliased) REQUIRE(a.alias == f);
        aliased += a.aliased;
        mirrored += a.alias_phase != phase;
        // Brute force in long double: both sines at 64 sample times.
        for (int n = 0; n < 64; ++n) {
            const long double t = (long double)n / rate;
            const long double pi = 3.141592653589793238462643383279502884L;
            const long double x = amp * std::sin(2 * pi * f * t + phase * pi / 180);
            const long double y = amp * std::sin(2 * pi * a.alias * t + a.alias_phase * pi / 180);
            REQUIRE(std::fabs(double(x - y)) <= 1e-9);
        }
    }
    CHECK(aliased > 1500);
    CHECK(mirrored > 500);
}

TEST_CASE("sampling: reconstruction error figures", "[sampling]") {
    using R = Sampling::Reconstruction;
    // One sine of frequency 1 over [0, 4], sampled ever faster.
    auto err = [](R r, double rate, double f = 1) {
        return Sampling::error_rms(signal({{f, 1, 20}}, rate, 4, r));
    };
    std::string table = "rate: nearest linear sinc";
    for (double rate : {2.5, 5.0, 10.0, 20.0, 40.0})
        table += "\n" + std::to_string(rate) + ": " + std::to_string(err(R::Nearest, rate)) + " " +
                 std::to_string(err(R::Linear, rate)) + " " + std::to_string(err(R::Sinc, rate));
    WARN(table);
    // Nearest: error ∝ 1/f_s; linear ∝ 1/f_s².
    CHECK(err(R::Nearest, 10) / err(R::Nearest, 40) == Approx(4).epsilon(0.15));
    CHECK(err(R::Linear, 10) / err(R::Linear, 40) == Approx(16).epsilon(0.15));
    // The windowed sinc beats both below Nyquist.
    for (double rate : {5.0, 10.0, 20.0}) {
        CHECK(err(R::Sinc, rate) < err(R::Linear, rate));
        CHECK(err(R::Linear, rate) < err(R::Nearest, rate));
    }
    CHECK(err(R::Sinc, 10) < 0.01);
    // Above Nyquist no reconstruction comes close: 7 at 10 follows the 3.
    for (R r : {R::Nearest, R::Linear, R::Sinc}) CHECK(err(r, 10, 7) > 0.5);
    // The sinc reconstruction of 7 at 10 is (close to) the alias, a sine of 3.
    const Sampling::Input in = signal({{7, 1, 0}}, 10, 4, R::Sinc);
    double worst = 0;
    for (int q = 0; q <= 400; ++q) {
        const double t = 4.0 * q / 400;
        worst = std::max(
            worst, std::fabs(Sampling::reconstruct(in, t) - std::sin(2 * M_PI * 3 * t + M_PI)));
    }
    CHECK(worst < 0.1);
    // At the samples every reconstruction gives the sample back.
    for (R r : {R::Nearest, R::Linear, R::Sinc}) {
        const Sampling::Input s = signal({{1.3, 0.8, 10}, {4.1, 0.3, 0}}, 9, 2, r);
        for (int n = 0; n <= 18; ++n)
            CHECK(Sampling::reconstruct(s, n / 9.0) ==
                  Approx(Sampling::signal(s.signal, n / 9.0)).margin(1e-12));
    }
}

TEST_CASE("sampling: images — stairsteps, and supersampling converging on the coverage",
          "[sampling]") {
    Sampling::Input in;
    in.mode = Sampling::Mode::Image;
    in.width = 24, in.height = 16;
    in.image.kind = Sampling::ImageKind::Edge;
    in.image.angle = 20;
    in.image.point = {12, 8};
    in.samples = 64;
    const auto r = Sampling::run(in);
    cg::sampling::Region edge;
    edge.kind = cg::sampling::RegionKind::Edge;
    edge.point = in.image.point;
    edge.angle_deg = in.image.angle;
    double err = 0;
    int grey = 0;
    for (int j = 0; j < in.height; ++j)
        for (int i = 0; i < in.width; ++i) {
            const std::size_t k = std::size_t(j) * in.width + i;
            // Point sampled: 0 or 1 only, the centre's side.
            REQUIRE((r.point_sampled[k] == 0 || r.point_sampled[k] == 1));
            REQUIRE(r.point_sampled[k] == cg::sampling::region_value(edge, {i + 0.5, j + 0.5}));
            const double exact =
                cg::sampling::exact_coverage(edge, cg::sampling::Filter::Box, i, j);
            err += std::pow(r.supersampled[k] - exact, 2);
            grey += r.supersampled[k] > 0 && r.supersampled[k] < 1;
            REQUIRE(std::fabs(r.supersampled[k] - exact) <=
                    0.25);  // 8 × 8 jittered: ≤ 15 cells crossed, 1/64 each
        }
    CHECK(std::sqrt(err / (in.width * in.height)) < 0.01);
    CHECK(grey >= in.width);  // every column the edge crosses has an in-between pixel

    // The zone plate: point sampling has as much contrast beyond ρ as inside it (false rings);
    // supersampled, the rings beyond 2ρ fade toward grey.
    Sampling::Input z;
    z.mode = Sampling::Mode::Image;
    z.width = z.height = 64;
    z.image.kind = Sampling::ImageKind::ZonePlate;
    z.image.nyquist_radius = 10;
    z.samples = 64;
    const auto zr = Sampling::run(z);
    double dev_point = 0, dev_super = 0;
    int far = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const double r2 = std::hypot(i + 0.5 - 32, j + 0.5 - 32);
            if (r2 < 22 || r2 > 30) continue;
            ++far;
            dev_point += std::fabs(zr.point_sampled[j * 64 + i] - 0.5);
            dev_super += std::fabs(zr.supersampled[j * 64 + i] - 0.5);
        }
    CHECK(dev_point / far > 0.25);
    CHECK(dev_super / far < 0.1);
}

TEST_CASE("sampling: run to the end equals the plain function", "[sampling]") {
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        cg::Rng rng(7000 + trial);
        Sampling::Input in;
        if (trial % 2 == 0) {
            in = signal({}, rng.uniform(1, 30), rng.uniform(0.05, 2),
                        static_cast<Sampling::Reconstruction>(trial % 3));
            for (long long k = rng.integer(1, 4); k > 0; --k)
                in.signal.push_back(
                    {rng.uniform(0, 40), rng.uniform(-2, 2), rng.uniform(-180, 180)});
        } else {
            in.mode = Sampling::Mode::Image;
            in.width = static_cast<int>(rng.integer(1, 12));
            in.height = static_cast<int>(rng.integer(1, 12));
            in.image.kind = static_cast<Sampling::ImageKind>(trial / 2 % 3);
            in.image.angle = rng.uniform(0, 360);
            in.image.point = {rng.uniform(0, in.width), rng.uniform(0, in.height)};
            in.image.horizon = rng.uniform(0.5, 1.5) * in.height;
            in.image.square = rng.uniform(0.05, 1);
            in.image.focal = in.height;
            in.image.nyquist_radius = rng.uniform(1, 10);
            in.pattern = static_cast<cg::sampling::Pattern>(rng.integer(0, 3));
            in.samples = cg::sampling::is_grid(in.pattern) ? 9 : 7;
            in.filter = static_cast<cg::sampling::Filter>(rng.integer(0, 2));
            in.seed = trial;
        }
        Sampling::validate(in);
        REQUIRE(cg::run_to_end<Sampling>(Sampling::start(in)) == Sampling::run(in));
    }
}

TEST_CASE("sampling: errors name the field", "[sampling][errors]") {
    const cg::Algorithm& a = cg::test::algorithm("sampling");
    auto error_of = [&](const std::string& text) -> std::string {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "(accepted)";
    };
    CHECK(error_of(R"({"rate": 10, "duration": 1})") ==
          "signal: is missing: give either a 1D \"signal\" or a 2D \"image\"");
    CHECK(error_of(R"({"signal": [], "rate": 10, "duration": 1})") ==
          "signal: must list between 1 and 16 sines (got 0)");
    CHECK(error_of(R"({"signal": [{"frequency": -1}], "rate": 10, "duration": 1})") ==
          "signal[0].frequency: must be between 0 and 10¹² (got −1)");
    CHECK(error_of(R"({"signal": [{"frequency": 1}], "rate": 0, "duration": 1})") ==
          "rate: must be positive and at most 10¹² (got 0)");
    CHECK(error_of(R"({"signal": [{"frequency": 1}], "rate": 10, "duration": 1000})") ==
          "duration: gives 10001 samples at this rate; at most 4096 are allowed");
    CHECK(
        error_of(
            R"({"signal": [{"frequency": 1}], "rate": 10, "duration": 1, "reconstruction": "cubic"})") ==
        "reconstruction: must be \"nearest\", \"linear\" or \"sinc\", got \"cubic\"");
    CHECK(error_of(R"({"signal": [{"frequency": 1, "amp": 2}], "rate": 10, "duration": 1})") ==
          "signal[0].amp: is not a known field (expected: frequency, amplitude, phase)");
    CHECK(error_of(R"({"image": {"type": "mandrill"}, "width": 8, "height": 8})") ==
          "image.type: must be \"edge\", \"checkerboard\" or \"zone-plate\", got \"mandrill\"");
    CHECK(error_of(R"({"image": {"type": "zone-plate"}, "width": 0, "height": 8})") ==
          "width: must be between 1 and 256 (got 0)");
    CHECK(
        error_of(
            R"({"image": {"type": "zone-plate"}, "width": 8, "height": 8, "supersampling": {"pattern": "regular", "samples": 8}})") ==
        "supersampling.samples: must be a square number n × n (1, 4, 9, 16, …) for the regular "
        "pattern (got 8)");
    CHECK(error_of(
              R"({"image": {"type": "checkerboard", "horizon": -2}, "width": 8, "height": 8})") ==
          "image.horizon: must be above the bottom row: between 0 (excluded) and 10⁶ pixels (got "
          "−2)");
    CHECK(
        error_of(
            R"({"image": {"type": "zone-plate"}, "width": 256, "height": 256, "supersampling": {"samples": 256}})") ==
        "supersampling.samples: makes 16777216 samples for the image; at most 4·10⁶ are "
        "allowed");
}

TEST_CASE("sampling: determinism, resumability and the picture", "[sampling]") {
    const cg::Algorithm& a = cg::test::algorithm("sampling");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    const cg::json image = cg::parse_json(
        R"({"image": {"type": "checkerboard"}, "width": 16, "height": 12, "supersampling": {"samples": 9, "pattern": "poisson"}})");
    cg::test::check_replay(a, image, 4);

    // 1D: after the fold of 7 kHz, the dashed alias (red) runs through every sample.
    auto run = a.create(a.example());
    for (int k = 0; k < 12; ++k) run->step(nullptr);
    cg::Scene scene;
    run->draw(scene);
    // Two charts in their own units, nothing on the world's grid: s(t) against t, the spectrum.
    CHECK_FALSE(scene.has_2d());
    REQUIRE(scene.panels.size() == 2);
    CHECK(scene.panels[0].x.label == "t");
    CHECK(scene.panels[1].x.label == "f");
    bool alias_curve = false;
    for (const auto& p : scene.panels[0].polygons)
        alias_curve = alias_curve || (p.style.role == cg::Role::Discarded && p.style.dashed);
    CHECK(alias_curve);
    bool alias_bar = false;  // 7 folds to 3, a red bar at f = 3
    for (const auto& sg : scene.panels[1].segments)
        alias_bar = alias_bar || (sg.style.role == cg::Role::Discarded && sg.a.x == Approx(3));
    CHECK(alias_bar);
    // 2D: two image panels, filled up to the current row (the rest pale blue).
    auto img = a.create(image);
    img->step(nullptr);
    img->step(nullptr);
    cg::Scene s2;
    img->draw(s2);
    CHECK_FALSE(s2.has_2d());
    REQUIRE(s2.panels.size() == 2);
    for (const auto& p : s2.panels) CHECK(p.kind == cg::PanelKind::Image);
    const auto& g = s2.panels[0].grids.at(0);
    CHECK(g.width == 16);
    int filled = 0;
    for (auto v : g.rgba) filled += v != 0xdde8f5ffu;
    CHECK(filled == 2 * 16);
    CHECK(s2.panels[0].handles.empty());  // only an edge has a point to drag
    // An edge's point is a handle in the first image (the point-sampled one).
    auto edge = a.create(cg::parse_json(
        R"({"image": {"type": "edge", "point": [5.5, 4], "angle": 30}, "width": 16, "height": 12})"));
    cg::Scene s3;
    edge->draw(s3);
    REQUIRE(s3.panels.size() == 2);
    REQUIRE(s3.panels[0].handles.size() == 1);
    CHECK(s3.panels[0].handles[0].p == glm::dvec2(5.5, 4));
    CHECK(s3.panels[0].handles[0].x_field == "/image/point/0");
    CHECK(s3.panels[1].handles.empty());
}
