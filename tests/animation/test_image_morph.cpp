// Image morphing: the exam-style example worked by hand (u, v, the source points, the blended
// row, the clamped border); every warped, morphed and dissolved pixel of 2,000 seeded random
// cases (1 to 8 pixels a side, 1 to 4 line pairs, random a, b, p, several α) against an
// independent long-double implementation of the field warp, the bilinear sampling and the
// blend, to 1e-9 of the value range; α = 0 gives A and α = 1 gives B exactly; the same lines in
// A and B give exactly the plain cross-dissolve; a translated line pair warps by exactly that
// translation inside the image; two opposite lines meeting half way are left out of that frame;
// the state machine equals compute; replay; bad input names the field; exam problems against a
// hand computation; the narration and the picture.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "animation/image_morph.hpp"
#include "core/format.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/sweep.hpp"
#include "support/traced.hpp"

using cg::ImageMorph;
using Input = ImageMorph::Input;
using Image = ImageMorph::Image;
using LD = long double;

namespace {

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("image-morph");
    if (!l) throw std::runtime_error("no lesson for image-morph");
    return *l;
}

std::string err(const std::string& text) {
    return cg::test::error_of("image-morph", text);
}

// ---- the reference: the field warp in long double, written separately from the code ----

struct P {
    LD x = 0, y = 0;
};
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator*(LD k, P a) { return {k * a.x, k * a.y}; }
LD dot(P a, P b) { return a.x * b.x + a.y * b.y; }
LD norm(P a) { return std::sqrt(a.x * a.x + a.y * a.y); }
P from(glm::dvec2 p) { return {p.x, p.y}; }

struct RefLine {
    P p, q;
};

// Where destination point x comes from, given destination lines and their source lines.
P ref_source(const std::vector<RefLine>& dst, const std::vector<RefLine>& src, LD a, LD b, LD pw,
             P x) {
    P sum{0, 0};
    LD total = 0;
    for (std::size_t i = 0; i < dst.size(); ++i) {
        const P e = dst[i].q - dst[i].p;
        const LD len = norm(e);
        if (len < LD(1e-6)) continue;
        const P n{-e.y, e.x};
        const P d = x - dst[i].p;
        const LD u = dot(d, e) / (len * len);
        const LD v = dot(d, n) / len;
        const P e2 = src[i].q - src[i].p;
        const P n2{-e2.y, e2.x};
        const P xs = src[i].p + u * e2 + (v / norm(e2)) * n2;
        LD dist;
        if (u < 0)
            dist = norm(x - dst[i].p);
        else if (u > 1)
            dist = norm(x - dst[i].q);
        else
            dist = std::fabs(v);
        const LD w = std::pow(std::pow(len, pw) / (a + dist), b);
        sum = sum + w * (xs - x);
        total += w;
    }
    return total > 0 ? x + (1 / total) * sum : x;
}

LD ref_pixel(const Image& img, int c, int r) {
    c = std::clamp(c, 0, img.width - 1);
    r = std::clamp(r, 0, img.height - 1);
    return LD(img.v[std::size_t(r) * std::size_t(img.width) + std::size_t(c)]);
}

// Bilinear between pixel centres (c + ½, r + ½), the image extended by its border pixels.
LD ref_sample(const Image& img, P x) {
    LD fx = std::clamp(x.x - LD(0.5), LD(0), LD(img.width - 1));
    LD fy = std::clamp(x.y - LD(0.5), LD(0), LD(img.height - 1));
    const LD c = std::floor(fx), r = std::floor(fy);
    const LD tx = fx - c, ty = fy - r;
    const int ci = int(c), ri = int(r);
    return (1 - tx) * (1 - ty) * ref_pixel(img, ci, ri) + tx * (1 - ty) * ref_pixel(img, ci + 1, ri) +
           (1 - tx) * ty * ref_pixel(img, ci, ri + 1) + tx * ty * ref_pixel(img, ci + 1, ri + 1);
}

struct RefFrame {
    std::vector<LD> wa, wb, morph, dissolve;
};

RefFrame ref_frame(const Input& in, LD alpha) {
    std::vector<RefLine> la, lb, lt;
    for (const auto& pr : in.lines) {
        const RefLine a{from(pr.a.p), from(pr.a.q)}, b{from(pr.b.p), from(pr.b.q)};
        la.push_back(a);
        lb.push_back(b);
        lt.push_back({a.p + alpha * (b.p - a.p), a.q + alpha * (b.q - a.q)});
    }
    RefFrame f;
    const LD A = in.params.a, B = in.params.b, Pw = in.params.p;
    for (int r = 0; r < in.image_a.height; ++r)
        for (int c = 0; c < in.image_a.width; ++c) {
            const P x{c + LD(0.5), r + LD(0.5)};
            const LD va = ref_sample(in.image_a, ref_source(lt, la, A, B, Pw, x));
            const LD vb = ref_sample(in.image_b, ref_source(lt, lb, A, B, Pw, x));
            f.wa.push_back(va);
            f.wb.push_back(vb);
            f.morph.push_back((1 - alpha) * va + alpha * vb);
            f.dissolve.push_back((1 - alpha) * ref_pixel(in.image_a, c, r) +
                                 alpha * ref_pixel(in.image_b, c, r));
        }
    return f;
}

Image random_image(cg::Rng& rng, int w, int h) {
    Image img;
    img.width = w;
    img.height = h;
    const bool integers = rng.chance(0.5);
    for (int k = 0; k < w * h; ++k)
        img.v.push_back(integers ? double(rng.integer(0, 255)) : rng.uniform(-50, 300));
    return img;
}

glm::dvec2 random_point(cg::Rng& rng, int w, int h) {
    return {rng.uniform(-2, w + 2), rng.uniform(-2, h + 2)};
}

ImageMorph::Line random_line(cg::Rng& rng, int w, int h) {
    ImageMorph::Line l;
    do {
        l.p = random_point(rng, w, h);
        l.q = random_point(rng, w, h);
    } while (std::hypot(l.q.x - l.p.x, l.q.y - l.p.y) < 0.5);
    return l;
}

Input random_case(cg::Rng& rng) {
    Input in;
    const int w = int(rng.integer(1, 8)), h = int(rng.integer(1, 8));
    in.image_a = random_image(rng, w, h);
    in.image_b = random_image(rng, w, h);
    const int m = int(rng.integer(1, 4));
    for (int i = 0; i < m; ++i) {
        ImageMorph::Pair pr{random_line(rng, w, h), random_line(rng, w, h)};
        if (rng.chance(0.15)) pr.b = pr.a;  // a line that stays put
        in.lines.push_back(pr);
    }
    in.params = {rng.uniform(0.01, 2), rng.chance(0.3) ? 2.0 : rng.uniform(0, 3),
                 rng.chance(0.3) ? 0.5 : rng.uniform(0, 1.5)};
    const int frames = int(rng.integer(1, 3));
    for (int k = 0; k < frames; ++k)
        in.alphas.push_back(rng.chance(0.2) ? double(rng.integer(0, 1)) : rng.uniform(0, 1));
    return in;
}

Input worked() {
    Input in;
    in.image_a = {4, 4, {0, 200, 0, 0, 0, 200, 0, 0, 0, 200, 0, 0, 0, 200, 0, 0}};
    in.image_b = {4, 4, {0, 0, 0, 100, 0, 0, 0, 100, 0, 0, 0, 100, 0, 0, 0, 100}};
    in.lines = {{{{1.5, 0.5}, {1.5, 3.5}}, {{3.5, 0.5}, {3.5, 3.5}}}};
    in.alphas = {0, 0.5, 1};
    in.focus_x = 2;
    in.focus_y = 1;
    return in;
}

std::vector<double> row(const Image& img, int r) {
    return {img.v.begin() + r * img.width, img.v.begin() + (r + 1) * img.width};
}

}  // namespace

TEST_CASE("image-morph: the exam-style example worked by hand", "[animation][image-morph]") {
    const auto res = ImageMorph::compute(worked());
    REQUIRE(res.frames.size() == 3);
    // α = ½: the line sits half way, x = 2.5. X = (2.5, 1.5): u = (0, 1)·(0, 3)/9 = 1/3,
    // v = (0, 1)·(−3, 0)/3 = 0; X'_A = (1.5, 0.5) + ⅓ (0, 3) = (1.5, 1.5), X'_B = (3.5, 1.5).
    const auto f = ImageMorph::focus(ImageMorph::resolve(worked()), res.frames[1], 2, 1);
    CHECK(f.alpha == 0.5);
    REQUIRE(f.a.terms.size() == 1);
    CHECK(f.a.terms[0].u == Approx(1.0 / 3).margin(1e-15));
    CHECK(f.a.terms[0].v == Approx(0).margin(1e-15));
    CHECK(f.a.terms[0].dist == Approx(0).margin(1e-15));
    CHECK(f.a.source.x == Approx(1.5).margin(1e-15));
    CHECK(f.a.source.y == Approx(1.5).margin(1e-15));
    CHECK(f.b.source.x == Approx(3.5).margin(1e-15));
    CHECK(f.b.source.y == Approx(1.5).margin(1e-15));
    CHECK(f.a.value == Approx(200).margin(1e-12));
    CHECK(f.b.value == Approx(100).margin(1e-12));
    CHECK(f.morph == Approx(150).margin(1e-12));
    CHECK(f.dissolve == 0);
    // Every row of the half-way morph: the column has moved one pixel right, whole; at the
    // right border B is clamped (X'_B = 4.5 reads column 3), so the last pixel is ½·0 + ½·100.
    const auto& mid = res.frames[1];
    for (int r = 0; r < 4; ++r) {
        const auto m = row(mid.morph, r);
        CHECK(m[0] == Approx(0).margin(1e-12));
        CHECK(m[1] == Approx(0).margin(1e-12));
        CHECK(m[2] == Approx(150).margin(1e-12));
        CHECK(m[3] == Approx(50).margin(1e-12));
        CHECK(row(mid.dissolve, r) == std::vector<double>{0, 100, 0, 50});  // two ghosts
    }
    // The ends are the images themselves, bit for bit.
    CHECK(res.frames[0].morph == worked().image_a);
    CHECK(res.frames[2].morph == worked().image_b);
    CHECK(res.focus.alpha == 1);  // the reported pixel is in the last frame
    CHECK(res.focus.morph == 0);
    // Per row |0 − 0| + |0 − 100| + |150 − 0| + |50 − 50| over 4 pixels; the ends are 0.
    CHECK(ImageMorph::difference(res.frames[1]) == Approx(62.5).margin(1e-9));
    CHECK(ImageMorph::difference(res.frames[0]) == 0);
    CHECK(res.difference == Approx(62.5).margin(1e-9));
}

TEST_CASE("image-morph: 2,000 random cases against a long-double field warp",
          "[animation][image-morph]") {
    cg::Rng rng(2026);
    const std::size_t n = cg::test::sweep(2000);
    std::size_t pixels = 0, stay = 0;
    for (std::size_t trial = 0; trial < n; ++trial) {
        CAPTURE(trial);
        const Input in = random_case(rng);
        for (const auto& pr : in.lines) stay += pr.a == pr.b;
        const auto res = ImageMorph::compute(in);
        REQUIRE(res.frames.size() == in.alphas.size());
        LD lo = 1e300, hi = -1e300;
        for (const Image* img : {&in.image_a, &in.image_b})
            for (double g : img->v) lo = std::min<LD>(lo, g), hi = std::max<LD>(hi, g);
        const LD tol = 1e-9L * std::max<LD>(1, hi - lo);
        for (std::size_t k = 0; k < in.alphas.size(); ++k) {
            const auto& f = res.frames[k];
            const RefFrame ref = ref_frame(in, in.alphas[k]);
            for (std::size_t q = 0; q < ref.morph.size(); ++q) {
                CAPTURE(k, q);
                REQUIRE(std::fabs(LD(f.warped_a.v[q]) - ref.wa[q]) <= tol);
                REQUIRE(std::fabs(LD(f.warped_b.v[q]) - ref.wb[q]) <= tol);
                REQUIRE(std::fabs(LD(f.morph.v[q]) - ref.morph[q]) <= tol);
                REQUIRE(std::fabs(LD(f.dissolve.v[q]) - ref.dissolve[q]) <= tol);
                ++pixels;
            }
        }
        // The reported pixel: every line's u and v against the reference.
        const Input res_in = ImageMorph::resolve(in);
        const auto& fc = res.focus;
        const double al = in.alphas.back();
        for (std::size_t i = 0; i < in.lines.size(); ++i) {
            const auto& t = fc.a.terms[i];
            const P p = from(in.lines[i].a.p) + LD(al) * (from(in.lines[i].b.p) - from(in.lines[i].a.p));
            const P q = from(in.lines[i].a.q) + LD(al) * (from(in.lines[i].b.q) - from(in.lines[i].a.q));
            const P e = q - p, x{res_in.focus_x + LD(0.5), res_in.focus_y + LD(0.5)};
            if (norm(e) < 1e-3L) continue;
            REQUIRE(t.used);
            const LD u = dot(x - p, e) / dot(e, e), v = dot(x - p, P{-e.y, e.x}) / norm(e);
            CHECK(std::fabs(t.u - u) <= 1e-9L * std::max<LD>(1, std::fabs(u)));
            CHECK(std::fabs(t.v - v) <= 1e-9L * std::max<LD>(1, std::fabs(v)));
        }
    }
    CHECK(pixels > n * 20);
    CHECK(stay > n / 20);
}

TEST_CASE("image-morph: α = 0 gives A and α = 1 gives B, exactly", "[animation][image-morph]") {
    cg::Rng rng(5);
    for (std::size_t trial = 0; trial < cg::test::sweep(500); ++trial) {
        CAPTURE(trial);
        Input in = random_case(rng);
        in.alphas = {0, 1};
        const auto res = ImageMorph::compute(in);
        CHECK(res.frames[0].morph == in.image_a);
        CHECK(res.frames[0].warped_a == in.image_a);
        CHECK(res.frames[1].morph == in.image_b);
        CHECK(res.frames[1].warped_b == in.image_b);
    }
}

TEST_CASE("image-morph: the same lines in A and B give exactly the plain cross-dissolve",
          "[animation][image-morph]") {
    cg::Rng rng(6);
    for (std::size_t trial = 0; trial < cg::test::sweep(500); ++trial) {
        CAPTURE(trial);
        Input in = random_case(rng);
        for (auto& pr : in.lines) pr.b = pr.a;
        const auto res = ImageMorph::compute(in);
        for (const auto& f : res.frames) {
            CHECK(f.morph == f.dissolve);
            CHECK(f.warped_a == in.image_a);
            CHECK(f.warped_b == in.image_b);
        }
        CHECK(res.difference == 0);
    }
}

TEST_CASE("image-morph: a translated line pair warps by that translation",
          "[animation][image-morph]") {
    cg::Rng rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        CAPTURE(trial);
        Input in;
        const int n = int(rng.integer(6, 12));
        in.image_a = random_image(rng, n, n);
        in.image_b = random_image(rng, n, n);
        const glm::dvec2 t{double(2 * rng.integer(-2, 2)), double(2 * rng.integer(-2, 2))};
        const auto line = random_line(rng, n, n);
        in.lines = {{line, {line.p + t, line.q + t}}};
        in.params = {rng.uniform(0.01, 2), rng.uniform(0, 3), rng.uniform(0, 1.5)};
        in.alphas = {0.5, 1};
        const auto res = ImageMorph::compute(in);
        // Half way, A is moved by t/2 and B back by t/2; at α = 1, A by the whole t.
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const int ah = c - int(t.x) / 2, bh = r - int(t.y) / 2;
                const int bc = c + int(t.x) / 2, br = r + int(t.y) / 2;
                const int ac = c - int(t.x), ar = r - int(t.y);
                if (ah >= 0 && ah < n && bh >= 0 && bh < n)
                    CHECK(res.frames[0].warped_a.at(c, r) ==
                          Approx(in.image_a.at(ah, bh)).margin(1e-9));
                if (bc >= 0 && bc < n && br >= 0 && br < n)
                    CHECK(res.frames[0].warped_b.at(c, r) ==
                          Approx(in.image_b.at(bc, br)).margin(1e-9));
                if (ac >= 0 && ac < n && ar >= 0 && ar < n)
                    CHECK(res.frames[1].warped_a.at(c, r) ==
                          Approx(in.image_a.at(ac, ar)).margin(1e-9));
            }
    }
}

TEST_CASE("image-morph: opposite lines meet half way and are left out of that frame",
          "[animation][image-morph]") {
    Input in = worked();
    in.lines = {{{{1.5, 0.5}, {1.5, 3.5}}, {{1.5, 3.5}, {1.5, 0.5}}}};
    in.alphas = {0.5};
    const auto res = ImageMorph::compute(in);
    REQUIRE(res.focus.a.terms.size() == 1);
    CHECK_FALSE(res.focus.a.terms[0].used);
    CHECK(res.focus.a.source == glm::dvec2(2.5, 1.5));  // no line: X itself
    CHECK(res.frames[0].morph == res.frames[0].dissolve);
    // A second line that keeps its length carries the warp alone.
    in.lines.push_back({{{0.5, 0.5}, {3.5, 0.5}}, {{0.5, 1.5}, {3.5, 1.5}}});
    const auto two = ImageMorph::compute(in);
    CHECK(two.focus.a.terms[1].used);
    CHECK(two.focus.a.source.y == Approx(1.0).margin(1e-12));
}

TEST_CASE("image-morph: the state machine gives what compute gives, through the registry too",
          "[animation][image-morph]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 200; ++trial) {
        CAPTURE(trial);
        const Input in = random_case(rng);
        const auto traced = cg::test::run_traced<ImageMorph>(in);
        const auto plain = ImageMorph::compute(in);
        CHECK(traced.result == plain);
        CHECK(cg::run_to_end<ImageMorph>(ImageMorph::start(in)) == plain);
        const auto ev = cg::test::events(traced);
        REQUIRE(ev.size() == in.alphas.size() * std::size_t(in.image_a.height + 1));
        CHECK(ev.back() == "frame");
        CHECK(std::count(ev.begin(), ev.end(), "frame") == std::ptrdiff_t(in.alphas.size()));
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("image-morph", p.input);
        CHECK(j["frames"].size() >= 1);
    }
}

TEST_CASE("image-morph: determinism and replay", "[animation][image-morph]") {
    const auto& a = cg::test::algorithm("image-morph");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 5);
    }
    CHECK(cg::test::trace(a, a.example()) == cg::test::trace(a, a.example()));
}

TEST_CASE("image-morph: the lesson's presets do what the lesson says", "[animation][image-morph]") {
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const Input in = cg::test::input_of<ImageMorph>("image-morph", p.input);
        const auto res = ImageMorph::compute(in);
        if (p.name.find("same lines") != std::string::npos) {
            CHECK(res.difference == 0);  // the plain dissolve, exactly
        } else {
            CHECK(res.difference > 1);  // the warp visibly changes the picture
        }
        if (p.name.find("bar turns") != std::string::npos) {
            // Half way the interpolated line runs diagonally and is shorter: 18/√2 ≈ 12.7.
            const auto& mid = res.frames[2];
            REQUIRE(mid.alpha == 0.5);
            const auto e = mid.lines[0].q - mid.lines[0].p;
            CHECK(std::hypot(e.x, e.y) == Approx(18 / std::sqrt(2.0)).epsilon(1e-12));
            // The morph's centre pixel is bright (the bar, turned), the dissolve's is too (both
            // shapes cross there), but off the diagonal the dissolve has the ghosts: half grey.
            CHECK(mid.morph.at(12, 12) == Approx(255).margin(1e-9));
            CHECK(mid.dissolve.at(4, 12) == Approx(127.5).margin(1e-9));
        }
    }
}

TEST_CASE("image-morph: bad input names the field and the reason", "[animation][image-morph]") {
    const std::string ok = R"("image_a": [[0, 1], [2, 3]], "image_b": [[4, 5], [6, 7]])";
    const std::string line = R"("lines": [{"a": [[0, 0], [1, 0]], "b": [[0, 1], [1, 1]]}])";
    CHECK(err("{" + ok + "," + line + "}") == "(accepted)");
    CHECK(err("{" + line + "}").find("image_a") == 0);
    CHECK(err("{" + ok + "}").find("lines") == 0);
    CHECK(err("{" + ok + R"(, "lines": []})").find("lines: must have at least one") == 0);
    CHECK(err("{" + ok + R"(, "lines": [{"a": [[1, 1], [1, 1]], "b": [[0, 1], [1, 1]]}]})")
              .find("lines[0].a: is degenerate") == 0);
    CHECK(err("{" + ok + R"(, "lines": [{"a": [[0, 0], [1, 0]], "b": [[2, 2], [2, 2]]}]})")
              .find("lines[0].b: is degenerate") == 0);
    CHECK(err("{" + ok + R"(, "lines": [{"a": [[0, 0], [1, 0, 3]], "b": [[0, 1], [1, 1]]}]})")
              .find("lines[0].a[1]") == 0);
    CHECK(err("{" + ok + R"(, "lines": [{"a": [[0, 0], [1e5, 0]], "b": [[0, 1], [1, 1]]}]})")
              .find("lines[0].a[1]: is too large") == 0);
    CHECK(err(R"({"image_a": [[0, 1], [2]], "image_b": [[4, 5], [6, 7]], )" + line + "}")
              .find("image_a[1]: has 1 pixels, row 0 has 2") == 0);
    CHECK(err(R"({"image_a": [[0, 1], [2, 3]], "image_b": [[4, 5, 6]], )" + line + "}")
              .find("image_b: is 3 × 1; it must be the size of image_a, 2 × 2") == 0);
    CHECK(err(R"({"image_a": [], "image_b": [[4]], )" + line + "}").find("image_a: must be") == 0);
    CHECK(err(R"({"image_a": [[0, "x"]], "image_b": [[4, 5]], )" + line + "}")
              .find("image_a[0][1]: must be a number") == 0);
    CHECK(err(R"({"image_a": [[0, 1e7]], "image_b": [[4, 5]], )" + line + "}")
              .find("image_a[0][1]: is too large") == 0);
    CHECK(err(R"({"image_a": {"pattern": "star", "size": 8}, "image_b": {"pattern": "disc", "size": 8}, )" +
              line + "}")
              .find("image_a.pattern: must be \"disc\"") == 0);
    CHECK(err(R"({"image_a": {"pattern": "disc", "size": 129}, "image_b": {"pattern": "disc", "size": 8}, )" +
              line + "}")
              .find("image_a.size: must be 1 to 128") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "params": {"a": 0}})").find("params.a: must be") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "params": {"b": 5}})").find("params.b: must be") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "params": {"p": -1}})").find("params.p: must be") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "params": {"q": 1}})").find("params") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "alphas": []})").find("alphas: must have at least one") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "alphas": [0.5, 1.5]})").find("alphas[1]: must be from 0 to 1") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "alphas": [0.5], "frames": 3})").find("frames: give either") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "frames": 121})").find("frames: must be 2 to 120") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "frames": 1})").find("frames: must be 2 to 120") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "focus": [2, 0]})").find("focus: x must be a column 0 to 1") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "focus": [0.5, 0]})").find("focus: must be a pixel") == 0);
    CHECK(err("{" + ok + "," + line + R"(, "alphas": [NaN]})").find("not valid JSON") != std::string::npos);
    CHECK(err(R"({"image_a": {"pattern": "disc", "size": 128}, "image_b": {"pattern": "disc", "size": 128}, )" +
              line + R"(, "frames": 20})")
              .find("alphas: 20 frames of 128 × 128 pixels is too many") == 0);
    // 33 line pairs.
    std::string many = R"("lines": [)";
    for (int i = 0; i < 33; ++i) many += std::string(i ? "," : "") + R"({"a": [[0, 0], [1, 0]], "b": [[0, 1], [1, 1]]})";
    CHECK(err("{" + ok + "," + many + "]}").find("lines: has 33 pairs; at most 32") == 0);
}

TEST_CASE("image-morph: exam problems are one pixel through one line pair, by hand",
          "[animation][image-morph][exam]") {
    const auto& a = cg::test::algorithm("image-morph");
    int halves = 0, clamped = 0;
    for (std::uint64_t seed = 0; seed < cg::test::sweep(300); ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<ImageMorph>("image-morph", p.input);
        REQUIRE(in.lines.size() == 1);
        REQUIRE(in.alphas.size() == 1);
        // By hand: the line moves by t, so the interpolated line is the A line moved by α t;
        // X'_A = X − α t, X'_B = X + (1 − α) t.
        const auto& pr = in.lines[0];
        const glm::dvec2 t = pr.b.p - pr.a.p;
        CHECK(pr.b.q - pr.a.q == t);
        const double al = in.alphas[0];
        const glm::dvec2 x{in.focus_x + 0.5, in.focus_y + 0.5};
        const glm::dvec2 p0 = pr.a.p + al * t, e = pr.a.q - pr.a.p;
        const double len = std::hypot(e.x, e.y);
        const double u = ((x - p0).x * e.x + (x - p0).y * e.y) / (len * len);
        const double v = ((x - p0).x * -e.y + (x - p0).y * e.x) / len;
        const glm::dvec2 xa = x - al * t, xb = x + (1 - al) * t;
        const double va = double(ref_sample(in.image_a, from(xa)));
        const double vb = double(ref_sample(in.image_b, from(xb)));
        halves += std::fabs(xa.x - std::floor(xa.x) - 0.5) > 1e-9;
        clamped += xb.x < 0.5 || xb.x > 3.5 || xb.y < 0.5 || xb.y > 3.5;
        CHECK(p.expected["focus/a/terms/0/u"].get<double>() == Approx(u).margin(1e-12));
        CHECK(p.expected["focus/a/terms/0/v"].get<double>() == Approx(v).margin(1e-12));
        const auto ga = p.expected["focus/a/source"].get<std::vector<double>>();
        const auto gb = p.expected["focus/b/source"].get<std::vector<double>>();
        CHECK(ga[0] == Approx(xa.x).margin(1e-12));
        CHECK(ga[1] == Approx(xa.y).margin(1e-12));
        CHECK(gb[0] == Approx(xb.x).margin(1e-12));
        CHECK(gb[1] == Approx(xb.y).margin(1e-12));
        CHECK(p.expected["focus/morph"].get<double>() ==
              Approx((1 - al) * va + al * vb).margin(1e-9));
        CHECK(p.answers == ImageMorph::answer_fields());
        CHECK(p.question.find("α = " + cg::num(al)) != std::string::npos);
    }
    CHECK(halves > 20);
    CHECK(clamped > 20);
}

TEST_CASE("image-morph: the narration and the picture", "[animation][image-morph]") {
    auto s = ImageMorph::start(worked());
    cg::Scene empty;
    ImageMorph::draw(s, empty);
    // Six image panels, titled, nothing on the world's grid.
    REQUIRE(empty.panels.size() == 6);
    CHECK_FALSE(empty.has_2d());
    for (const auto& p : empty.panels) {
        CHECK(p.kind == cg::PanelKind::Image);
        CHECK(p.grids.size() == 1);
        CHECK(p.points.empty());
    }
    CHECK(empty.panels[0].title == "A (its lines)");
    CHECK(empty.focus2.empty());
    // Frame 1 (α = 0) and its summary, then row 0 and row 1 of frame 2 (α = ½).
    cg::StepInfo info;
    for (int k = 0; k < 5 + 2; ++k) ImageMorph::step(s, &info);
    CHECK(info.event == "row");
    CHECK(info.narration.find("Frame 2 of 3 (α = 0.5), row 1") != std::string::npos);
    CHECK(info.narration.find("u = 0.3333") != std::string::npos);
    CHECK(info.narration.find("C = (1 − α)·200 + α·100 = 150") != std::string::npos);
    cg::Scene scene;
    ImageMorph::draw(s, scene);
    REQUIRE(scene.panels.size() == 6);
    // The morph panel: rows 0 and 1 made (the top two rows of the grid), the rest empty.
    const auto& morph = scene.panels[2].grids[0];
    auto grey = [](std::uint32_t c) { return c >> 24 == ((c >> 8) & 0xff); };
    CHECK(grey(morph.rgba[3 * 4 + 2]));    // row 0, column 2: a grey value
    CHECK(!grey(morph.rgba[0 * 4 + 2]));   // row 3 not made yet: tinted, no grey
    // X in the morph, its sources X'_A in A and X'_B in B; the row just made is the focus.
    REQUIRE(scene.panels[2].points.size() == 1);
    CHECK(scene.panels[2].points[0].label == "X");
    REQUIRE(scene.panels[0].points.size() == 1);
    CHECK(scene.panels[0].points[0].label == "X'_A");
    REQUIRE(scene.panels[1].points.size() == 1);
    CHECK(scene.panels[1].points[0].label == "X'_B");
    REQUIRE(scene.focus2.size() == 1);
    CHECK(scene.focus2[0].panel == 2);
    CHECK(scene.focus2[0].lo == glm::dvec2(0, 2));  // row 1 from the top of 4: cells y 2..3
    CHECK(scene.focus2[0].hi == glm::dvec2(4, 3));
    int arrows = 0;
    for (const auto& p : scene.panels)
        for (const auto& g : p.segments) arrows += g.arrow;
    CHECK(arrows == 5);  // A's line, B's line, the interpolated one on three panels
    ImageMorph::step(s, &info);
    ImageMorph::step(s, &info);
    ImageMorph::step(s, &info);
    CHECK(info.event == "frame");
    CHECK(info.narration.find("Frame 2 of 3 done") != std::string::npos);
}
