// Colour spaces: the exam's colour worked by hand; Python's colorsys (3.11) values pasted as
// literals (computed with colorsys, then checked by hand against the formulas) for RGB → HSV,
// RGB → HSL, HSV → RGB and HSL → RGB, and for YIQ the difference colorsys's rounded
// coefficients make; the six primaries and secondaries, black and white exactly; the matrices
// against their exact inverses; round trips through every pair of spaces on 10,000 random
// colours to 1e-12; an independent long-double reference (Foley's i, f, p, q, t for HSV → RGB,
// colorsys's rc/gc/bc form for the hue, the matrices in long double); hue wrapping, greys and
// the gamut; errors naming the field; determinism; exam problems; the picture.
//
// Sections: [helpers] [hand cases] [colorsys] [exact] [matrices] [round trips] [reference]
//           [conventions] [errors] [determinism] [exam] [picture]
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "colour/colour_spaces.hpp"
#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::ColourSpaces;
using glm::dvec3;
using Space = ColourSpaces::Space;
using ld = long double;

namespace {

// ---- [helpers] ------------------------------------------------------------------------------

constexpr Space kAll[] = {Space::Rgb, Space::Cmy, Space::Hsv, Space::Hsl, Space::Xyz, Space::Yiq};

dvec3 one(Space from, Space to, const dvec3& c) {
    return ColourSpaces::convert({from, to, {c}}).colors[0];
}

bool is_hue_space(Space s) {
    return s == Space::Hsv || s == Space::Hsl;
}

double diff(const dvec3& a, const dvec3& b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

// Hues compared on the circle.
double hue_diff(double a, double b) {
    const double d = std::fabs(a - b);
    return std::min(d, 360 - d);
}

cg::test::Traced<ColourSpaces> traced(Space from, Space to, std::vector<dvec3> colors) {
    return cg::test::run_traced<ColourSpaces>({from, to, std::move(colors)});
}

}  // namespace

// ---- [hand cases] ---------------------------------------------------------------------------

TEST_CASE("colour-spaces: (0.3, 0.8, 0.5) worked by hand", "[colour][colour-spaces]") {
    SECTION("to HSV: max G = 0.8, min 0.3, C = 0.5, H = 60·(0.2/0.5 + 2) = 144") {
        const auto t = traced(Space::Rgb, Space::Hsv, {{0.3, 0.8, 0.5}});
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"max-min", "hue", "saturation", "result"});
        CHECK(diff(t.result.colors[0], {144, 0.625, 0.8}) < 1e-13);
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("max = 0.8 (G), min = 0.3, chroma C = max − min = 0.5"));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("max is G: H = 60·((B − R)/C + 2) = 60·((0.5 − 0.3)/0.5 + 2) "
                                   "= 144°"));
        CHECK_THAT(t.steps[2].narration,
                   Catch::Contains("V = max = 0.8, S = C/V = 0.5/0.8 = 0.625"));
        CHECK(t.steps[1].line == 8);
    }
    SECTION("to HSL: L = 0.55, S = 0.5 / (1 − |1.1 − 1|) = 5/9") {
        const auto t = traced(Space::Rgb, Space::Hsl, {{0.3, 0.8, 0.5}});
        CHECK(diff(t.result.colors[0], {144, 5.0 / 9, 0.55}) < 1e-13);
        CHECK_THAT(t.steps[2].narration, Catch::Contains("L = (max + min)/2 = 0.55"));
    }
    SECTION("back from HSV (144, 0.625, 0.8): C = 0.5, H′ = 2.4, X = 0.2, sector 2, m = 0.3") {
        const auto t = traced(Space::Hsv, Space::Rgb, {{144, 0.625, 0.8}});
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"chroma", "sector", "add-m", "result"});
        CHECK(diff(t.result.colors[0], {0.3, 0.8, 0.5}) < 1e-15);
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("C = V·S = 0.8 · 0.625 = 0.5, H′ = H/60 = 2.4, X = C·(1 − |H′ "
                                   "mod 2 − 1|) = 0.2"));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("⌊H′⌋ = 2, the sector from green to cyan: (0, C, X), so (R1, "
                                   "G1, B1) = (0, 0.5, 0.2)"));
        CHECK_THAT(t.steps[2].narration, Catch::Contains("m = V − C = 0.8 − 0.5 = 0.3"));
    }
    SECTION("to CMY, XYZ and YIQ: the complement and the matrices row by row") {
        CHECK(diff(one(Space::Rgb, Space::Cmy, {0.3, 0.8, 0.5}), {0.7, 0.2, 0.5}) < 1e-15);
        // X = 0.4124·0.3 + 0.3576·0.8 + 0.1805·0.5 = 0.12372 + 0.28608 + 0.09025; Y, Z alike.
        CHECK(diff(one(Space::Rgb, Space::Xyz, {0.3, 0.8, 0.5}), {0.50005, 0.67204, 0.5764}) <
              1e-15);
        // Y = 0.0897 + 0.4696 + 0.057; I = 0.1788 − 0.2192 − 0.161; Q = 0.0633 − 0.4184 + 0.156.
        CHECK(diff(one(Space::Rgb, Space::Yiq, {0.3, 0.8, 0.5}), {0.6163, -0.2014, -0.1991}) <
              1e-15);
        const auto t = traced(Space::Rgb, Space::Yiq, {{0.3, 0.8, 0.5}});
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"matrix-row", "matrix-row", "matrix-row", "result"});
        CHECK_THAT(t.steps[0].narration,
                   Catch::Contains("Y = 0.299·0.3 + 0.587·0.8 + 0.114·0.5 = 0.6163"));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("I = 0.596·0.3 − 0.274·0.8 − 0.322·0.5 = −0.2014 (as "
                                   "0.596(R − G) + 0.322(G − B)"));
    }
}

// ---- [colorsys] -----------------------------------------------------------------------------
// Computed with Python 3.11's colorsys (H scaled from [0, 1) to degrees; rgb_to_hls's (h, l, s)
// reordered to [H, S, L]) and pasted; each was checked against the formulas by hand.

TEST_CASE("colour-spaces: RGB to HSV and HSL agree with Python's colorsys",
          "[colour][colour-spaces]") {
    struct Row {
        dvec3 rgb, hsv, hsl, yiq;
    };
    const Row rows[] = {
        {{0.3, 0.8, 0.5},
         {144.0, 0.625, 0.8},
         {144.0, 0.5555555555555556, 0.55},
         {0.617, -0.20299, -0.20012999999999997}},
        {{1, 0, 0}, {0.0, 1.0, 1}, {0.0, 1.0, 0.5}, {0.3, 0.599, 0.21299999999999997}},
        {{0.5, 0.5, 0.5},
         {0.0, 0.0, 0.5},
         {0.0, 0.0, 0.5},
         {0.49999999999999994, 2.6090241078691177e-17, 4.940492459581946e-17}},
        {{0.2, 0.4, 0.9},
         {222.85714285714286, 0.7777777777777777, 0.9},
         {222.85714285714286, 0.7777777777777776, 0.55},
         {0.395, -0.28065, 0.11344999999999998}},
        {{0.9, 0.1, 0.6},
         {322.5, 0.888888888888889, 0.9},
         {322.5, 0.8, 0.5},
         {0.395, 0.31834999999999997, 0.32644999999999996}},
        {{0.25, 0.75, 1.0},
         {199.99999999999997, 0.75, 1.0},
         {199.99999999999997, 1.0, 0.625},
         {0.6275, -0.37992499999999996, -0.028474999999999973}},
        {{0.6, 0.6, 0.2},
         {60.0, 0.6666666666666666, 0.6},
         {60.0, 0.49999999999999994, 0.4},
         {0.556, 0.12867999999999996, -0.12484000000000003}},
        {{0.05, 0.02, 0.01},
         {15.0, 0.7999999999999999, 0.05},
         {15.0, 0.6666666666666666, 0.030000000000000002},
         {0.027899999999999998, 0.021187000000000004, 0.0032690000000000037}},
        {{1, 1, 1},
         {0.0, 0.0, 1},
         {0.0, 0.0, 1.0},
         {0.9999999999999999, 5.2180482157382354e-17, 9.880984919163892e-17}},
        {{0, 0, 0}, {0.0, 0.0, 0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}},
        {{0.7, 0.2, 0.2},
         {0.0, 0.7142857142857143, 0.7},
         {0.0, 0.5555555555555556, 0.44999999999999996},
         {0.35, 0.2995, 0.1065}},
    };
    for (const Row& r : rows) {
        CAPTURE(r.rgb.x, r.rgb.y, r.rgb.z);
        const dvec3 hsv = one(Space::Rgb, Space::Hsv, r.rgb),
                    hsl = one(Space::Rgb, Space::Hsl, r.rgb);
        CHECK(hue_diff(hsv.x, r.hsv.x) < 1e-12);
        CHECK(std::fabs(hsv.y - r.hsv.y) < 1e-15);
        CHECK(hsv.z == r.hsv.z);
        CHECK(hue_diff(hsl.x, r.hsl.x) < 1e-12);
        CHECK(std::fabs(hsl.y - r.hsl.y) < 1e-15);
        CHECK(std::fabs(hsl.z - r.hsl.z) < 1e-15);
        // YIQ: colorsys takes Y = 0.30 R + 0.59 G + 0.11 B and I = 0.74 (R − Y) − 0.27 (B − Y),
        // Q = 0.48 (R − Y) + 0.41 (B − Y); we take the FCC matrix with Y = 0.299 R + 0.587 G +
        // 0.114 B. The two differ by at most 0.004 (a swapped row or sign would show here).
        const dvec3 yiq = one(Space::Rgb, Space::Yiq, r.rgb);
        CHECK(diff(yiq, r.yiq) < 0.004);
    }
}

TEST_CASE("colour-spaces: HSV and HSL to RGB agree with Python's colorsys",
          "[colour][colour-spaces]") {
    struct Row {
        dvec3 in, rgb;
    };
    const Row hsv[] = {
        {{144, 0.625, 0.8}, {0.30000000000000004, 0.8, 0.5000000000000002}},
        {{0, 1, 1}, {1, 0.0, 0.0}},
        {{200, 0.5, 0.6}, {0.3, 0.49999999999999994, 0.6}},
        {{330, 0.8, 0.9}, {0.9, 0.17999999999999997, 0.54}},
        {{45, 0.3, 0.7}, {0.7, 0.6475, 0.48999999999999994}},
        {{270, 1, 0.5}, {0.25, 0.0, 0.5}},
        {{90, 0.2, 0.4}, {0.36000000000000004, 0.4, 0.32000000000000006}},
    };
    const Row hsl[] = {
        // colorsys.hls_to_rgb(H/360, L, S)
        {{144, 0.5555555555555556, 0.55}, {0.30000000000000004, 0.8, 0.5000000000000002}},
        {{0, 1, 0.5}, {1.0, 0.0, 0.0}},
        {{200, 0.5, 0.6}, {0.3999999999999999, 0.6666666666666665, 0.8}},
        {{330, 0.8, 0.3}, {0.54, 0.05999999999999994, 0.3000000000000001}},
        {{45, 0.3, 0.7}, {0.79, 0.745, 0.6099999999999999}},
        {{270, 1, 0.25}, {0.24999999999999978, 0.0, 0.5}},
        {{90, 0.2, 0.4}, {0.4, 0.48, 0.32000000000000006}},
    };
    for (const Row& r : hsv) {
        CAPTURE(r.in.x, r.in.y, r.in.z);
        CHECK(diff(one(Space::Hsv, Space::Rgb, r.in), r.rgb) < 1e-15);
    }
    for (const Row& r : hsl) {
        CAPTURE(r.in.x, r.in.y, r.in.z);
        CHECK(diff(one(Space::Hsl, Space::Rgb, r.in), r.rgb) < 1e-15);
    }
}

// ---- [exact] --------------------------------------------------------------------------------

TEST_CASE("colour-spaces: primaries, secondaries, black and white exactly",
          "[colour][colour-spaces]") {
    struct Row {
        dvec3 rgb;
        double hue;
    };
    const Row rows[] = {{{1, 0, 0}, 0},   {{1, 1, 0}, 60},  {{0, 1, 0}, 120},
                        {{0, 1, 1}, 180}, {{0, 0, 1}, 240}, {{1, 0, 1}, 300}};
    const auto& xyz = ColourSpaces::xyz_from_rgb();
    for (const Row& r : rows) {
        CAPTURE(r.hue);
        CHECK(one(Space::Rgb, Space::Hsv, r.rgb) == dvec3(r.hue, 1, 1));
        CHECK(one(Space::Rgb, Space::Hsl, r.rgb) == dvec3(r.hue, 1, 0.5));
        CHECK(one(Space::Hsv, Space::Rgb, {r.hue, 1, 1}) == r.rgb);
        CHECK(one(Space::Hsl, Space::Rgb, {r.hue, 1, 0.5}) == r.rgb);
        CHECK(one(Space::Rgb, Space::Cmy, r.rgb) == dvec3(1) - r.rgb);
        CHECK(one(Space::Cmy, Space::Rgb, dvec3(1) - r.rgb) == r.rgb);
        // In XYZ each primary is a column of the matrix, each secondary the sum of two.
        const dvec3 expected{glm::dot(xyz[0], r.rgb), glm::dot(xyz[1], r.rgb),
                             glm::dot(xyz[2], r.rgb)};
        CHECK(one(Space::Rgb, Space::Xyz, r.rgb) == expected);
    }
    CHECK(one(Space::Rgb, Space::Xyz, {1, 0, 0}) == dvec3(0.4124, 0.2126, 0.0193));
    CHECK(one(Space::Rgb, Space::Hsv, {0, 0, 0}) == dvec3(0, 0, 0));
    CHECK(one(Space::Rgb, Space::Hsv, {1, 1, 1}) == dvec3(0, 0, 1));
    CHECK(one(Space::Rgb, Space::Hsl, {1, 1, 1}) == dvec3(0, 0, 1));
    CHECK(one(Space::Rgb, Space::Yiq, {1, 1, 1}) == dvec3(1, 0, 0));  // I = Q = 0 exactly
    CHECK(one(Space::Rgb, Space::Yiq, {0.3, 0.3, 0.3}).y == 0);
    CHECK(one(Space::Yiq, Space::Rgb, {0.5, 0, 0}) == dvec3(0.5));
    // D65: white in XYZ is the row sums, (0.9505, 1, 1.089).
    CHECK(diff(one(Space::Rgb, Space::Xyz, {1, 1, 1}), {0.9505, 1, 1.089}) < 1e-15);
}

// ---- [matrices] -----------------------------------------------------------------------------

TEST_CASE("colour-spaces: the inverse matrices are inverses, and near the published ones",
          "[colour][colour-spaces]") {
    auto check = [](const std::array<dvec3, 3>& m, const std::array<dvec3, 3>& inv) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                ld sum = 0;  // (M⁻¹ M)[i][j] in long double
                for (int k = 0; k < 3; ++k) sum += ld(inv[i][k]) * ld(m[k][j]);
                CHECK(std::fabs(sum - (i == j ? 1 : 0)) < 1e-15L);
            }
    };
    check(ColourSpaces::xyz_from_rgb(), ColourSpaces::rgb_from_xyz());
    check(ColourSpaces::yiq_from_rgb(), ColourSpaces::rgb_from_yiq());
    // IEC 61966-2-1's printed inverse, 4 digits.
    const double published[3][3] = {
        {3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            CHECK(std::fabs(ColourSpaces::rgb_from_xyz()[i][j] - published[i][j]) < 6e-5);
    // The FCC inverse as usually printed: R = Y + 0.956 I + 0.621 Q, …
    const double yiq_published[3][3] = {{1, 0.956, 0.621}, {1, -0.272, -0.647}, {1, -1.106, 1.703}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            CHECK(std::fabs(ColourSpaces::rgb_from_yiq()[i][j] - yiq_published[i][j]) < 3e-3);
    // The I and Q rows sum to 0; the Y row to 1.
    const auto& y = ColourSpaces::yiq_from_rgb();
    CHECK(std::fabs(y[0].x + y[0].y + y[0].z - 1) < 1e-15);
    CHECK(std::fabs(y[1].x + y[1].y + y[1].z) < 1e-15);
    CHECK(std::fabs(y[2].x + y[2].y + y[2].z) < 1e-15);
}

// ---- [round trips] --------------------------------------------------------------------------

TEST_CASE("colour-spaces: 10,000 random colours round-trip through every pair to 1e-12",
          "[colour][colour-spaces]") {
    double worst = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        dvec3 rgb{rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
        switch (trial % 8) {  // greys, cube faces and edges, near-greys
            case 0:
                rgb = dvec3(rgb.x);
                break;
            case 1:
                rgb[trial % 3] = trial % 2 ? 1.0 : 0.0;
                break;
            case 2:
                rgb[trial % 3] = 1, rgb[(trial + 1) % 3] = 0;
                break;
            case 3:
                rgb = dvec3(rgb.x) + dvec3(1e-9, -1e-9, 0) * double(rgb.x > 0.1 && rgb.x < 0.9);
                break;
            default:
                break;
        }
        CAPTURE(trial, rgb.x, rgb.y, rgb.z);
        for (Space a : kAll) {
            const dvec3 in_a = one(Space::Rgb, a, rgb);
            for (Space b : kAll) {
                CAPTURE(ColourSpaces::name(a), ColourSpaces::name(b));
                const ColourSpaces::Input in{a, b, {in_a}};
                const auto r = cg::run_to_end<ColourSpaces>(ColourSpaces::start(in));
                REQUIRE(ColourSpaces::convert(in) == r);
                REQUIRE_FALSE(r.out_of_gamut[0]);
                const dvec3 back = one(b, Space::Rgb, r.colors[0]);
                const double d = diff(back, rgb);
                worst = std::max(worst, d);
                REQUIRE(d <= 1e-12);
                if (b == Space::Hsv || b == Space::Hsl) {
                    REQUIRE(r.colors[0].x >= 0);
                    REQUIRE(r.colors[0].x < 360);
                }
            }
        }
    }
    CHECK(worst < 1e-14);
}

// ---- [reference] ----------------------------------------------------------------------------
// An independent long-double implementation: HSV → RGB by Foley's i, f, p, q, t; the hue by
// colorsys's rc, gc, bc form; HSL → RGB by colorsys's m1, m2 form; the matrices by plain
// dot products in long double.

namespace {

struct L3 {
    ld v[3];
};

L3 ref_hsv_to_rgb(ld h, ld s, ld v) {
    if (s == 0) return {{v, v, v}};
    h = std::fmod(h, 360.0L);
    if (h < 0) h += 360;
    const ld hh = h / 60;
    const int i = static_cast<int>(std::floor(hh)) % 6;
    const ld f = hh - std::floor(hh);
    const ld p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (i) {
        case 0:
            return {{v, t, p}};
        case 1:
            return {{q, v, p}};
        case 2:
            return {{p, v, t}};
        case 3:
            return {{p, q, v}};
        case 4:
            return {{t, p, v}};
        default:
            return {{v, p, q}};
    }
}

ld ref_v(ld m1, ld m2, ld hue) {
    hue = hue - std::floor(hue);
    if (hue < 1.0L / 6) return m1 + (m2 - m1) * hue * 6;
    if (hue < 0.5L) return m2;
    if (hue < 2.0L / 3) return m1 + (m2 - m1) * (2.0L / 3 - hue) * 6;
    return m1;
}

L3 ref_hsl_to_rgb(ld h, ld s, ld l) {
    if (s == 0) return {{l, l, l}};
    const ld m2 = l <= 0.5L ? l * (1 + s) : l + s - l * s, m1 = 2 * l - m2;
    h /= 360;
    return {{ref_v(m1, m2, h + 1.0L / 3), ref_v(m1, m2, h), ref_v(m1, m2, h - 1.0L / 3)}};
}

// [H in degrees, S, V or L] by colorsys's method.
L3 ref_rgb_to_hue(ld r, ld g, ld b, bool hsl) {
    const ld mx = std::max({r, g, b}), mn = std::min({r, g, b}), c = mx - mn;
    ld h = 0;
    if (c > 0) {
        const ld rc = (mx - r) / c, gc = (mx - g) / c, bc = (mx - b) / c;
        h = r == mx ? bc - gc : g == mx ? 2 + rc - bc : 4 + gc - rc;
        h = h / 6 - std::floor(h / 6);
    }
    if (!hsl) return {{360 * h, mx > 0 ? c / mx : 0, mx}};
    const ld l = (mx + mn) / 2;
    const ld s = c == 0 ? 0 : l <= 0.5L ? c / (mx + mn) : c / (2 - mx - mn);
    return {{360 * h, s, l}};
}

}  // namespace

TEST_CASE("colour-spaces: 10,000 random colours agree with a long-double reference",
          "[colour][colour-spaces]") {
    for (int trial = 0; trial < 10000; ++trial) {
        cg::Rng rng(trial);
        CAPTURE(trial);
        const dvec3 rgb{rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
        for (bool hsl : {false, true}) {
            const Space space = hsl ? Space::Hsl : Space::Hsv;
            const dvec3 got = one(Space::Rgb, space, rgb);
            const L3 ref = ref_rgb_to_hue(rgb.x, rgb.y, rgb.z, hsl);
            const double chroma = std::max({rgb.x, rgb.y, rgb.z}) - std::min({rgb.x, rgb.y, rgb.z});
            // The hue's error grows like 1/C: compare it scaled.
            REQUIRE(hue_diff(got.x, double(ref.v[0])) * chroma <= 1e-12);
            REQUIRE(std::fabs(got.y - ref.v[1]) <= 1e-12L);
            REQUIRE(std::fabs(got.z - ref.v[2]) <= 1e-15L);
            // And back from random HSV/HSL inputs, by the other method.
            const dvec3 h{rng.uniform(-720, 720), rng.uniform(0, 1), rng.uniform(0, 1)};
            const dvec3 back = one(space, Space::Rgb, h);
            const L3 r2 = hsl ? ref_hsl_to_rgb(h.x, h.y, h.z) : ref_hsv_to_rgb(h.x, h.y, h.z);
            for (int i = 0; i < 3; ++i) REQUIRE(std::fabs(back[i] - r2.v[i]) <= 1e-12L);
        }
        for (Space lin : {Space::Xyz, Space::Yiq}) {
            const auto& m =
                lin == Space::Xyz ? ColourSpaces::xyz_from_rgb() : ColourSpaces::yiq_from_rgb();
            const dvec3 got = one(Space::Rgb, lin, rgb);
            for (int i = 0; i < 3; ++i) {
                const ld ref = ld(m[i].x) * rgb.x + ld(m[i].y) * rgb.y + ld(m[i].z) * rgb.z;
                REQUIRE(std::fabs(got[i] - ref) <= 1e-15L);
            }
        }
    }
}

// ---- [conventions] --------------------------------------------------------------------------

TEST_CASE(
    "colour-spaces: hues wrap, greys have H = 0 and S = 0, XYZ outside the cube is "
    "clamped and reported",
    "[colour][colour-spaces]") {
    CHECK(one(Space::Hsv, Space::Rgb, {-30, 0.5, 0.8}) ==
          one(Space::Hsv, Space::Rgb, {330, 0.5, 0.8}));
    CHECK(one(Space::Hsv, Space::Rgb, {360, 1, 1}) == dvec3(1, 0, 0));
    CHECK(one(Space::Hsl, Space::Rgb, {720 + 120, 1, 0.5}) == dvec3(0, 1, 0));
    CHECK(one(Space::Hsv, Space::Hsv, {400, 0.5, 0.5}).x == Approx(40));
    const auto t = traced(Space::Hsv, Space::Rgb, {{-30, 0.5, 0.8}});
    CHECK_THAT(t.steps[0].narration, Catch::Contains("(H = −30° is 330° modulo 360)"));
    // A hue just below 0 lands on 0, never 360.
    const dvec3 nearly_red = one(Space::Rgb, Space::Hsv, {1, 0, 1e-17});
    CHECK(nearly_red.x == 0);
    // Greys: any hue and saturation give the grey, and come back as H = 0, S = 0.
    CHECK(one(Space::Hsv, Space::Hsv, {200, 0, 0.4}) == dvec3(0, 0, 0.4));
    CHECK(one(Space::Hsl, Space::Hsl, {200, 0.7, 1}) == dvec3(0, 0, 1));
    const auto grey = traced(Space::Rgb, Space::Hsl, {{0.4, 0.4, 0.4}});
    CHECK(grey.steps[1].event == "grey");
    // XYZ outside the sRGB gamut: a saturated spectral green.
    const auto g = traced(Space::Xyz, Space::Rgb, {{0.2, 0.6, 0.1}});
    CHECK(cg::test::events(g) == std::vector<std::string>{"matrix-row", "matrix-row", "matrix-row",
                                                          "out-of-gamut", "result"});
    CHECK(g.result.out_of_gamut[0]);
    const dvec3 c = g.result.colors[0];
    CHECK((c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z == 0));
    CHECK_THAT(g.steps[3].narration, Catch::Contains("this colour is out of the RGB gamut"));
    // D65 white in XYZ is RGB white, in the gamut (within rounding).
    const auto w = traced(Space::Xyz, Space::Hsv, {{0.9505, 1, 1.089}});
    CHECK(w.steps[3].event == "in-gamut");
    CHECK_FALSE(w.result.out_of_gamut[0]);
    CHECK(diff(w.result.rgb[0], dvec3(1)) < 1e-15);
}

// ---- [errors] -------------------------------------------------------------------------------

TEST_CASE("colour-spaces: bad input names the field", "[colour][colour-spaces]") {
    using cg::test::error_of;
    const std::string id = "colour-spaces";
    CHECK(error_of(id, R"({"from": "rgb", "to": "hsv", "colors": [[0.3, 0.8, 0.5]]})") ==
          "(accepted)");
    CHECK(error_of(id, R"({"from": "lab", "to": "hsv", "colors": [[0.3, 0.8, 0.5]]})") ==
          "from: must be one of rgb, cmy, hsv, hsl, xyz, yiq (lower case), got a string (\"lab\")");
    CHECK(error_of(id, R"({"from": "rgb", "to": 3, "colors": [[0.3, 0.8, 0.5]]})") ==
          "to: must be a colour space (rgb, cmy, hsv, hsl, xyz or yiq), got 3");
    CHECK(error_of(id, R"({"from": "rgb", "to": "hsv", "colors": [[0.3, 1.8, 0.5]]})") ==
          "colors[0][1]: RGB's G must be in [0, 1] (got 1.8)");
    CHECK(error_of(id, R"({"from": "hsv", "to": "rgb", "colors": [[400, 0.5, -0.1]]})") ==
          "colors[0][2]: HSV's V must be in [0, 1] (got −0.1)");
    CHECK(error_of(id, R"({"from": "hsl", "to": "rgb", "colors": [[0, 0, 0], [10, 2, 0.5]]})") ==
          "colors[1][1]: HSL's S must be in [0, 1] (got 2)");
    CHECK(error_of(id, R"({"from": "cmy", "to": "rgb", "colors": [[0, -1, 0]]})") ==
          "colors[0][1]: CMY's M must be in [0, 1] (got −1)");
    CHECK(error_of(id, R"({"from": "xyz", "to": "rgb", "colors": [[0, 2e6, 0]]})") ==
          "colors[0][1]: XYZ's Y must lie within ±1e6 (got 2000000)");
    CHECK(error_of(id, R"({"from": "rgb", "to": "hsv", "colors": []})") ==
          "colors: must list at least one colour [a, b, c]");
    CHECK(error_of(id, R"({"from": "hsv", "to": "rgb", "colors": [[0.3, 0.8]]})") ==
          "colors[0]: must be a colour of three numbers [H, S, V], got an array ([0.3,0.8])");
    CHECK(error_of(id, R"({"from": "rgb", "to": "hsv", "colors": [[0.3, "a", 0.5]]})") ==
          "colors[0][1]: must be a number, got a string (\"a\")");
    CHECK(error_of(id, R"({"from": "rgb", "to": "hsv", "colours": [[0.3, 0.8, 0.5]]})") ==
          "colours: is not a known field (expected: from, to, colors)");
    std::string many = R"({"from": "rgb", "to": "hsv", "colors": [)";
    for (int k = 0; k < 1001; ++k) many += std::string(k ? "," : "") + "[0, 0, 0]";
    CHECK(error_of(id, many + "]}") == "colors: must list at most 1000 colours (got 1001)");
    CHECK(error_of(id, R"({"from": "hsv", "to": "rgb", "colors": [[1e300, 0.5, 0.5]]})") ==
          "(accepted)");
    CHECK_THROWS_WITH(
        ColourSpaces::start(
            {Space::Rgb, Space::Hsv, {{0, std::numeric_limits<double>::infinity(), 0}}}),
        "colors[0][1]: must be a finite number (got inf)");
}

// ---- [determinism] --------------------------------------------------------------------------

TEST_CASE("colour-spaces: traces are deterministic and stepping back reproduces them",
          "[colour][colour-spaces]") {
    const cg::Algorithm& a = cg::test::algorithm("colour-spaces");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* lesson = lessons.for_algorithm("colour-spaces");
    REQUIRE(lesson);
    CHECK(lesson->presets.size() >= 6);
    for (const auto& p : lesson->presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, 2);
    }
    const cg::json r = cg::test::result_of("colour-spaces", a.example());
    CHECK(r["colors"][1] == cg::json::array({0.0, 1.0, 1.0}));
    CHECK(r["colors"][2] == cg::json::array({0.0, 0.0, 0.5}));
    CHECK(r["out_of_gamut"] == cg::json::array({false, false, false}));
    CHECK(r["rgb"][0] == cg::json::array({0.3, 0.8, 0.5}));
}

// ---- [exam] ---------------------------------------------------------------------------------

TEST_CASE("colour-spaces: exam problems are simple numbers with answers that convert back",
          "[colour][colour-spaces][exam]") {
    int directions[6][6] = {};
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const ColourSpaces::Input in = ColourSpaces::exam_input(rng);
        ++directions[static_cast<int>(in.from)][static_cast<int>(in.to)];
        const auto r = ColourSpaces::convert(in);
        for (std::size_t k = 0; k < in.colors.size(); ++k) {
            // Inputs in tenths or quarters (hues in multiples of 15°).
            for (int i = 0; i < 3; ++i) {
                const double v =
                    in.colors[k][i] * (is_hue_space(in.from) && i == 0 ? 1.0 / 15 : 20);
                REQUIRE(std::fabs(v - std::round(v)) < 1e-9);
            }
            REQUIRE_FALSE(r.out_of_gamut[k]);
            const dvec3 back = one(in.to, in.from, r.colors[k]);
            if (is_hue_space(in.from))
                REQUIRE(diff(one(in.from, Space::Rgb, back),
                             one(in.from, Space::Rgb, in.colors[k])) < 1e-12);
            else
                REQUIRE(diff(back, in.colors[k]) < 1e-12);
        }
        CHECK_THAT(ColourSpaces::question(in), Catch::StartsWith("Convert "));
    }
    CHECK(directions[0][2] > 50);  // RGB → HSV, the classic
    CHECK(directions[2][0] > 50);  // and back
    CHECK(directions[0][3] > 30);
    CHECK(directions[3][0] > 30);
    CHECK(directions[0][5] > 30);
    CHECK(directions[0][4] > 30);
    CHECK(directions[0][1] + directions[1][0] > 30);
}

// ---- [picture] ------------------------------------------------------------------------------

TEST_CASE("colour-spaces: the picture: the hexcone with the colour's point, and the RGB cube",
          "[colour][colour-spaces]") {
    auto s = ColourSpaces::start({Space::Rgb, Space::Hsv, {{0.3, 0.8, 0.5}, {1, 0, 0}}});
    cg::Scene scene;
    ColourSpaces::draw(s, scene);
    CHECK(scene.has_3d());
    CHECK_FALSE(scene.has_2d());
    CHECK(scene.faces3.size() == 12);  // the top hexagon's 6 wedges and the 6 sides
    // The colour's point in the cone and the cube, in its own colour (0.3, 0.8, 0.5).
    int own = 0;
    for (const auto& p : scene.points3) own += p.style.rgba == 0x4dcc80ffu;
    CHECK(own == 2);
    ColourSpaces::step(s, nullptr);  // max-min
    ColourSpaces::step(s, nullptr);  // hue: the sector 120°–180° stands out
    scene.clear();
    ColourSpaces::draw(s, scene);
    int outlined = 0;
    for (const auto& f : scene.faces3) outlined += f.outline;
    CHECK(outlined == 1);
    CHECK(scene.faces3[4].outline);  // the wedge after green (index 2: two faces per wedge)
    // Each solid labels the colour once, in its own space: before the result only the cube
    // (RGB); at the end the cone says HSV and the cube RGB, in the step's orange.
    auto labelled = [&](const std::string& prefix) {
        int n = 0;
        for (const auto& l : scene.labels3)
            n += l.text.rfind(prefix, 0) == 0 && l.style.role == cg::Role::Active;
        return n;
    };
    CHECK(labelled("RGB (0.3, 0.8, 0.5)") == 1);
    CHECK(labelled("HSV") == 0);
    while (!ColourSpaces::done(s)) ColourSpaces::step(s, nullptr);
    scene.clear();
    ColourSpaces::draw(s, scene);
    CHECK(labelled("HSV (0, 1, 1)") == 1);  // the last colour, red
    CHECK(labelled("RGB (1, 0, 0)") == 1);
    CHECK(scene.focus3.size() == 1);
    // HSL: the double hexcone (the sides up to white too).
    auto h = ColourSpaces::start({Space::Hsl, Space::Rgb, {{144, 0.5, 0.5}}});
    scene.clear();
    ColourSpaces::draw(h, scene);
    CHECK(scene.faces3.size() == 18);
}
