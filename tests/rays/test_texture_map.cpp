// Texture mapping: the globe worked by hand and hand cases for every parametrisation, wrap and
// filter; 6 × 2,000 random points on transformed quadrics against (u, v) from atan2/acos in long
// double, the partials against finite differences of P(u, v); bilinear weights summing to 1 and
// reproducing a linear texture exactly; mip levels equal to brute-force box averages and the
// trilinear colour against the reference; the state machine bit for bit against the plain
// function; image files (rows turned over, missing and unreadable files named); errors; exam
// problems; determinism and the picture.
#include <stb/stb_image_write.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <set>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "rays/texture_draw.hpp"
#include "rays/texture_json.hpp"
#include "rays/texture_map.hpp"
#include "rays/texture_reference.hpp"
#include "support/process.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::TextureMap;
using glm::dvec2;
using glm::dvec3;
namespace t = cg::test;

namespace {

const cg::Algorithm& algo() {
    return cg::test::algorithm("texture-map");
}

TextureMap::Input input_of(const cg::json& j) {
    return cg::test::input_of<TextureMap>("texture-map", j);
}

cg::json run(const std::string& text) {
    return cg::test::result_of("texture-map", text);
}

std::string error_of(const std::string& text) {
    return cg::test::error_of("texture-map", text);
}

bool near(const cg::json& j, std::vector<double> want, double tol = 1e-12) {
    if (!j.is_array() || j.size() != want.size()) return false;
    for (std::size_t i = 0; i < want.size(); ++i)
        if (std::fabs(j[i].get<double>() - want[i]) > tol) return false;
    return true;
}

cg::TextureImage random_image(cg::Rng& rng, int w, int h) {
    cg::TextureImage im;
    im.width = w, im.height = h;
    for (int k = 0; k < w * h; ++k)
        im.texels.push_back({rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)});
    return im;
}

// A point on a quadric in model space, from its own equation (not from uv_point).
dvec3 model_point_on(const cg::Quadric& q, cg::Rng& rng) {
    const double phi = rng.uniform(-3.14159, 3.14159);
    switch (q.kind) {
        case cg::QuadricKind::Sphere:
        case cg::QuadricKind::Ellipsoid: {
            const double th = rng.uniform(0.05, 3.09);
            const double a = q.kind == cg::QuadricKind::Sphere ? q.r : q.a;
            const double b = q.kind == cg::QuadricKind::Sphere ? q.r : q.b;
            const double c = q.kind == cg::QuadricKind::Sphere ? q.r : q.c;
            return {a * std::sin(th) * std::cos(phi), b * std::sin(th) * std::sin(phi),
                    c * std::cos(th)};
        }
        case cg::QuadricKind::Cylinder:
            return {q.p * std::cos(phi), q.q * std::sin(phi), rng.uniform(q.zmin, q.zmax)};
        case cg::QuadricKind::Cone: {
            const double z = rng.uniform(0.2, 2) * (rng.chance(0.5) ? 1 : -1);
            return {q.p * std::fabs(z) / q.r * std::cos(phi),
                    q.q * std::fabs(z) / q.r * std::sin(phi), z};
        }
        case cg::QuadricKind::Paraboloid: {
            const double z = rng.uniform(0.1, 3);
            return {q.p * std::sqrt(z) * std::cos(phi), q.q * std::sqrt(z) * std::sin(phi), z};
        }
        case cg::QuadricKind::Hyperboloid: {
            const double z = rng.uniform(-2, 2);
            const double rho = std::sqrt(1 + z * z / (q.c * q.c));
            return {q.a * rho * std::cos(phi), q.b * rho * std::sin(phi), z};
        }
    }
    return {};
}

}  // namespace

TEST_CASE("texture-map: the globe worked by hand", "[rays][texture-map]") {
    // (0, 0.8, 0.6) on the unit sphere: φ = 90°, θ = acos 0.6; u = ½ + ¼ = 0.75,
    // v = 1 − acos(0.6)/π = 0.704833; on the 4 × 2 texture x = 0.75·4 − ½ = 2.5 (f = ½),
    // y = 0.704833·2 − ½ = 0.909666 (g); texels (2, 0), (3, 0), (2, 1), (3, 1).
    const auto tr = cg::test::run_traced<TextureMap>(input_of(algo().example()));
    CHECK(cg::test::events(tr) == std::vector<std::string>{"sphere-uv", "wrap", "bilinear"});
    const double v = 1 - std::acos(0.6) / 3.14159265358979323846, g = 2 * v - 0.5;
    CHECK(tr.result.frame.uv.x == Approx(0.75).margin(1e-15));
    CHECK(tr.result.frame.uv.y == Approx(v).margin(1e-15));
    const cg::TexelTaps& taps = tr.result.lookup.taps;
    CHECK(taps.texel[0] == glm::ivec2(2, 0));
    CHECK(taps.texel[3] == glm::ivec2(3, 1));
    CHECK(taps.weight[0] == Approx(0.5 * (1 - g)).margin(1e-12));
    CHECK(taps.weight[3] == Approx(0.5 * g).margin(1e-12));
    // The bottom row is the grid's second: (1, 1, 1) and (0, 0, 0); the top (0, 1, 0), (0, 1, 1).
    const dvec3 want =
        0.5 * (1 - g) * dvec3(1, 1, 1) + 0.5 * g * dvec3(0, 1, 0) + 0.5 * g * dvec3(0, 1, 1);
    CHECK(glm::length(tr.result.lookup.color - want) < 1e-12);
    CHECK(tr.steps[0].narration.find("90°") != std::string::npos);
}

TEST_CASE("texture-map: hand cases for every parametrisation, wrap and filter",
          "[rays][texture-map]") {
    SECTION("plane, nearest: the texel containing (s, t)") {
        const cg::json r = run(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.3, 0.8, 0],
                "texture": {"grid": {"width": 2, "height": 2, "texels": [[0, 0.5], [0.75, 1]]}, "filter": "nearest"}})");
        CHECK(r["uv"] == cg::json::parse("[0.3, 0.8]"));
        CHECK(r["texel"] == cg::json::parse("[0, 1]"));  // the top-left texel: 0
        CHECK(r["color"] == cg::json::parse("[0, 0, 0]"));
        CHECK(r["weights"] == cg::json::parse("[1.0]"));
    }
    SECTION("plane, on a texel border: nearest takes the texel to the upper right") {
        const cg::json r = run(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.5, 0.5, 0],
                "texture": {"grid": {"width": 2, "height": 2, "texels": [[0, 0.5], [0.75, 1]]}, "filter": "nearest"}})");
        CHECK(r["texel"] == cg::json::parse("[1, 1]"));
        CHECK(r["color"][0] == 0.5);
    }
    SECTION("plane, bilinear at the centre: the four texels equally") {
        const cg::json r = run(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.5, 0.5, 0],
                "texture": {"grid": {"width": 2, "height": 2, "texels": [[0, 0.5], [0.75, 1]]}}})");
        CHECK(r["weights"] == cg::json::parse("[0.25, 0.25, 0.25, 0.25]"));
        CHECK(r["color"][0] == Approx((0 + 0.5 + 0.75 + 1) / 4.0));
    }
    SECTION("repeat and clamp beyond the texture") {
        const std::string base =
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [1.3, -0.2, 0],
                "texture": {"grid": {"width": 2, "height": 2, "texels": [[0, 0.5], [0.75, 1]]}, "filter": "nearest", "wrap": )";
        const cg::json rep = run(base + R"("repeat"}})");
        CHECK(near(rep["st"], {0.3, 0.8}));
        CHECK(rep["texel"] == cg::json::parse("[0, 1]"));
        const cg::json cl = run(base + R"("clamp"}})");
        CHECK(cl["st"] == cg::json::parse("[1.0, 0.0]"));
        CHECK(cl["texel"] == cg::json::parse("[1, 0]"));
        CHECK(cl["color"][0] == 1);
    }
    SECTION("a plane with its own axes and scale") {
        // Normal y, u along x, v = n × a = (0, 0, −1), scale 2: P = (3, 0, −1) → (1.5, 0.5).
        const cg::json r = run(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "u_axis": [1, 0, 0], "uv_scale": 2},
                "point": [3, 0, -1], "texture": {"checker": {"size": 2}, "filter": "nearest"}})");
        CHECK(r["uv"] == cg::json::parse("[1.5, 0.5]"));
        CHECK(r["texel"] == cg::json::parse("[1, 1]"));
    }
    SECTION("triangle: barycentric interpolation of the corners' (u, v)") {
        const cg::json r = run(
            R"({"surface": {"type": "triangle", "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]], "uv": [[0.25, 0.25], [0.75, 0.25], [0.25, 0.75]]},
                "point": [1, 2, 0], "texture": {"checker": {"size": 4}, "filter": "nearest"}})");
        CHECK(near(r["barycentric"], {0.25, 0.25, 0.5}));
        CHECK(near(r["uv"], {0.375, 0.5}));
        CHECK(r["texel"] == cg::json::parse("[1, 2]"));
    }
    SECTION("cylinder: angle and height") {
        const auto tr = cg::test::run_traced<TextureMap>(input_of(cg::parse_json(
            R"({"surface": {"type": "cylinder", "params": {"p": 1, "q": 1}, "zmin": 0, "zmax": 2},
                "point": [0, -1, 1.5], "texture": {"checker": {"size": [8, 2]}, "filter": "nearest"}})")));
        CHECK(tr.steps[0].event == "axial-uv");
        CHECK(tr.result.frame.uv.x == Approx(0.25));
        CHECK(tr.result.frame.uv.y == Approx(0.75));
        CHECK(tr.result.lookup.taps.texel[0] == glm::ivec2(2, 1));
    }
    SECTION("the pole: u is ½, the step says the map is singular") {
        const auto tr = cg::test::run_traced<TextureMap>(input_of(cg::parse_json(
            R"({"surface": {"type": "sphere", "params": {"r": 2}}, "point": [0, 0, 2],
                "texture": {"checker": {"size": 8}, "filter": "nearest"}})")));
        CHECK(tr.result.frame.uv == dvec2(0.5, 1));
        CHECK(tr.result.frame.singular);
        CHECK(tr.steps[0].narration.find("pole") != std::string::npos);
    }
    SECTION("a transformed sphere is parametrised in model space") {
        // The unit sphere turned so its pole points along +y and moved to (5, 0, 0): the world
        // point (5, 1, 0) is the model's north pole.
        const cg::json r = run(
            R"({"surface": {"type": "sphere", "params": {"r": 1}, "transform": [[1, 0, 0, 5], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]]},
                "point": [5, 1, 0], "texture": {"checker": {"size": 8}, "filter": "nearest"}})");
        CHECK(r["uv"][1] == 1);
    }
    SECTION("mipmap: the levels built one by one, λ from the footprint, two levels blended") {
        const auto tr = cg::test::run_traced<TextureMap>(input_of(cg::parse_json(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.3, 0.6, 0],
                "texture": {"checker": {"size": 16}, "filter": "mipmap"}, "footprint": 0.2})")));
        CHECK(cg::test::events(tr) ==
              std::vector<std::string>{"plane-uv", "wrap", "mip-level", "mip-level", "mip-level",
                                       "mip-level", "level-of-detail", "level-sample",
                                       "level-sample", "blend"});
        CHECK(tr.result.levels == 5);
        CHECK(tr.result.lookup.lambda == Approx(std::log2(0.2 * 16)));
        CHECK(tr.result.lookup.level0 == 1);
        CHECK(tr.result.lookup.level1 == 2);
        // A checker averages to grey from level 1 on: every 2 × 2 block holds both colours.
        CHECK(tr.result.lookup.color.x == Approx(0.5));
    }
    SECTION("mipmap: a tiny footprint reads level 0 only") {
        const cg::json r = run(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.3, 0.6, 0],
                "texture": {"checker": {"size": 16}, "filter": "mipmap"}, "footprint": 0.01})");
        CHECK(r["lambda"] == 0);
        CHECK(r["levels"] == cg::json::parse("[0, 1]"));
        CHECK(r["blend"] == 0);
    }
}

TEST_CASE("texture-map: (u, v) on transformed quadrics agree with atan2/acos in long double",
          "[rays][texture-map][reference]") {
    int checked = 0;
    for (int kind = 0; kind < 6; ++kind) {
        cg::Rng rng(500 + kind);
        for (int trial = 0; trial < 2000; ++trial) {
            cg::Quadric q;
            q.kind = static_cast<cg::QuadricKind>(kind);
            q.r = rng.uniform(0.3, 3), q.a = rng.uniform(0.3, 3), q.b = rng.uniform(0.3, 3);
            q.c = rng.uniform(0.3, 3), q.p = rng.uniform(0.3, 3), q.q = rng.uniform(0.3, 3);
            if (q.kind == cg::QuadricKind::Cylinder || rng.chance(0.3)) {
                q.zmin = rng.uniform(-3, -1);
                q.zmax = rng.uniform(1, 3);
            }
            if (rng.chance(0.6)) {
                glm::dmat4 m = glm::translate(
                    glm::dmat4(1.0), {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)});
                m = glm::rotate(m, rng.uniform(0, 6.28),
                                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 1)));
                m = glm::scale(m, {rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)});
                q.world_from_model = m;
            }
            const dvec3 m = model_point_on(q, rng);
            const bool axial =
                q.kind != cg::QuadricKind::Sphere && q.kind != cg::QuadricKind::Ellipsoid;
            if (axial && std::isfinite(q.zmin) && (m.z < q.zmin || m.z > q.zmax)) continue;
            const dvec3 P = dvec3(q.world_from_model * glm::dvec4(m, 1));
            cg::UvSurface s;
            s.kind = cg::UvKind::Quadric;
            s.quadric = q;
            const cg::PreparedUv p = cg::prepare_uv(s);
            const cg::UvFrame f = cg::uv_frame(p, P);
            CAPTURE(kind, trial);
            t::LD u, v;
            t::quadric_uv_ref(q, t::lv(m), u, v);
            CHECK(std::fabs(f.uv.x - u) < 1e-9L);
            CHECK(std::fabs(f.uv.y - v) < 1e-9L * std::max<t::LD>(1, std::fabs(v)));
            // P(u, v) brings the point back, and the partials are its derivatives.
            CHECK(glm::length(cg::uv_point(p, f.uv) - P) < 1e-9 * (1 + glm::length(P)));
            const double h = 1e-6;
            const dvec3 du =
                (cg::uv_point(p, f.uv + dvec2(h, 0)) - cg::uv_point(p, f.uv - dvec2(h, 0))) /
                (2 * h);
            const dvec3 dv =
                (cg::uv_point(p, f.uv + dvec2(0, h)) - cg::uv_point(p, f.uv - dvec2(0, h))) /
                (2 * h);
            CHECK(glm::length(du - f.P_u) < 1e-5 * (1 + glm::length(f.P_u)));
            CHECK(glm::length(dv - f.P_v) < 1e-5 * (1 + glm::length(f.P_v)));
            // P_u × P_v points out of the solid (along ∇F) where the transform keeps orientation.
            if (glm::determinant(glm::dmat3(q.world_from_model)) > 0)
                CHECK(glm::dot(glm::cross(f.P_u, f.P_v), cg::normal_at(p.quadric, P)) > 0);
            // The texture-map algorithm accepts the point and reports the same (u, v).
            TextureMap::Input in;
            in.surface = s;
            in.point = P;
            in.texture.image = cg::checker_image(4, 4, dvec3(0), dvec3(1));
            CHECK(TextureMap::solve(in).frame.uv == f.uv);
            ++checked;
        }
    }
    CHECK(checked > 11000);
}

TEST_CASE("texture-map: bilinear weights sum to 1 and a linear texture comes back exactly",
          "[rays][texture-map][reference]") {
    cg::Rng rng(77);
    for (int trial = 0; trial < 3000; ++trial) {
        const int W = static_cast<int>(rng.integer(1, 9)), H = static_cast<int>(rng.integer(1, 9));
        const cg::TexWrap wrap = rng.chance(0.5) ? cg::TexWrap::Repeat : cg::TexWrap::Clamp;
        const cg::TextureImage im = random_image(rng, W, H);
        const dvec2 st{rng.uniform(0, 1), rng.uniform(0, 1)};
        CAPTURE(trial, W, H, st.x, st.y);
        const cg::TexelTaps b = cg::sample_bilinear(im, st, wrap);
        double sum = 0;
        for (double w : b.weight) {
            CHECK(w >= 0);
            sum += w;
        }
        CHECK(sum == Approx(1).margin(1e-15));
        const t::LColor ref = t::bilinear_ref(im, st.x, st.y, wrap);
        CHECK(std::fabs(b.color.x - ref.r) < 1e-13L);
        CHECK(std::fabs(b.color.z - ref.b) < 1e-13L);
        // Nearest: the texel containing the point.
        const cg::TexelTaps n = cg::sample_nearest(im, st, wrap);
        CHECK(n.texel[0].x == std::min(W - 1, static_cast<int>(std::floor(st.x * W))));
        CHECK(n.texel[0].y == std::min(H - 1, static_cast<int>(std::floor(st.y * H))));
    }
    // T(i, j) = a + b·(i + ½)/W + c·(j + ½)/H: bilinear gives a + b s + c t between the centres.
    for (int trial = 0; trial < 2000; ++trial) {
        const int W = static_cast<int>(rng.integer(2, 16)),
                  H = static_cast<int>(rng.integer(2, 16));
        const double a = rng.uniform(0, 1), b = rng.uniform(-1, 1), c = rng.uniform(-1, 1);
        cg::TextureImage im;
        im.width = W, im.height = H;
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i)
                im.texels.push_back(dvec3(a + b * (i + 0.5) / W + c * (j + 0.5) / H));
        const double s = rng.uniform(0.5 / W, 1 - 0.5 / W), tt = rng.uniform(0.5 / H, 1 - 0.5 / H);
        CAPTURE(trial, W, H, s, tt);
        CHECK(cg::sample_bilinear(im, {s, tt}, cg::TexWrap::Clamp).color.x ==
              Approx(a + b * s + c * tt).margin(1e-14));
    }
}

TEST_CASE("texture-map: mip levels are box averages and the trilinear colour agrees",
          "[rays][texture-map][reference]") {
    cg::Rng rng(31);
    for (int trial = 0; trial < 300; ++trial) {
        const int W = 1 << rng.integer(0, 6), H = 1 << rng.integer(0, 6);
        cg::Texture tex;
        tex.image = random_image(rng, W, H);
        tex.filter = cg::TexFilter::Mipmap;
        tex.wrap = rng.chance(0.5) ? cg::TexWrap::Repeat : cg::TexWrap::Clamp;
        const cg::MipMap mip = cg::build_mipmap(tex.image);
        CAPTURE(trial, W, H);
        REQUIRE(static_cast<int>(mip.levels.size()) == cg::mip_level_count(W, H));
        CHECK(mip.levels.back().width == 1);
        CHECK(mip.levels.back().height == 1);
        for (std::size_t k = 0; k < mip.levels.size(); ++k) {
            const cg::TextureImage& L = mip.levels[k];
            CHECK(L.width == std::max(1, W >> k));
            CHECK(L.height == std::max(1, H >> k));
            for (int j = 0; j < L.height; j += 1 + L.height / 4)
                for (int i = 0; i < L.width; i += 1 + L.width / 4) {
                    const t::LColor ref = t::box_average_ref(tex.image, static_cast<int>(k), i, j);
                    CHECK(std::fabs(L.at(i, j).y - ref.g) < 1e-13L);
                }
        }
        // The trilinear lookup from its parts, in long double.
        const dvec2 uv{rng.uniform(-2, 2), rng.uniform(-2, 2)};
        const double footprint = std::exp2(rng.uniform(-8, 2));
        const cg::TextureLookup l = cg::lookup(tex, &mip, uv, footprint);
        const t::LD rho = footprint * static_cast<t::LD>(std::max(W, H));
        const t::LD lambda =
            rho <= 1 ? 0
                     : std::min<t::LD>(std::log2(rho), static_cast<t::LD>(mip.levels.size() - 1));
        CHECK(std::fabs(l.lambda - lambda) < 1e-12L);
        const int k0 = static_cast<int>(std::floor(lambda));
        const int k1 = std::min<int>(k0 + 1, static_cast<int>(mip.levels.size()) - 1);
        const t::LD s = t::wrap_ref(uv.x, tex.wrap), tt = t::wrap_ref(uv.y, tex.wrap);
        const t::LColor c0 = t::bilinear_ref(mip.levels[k0], s, tt, tex.wrap),
                        c1 = t::bilinear_ref(mip.levels[k1], s, tt, tex.wrap);
        const t::LD blend = lambda - k0;
        CHECK(std::fabs(l.color.x - ((1 - blend) * c0.r + blend * c1.r)) < 1e-11L);
    }
}

TEST_CASE("texture-map: the state machine gives the plain function's answer, bit for bit",
          "[rays][texture-map]") {
    cg::Rng rng(4);
    std::set<std::string> events;
    for (int trial = 0; trial < 1500; ++trial) {
        TextureMap::Input in;
        const int kind = static_cast<int>(rng.integer(0, 2));
        if (kind == 0) {
            in.surface.kind = cg::UvKind::Plane;
            in.surface.normal = glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 1));
            in.surface.u_axis = {1, 0, 0};
            in.surface.origin = {rng.uniform(-2, 2), 0, 0};
            in.surface.scale = rng.uniform(0.2, 3);
            const cg::PreparedUv p = cg::prepare_uv(in.surface);
            in.point = cg::uv_point(p, {rng.uniform(-3, 3), rng.uniform(-3, 3)});
        } else if (kind == 1) {
            in.surface.kind = cg::UvKind::Quadric;
            in.surface.quadric.kind = cg::QuadricKind::Sphere;
            in.surface.quadric.r = rng.uniform(0.5, 2);
            in.point =
                in.surface.quadric.r *
                glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        } else {
            in.surface.kind = cg::UvKind::Triangle;
            in.surface.p = {dvec3(0, 0, 0), dvec3(2, 0, 1), dvec3(0, 3, 0)};
            in.surface.uv = {dvec2(rng.uniform(0, 1), 0), dvec2(1, 0.2), dvec2(0.3, 1)};
            const double b = rng.uniform(0, 0.5), g = rng.uniform(0, 0.5);
            in.point = in.surface.p[0] + b * (in.surface.p[1] - in.surface.p[0]) +
                       g * (in.surface.p[2] - in.surface.p[0]);
        }
        const int W = 1 << rng.integer(0, 5), H = 1 << rng.integer(0, 5);
        in.texture.image = random_image(rng, W, H);
        in.texture.filter = static_cast<cg::TexFilter>(rng.integer(0, 2));
        in.texture.wrap = rng.chance(0.5) ? cg::TexWrap::Repeat : cg::TexWrap::Clamp;
        in.footprint = rng.chance(0.2) ? 0 : std::exp2(rng.uniform(-7, 1));
        CAPTURE(trial);
        const TextureMap::Result want = TextureMap::solve(in);
        auto s = TextureMap::start(in);
        CHECK(cg::run_to_end<TextureMap>(s) == want);
        const auto tr = cg::test::run_traced<TextureMap>(in);
        CHECK(tr.result == want);
        for (const auto& st : tr.steps) {
            events.insert(st.event);
            CHECK(st.narration.find("nan") == std::string::npos);
            CHECK(st.narration.find("inf") == std::string::npos);
        }
    }
    for (const auto& e : TextureMap::spec().events) {
        if (e.id == "axial-uv") continue;  // the hand cases have it
        CAPTURE(e.id);
        CHECK(events.count(e.id) == 1);
    }
}

TEST_CASE(
    "texture-map: image files are read with their first row at v = 1, and bad files are named",
    "[rays][texture-map][errors]") {
    // A 2 × 2 PNG: top row red, green; bottom row blue, white.
    const std::string png = cg::test::output_path("tex-2x2.png");
    const unsigned char px[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    REQUIRE(stbi_write_png(png.c_str(), 2, 2, 3, px, 6) != 0);
    const cg::TextureImage im = cg::texture_json::read_image_file(png, "texture.image");
    REQUIRE(im.width == 2);
    CHECK(im.at(0, 1) == dvec3(1, 0, 0));  // the file's first row is the top: j = 1
    CHECK(im.at(1, 0) == dvec3(1, 1, 1));
    const std::string in =
        R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.25, 0.75, 0],
                               "texture": {"image": ")" +
        png + R"(", "filter": "nearest"}})";
    CHECK(run(in)["color"] == cg::json::parse("[1.0, 0.0, 0.0]"));

    const std::string missing = cg::test::output_path("no-such-texture.png");
    CHECK(
        error_of(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0, 0, 0],
                       "texture": {"image": ")" +
            missing + R"("}})") == "texture.image: cannot read \"" + missing + "\": no such file");
    const std::string text = cg::test::write_temp("not-an-image.png", "hello, I am not a PNG");
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0, 0, 0],
                       "texture": {"image": ")" +
            text + R"("}})"),
        Catch::StartsWith("texture.image: cannot read \"" + text + "\": not an image"));

    // Through the CLI, a relative path is taken beside the input file.
    const std::string dir = cg::test::output_path("texdir");
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(png, dir + "/beside.png",
                               std::filesystem::copy_options::overwrite_existing);
    {
        std::ofstream f(dir + "/in.json");
        f << R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.75, 0.25, 0],
                 "texture": {"image": "beside.png", "filter": "nearest"}})";
    }
    auto r = cg::test::cgsandbox({"run", "texture-map", "--input", dir + "/in.json"});
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(cg::parse_json(r.out)["color"] == cg::json::parse("[1.0, 1.0, 1.0]"));
    {
        std::ofstream f(dir + "/bad.json");
        f << R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0, 0, 0],
                 "texture": {"image": "gone.png"}})";
    }
    r = cg::test::cgsandbox({"run", "texture-map", "--input", dir + "/bad.json"});
    CHECK(r.exit_code == 2);
    CHECK(r.err == "cgsandbox: " + dir + "/bad.json: texture.image: cannot read \"" + dir +
                       "/gone.png\": no such file\n");
}

TEST_CASE("texture-map: bad input is refused with the field named", "[rays][texture-map][errors]") {
    const std::string plane =
        R"("surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]})";
    const std::string grid = R"({"grid": {"width": 2, "height": 2, "texels": [[0, 1], [1, 0]]}})";
    // Off a plane a point is projected onto it; off any other surface it is refused.
    CHECK(run("{" + plane + R"(, "point": [0.25, 0.5, 1], "texture": )" + grid + "}")["uv"] ==
          cg::json::parse("[0.25, 0.5]"));
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "sphere", "params": {"r": 1}}, "point": [0, 0, 0], "texture": )" +
            grid + "}"),
        Catch::StartsWith("point: must lie on the sphere"));
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}, "point": [1, 1, 0], "texture": )" +
            grid + "}"),
        Catch::StartsWith("point: must lie inside the triangle"));
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "uv": [[0, 0], [1, 1], [2, 2]]}, "point": [0, 0, 0], "texture": )" +
            grid + "}"),
        Catch::StartsWith("surface.uv: must not put the three corners on one line"));
    CHECK_THAT(
        error_of(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "u_axis": [0, 0, 2]}, "point": [0, 0, 0], "texture": )" +
            grid + "}"),
        Catch::StartsWith("surface.u_axis: must not be parallel to the plane's normal"));
    CHECK_THAT(
        error_of(
            "{" + plane +
            R"(, "point": [0, 0, 0], "texture": {"grid": {"width": 3, "height": 2, "texels": [[0, 1, 0], [1, 0, 1]]}, "filter": "mipmap"}})"),
        Catch::StartsWith(
            "texture.filter: \"mipmap\" needs a width and height that are powers of two"));
    CHECK_THAT(
        error_of(
            "{" + plane +
            R"(, "point": [0, 0, 0], "texture": {"grid": {"width": 2, "height": 3, "texels": [[0, 1], [1, 0]]}}})"),
        Catch::StartsWith("texture.grid.texels: must be 3 rows"));
    CHECK_THAT(
        error_of(
            "{" + plane +
            R"(, "point": [0, 0, 0], "texture": {"grid": {"width": 2, "height": 2, "texels": [[0, 1], [1, 0, 1]]}}})"),
        Catch::StartsWith("texture.grid.texels[1]: must be a row of 2 colours"));
    CHECK_THAT(
        error_of(
            "{" + plane +
            R"(, "point": [0, 0, 0], "texture": {"grid": {"width": 2, "height": 2, "texels": [[0, -1], [1, 0]]}}})"),
        Catch::StartsWith("texture: texel (1, 1) must be a colour with components in [0, 1e6]"));
    CHECK_THAT(
        error_of(
            "{" + plane +
            R"(, "point": [0, 0, 0], "texture": {"checker": {}, "grid": {"width": 1, "height": 1, "texels": [[0]]}}})"),
        Catch::StartsWith("texture: needs exactly one of \"image\""));
    CHECK_THAT(
        error_of("{" + plane +
                 R"(, "point": [0, 0, 0], "texture": {"checker": {}, "filter": "trilinear"}})"),
        Catch::StartsWith("texture.filter: must be \"nearest\", \"bilinear\" or \"mipmap\""));
    CHECK_THAT(error_of("{" + plane +
                        R"(, "point": [0, 0, 0], "texture": {"checker": {}, "wrap": "mirror"}})"),
               Catch::StartsWith("texture.wrap: must be \"repeat\" or \"clamp\""));
    CHECK_THAT(
        error_of("{" + plane + R"(, "point": [0, 0, 0], "texture": {"checker": {}, "colour": 1}})"),
        Catch::StartsWith("texture.colour: is not a field of a texture"));
    CHECK_THAT(
        error_of("{" + plane + R"(, "point": [0, 0, 0], "texture": {"checker": {"size": 0}}})"),
        Catch::StartsWith("texture.checker.size: must be a number of squares from 1 to 4096"));
    CHECK_THAT(error_of("{" + plane +
                        R"(, "point": [0, 0, 0], "texture": {"checker": {}}, "footprint": -1})"),
               Catch::StartsWith("footprint: must be a size"));
    CHECK_THAT(
        error_of(
            "{" + plane +
            R"(, "point": [0, 0, 0], "texture": {"grid": {"width": 5000, "height": 1, "texels": [[0]]}}})"),
        Catch::StartsWith("texture.grid.width: must be a number of texels from 1 to 4096"));
}

TEST_CASE("texture-map: exam problems are answered as the reference says",
          "[rays][texture-map][exam]") {
    std::set<std::string> events;
    int mip = 0, degenerate_pole = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(algo(), seed);
        const TextureMap::Input in = input_of(p.input);
        const auto tr = cg::test::run_traced<TextureMap>(in);
        for (const auto& s : tr.steps) events.insert(s.event);
        const dvec2 uv = tr.result.frame.uv;
        // (u, v) are multiples of 1/16 (or the pole's ½).
        CHECK(std::fabs(uv.x * 16 - std::round(uv.x * 16)) < 1e-9);
        CHECK(std::fabs(uv.y * 16 - std::round(uv.y * 16)) < 1e-9);
        mip += in.texture.filter == cg::TexFilter::Mipmap;
        degenerate_pole += tr.result.frame.singular;
        // The colour from the reference lookup.
        if (in.texture.filter == cg::TexFilter::Bilinear) {
            const t::LColor c =
                t::bilinear_ref(in.texture.image, t::wrap_ref(uv.x, in.texture.wrap),
                                t::wrap_ref(uv.y, in.texture.wrap), in.texture.wrap);
            CHECK(std::fabs(p.expected["color"][0].get<double>() - c.r) < 1e-12L);
        }
        CHECK(cg::grade(p, p.expected)[0].correct);
        CHECK(p.question.find("Give (u, v)") != std::string::npos);
    }
    CHECK(mip > 20);
    CHECK(degenerate_pole > 5);
    for (const char* e :
         {"plane-uv", "sphere-uv", "axial-uv", "triangle-uv", "nearest", "bilinear", "blend"}) {
        CAPTURE(e);
        CHECK(events.count(e) == 1);
    }
}

TEST_CASE("texture-map: traces are deterministic and stepping back reproduces them",
          "[rays][texture-map]") {
    cg::test::check_replay(algo(), algo().example(), cg::test::kEveryStep);
    cg::test::check_replay(
        algo(),
        cg::parse_json(
            R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.3, 0.6, 0],
                           "texture": {"checker": {"size": 16}, "filter": "mipmap"}, "footprint": 0.2})"),
        cg::test::kEveryStep);
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const cg::json j = algo().exam_input(seed);
        CHECK(cg::exam_for_input(algo(), j).expected == cg::make_exam(algo(), seed).expected);
    }
}

TEST_CASE("texture-map: the picture shows the texture, the texels read and the textured surface",
          "[rays][texture-map]") {
    auto s = TextureMap::start(input_of(algo().example()));
    while (!TextureMap::done(s)) TextureMap::step(s, nullptr);
    cg::Scene scene;
    TextureMap::draw(s, scene);
    CHECK_FALSE(scene.has_2d());  // nothing on the world's grid
    // The texture in an image panel of its own, the four texels read outlined in its cells with
    // their weights, (s, t) on it.
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& tex = scene.panels[0];
    CHECK(tex.kind == cg::PanelKind::Image);
    REQUIRE(tex.grids.size() == 1);
    CHECK(tex.grids[0].width == 4);
    CHECK(tex.grids[0].height == 2);
    CHECK(tex.grids[0].rgba[0] == 0x0000ffffu);  // texel (0, 0): the bottom row's blue
    CHECK(tex.polygons.size() == 4);             // the four texels read
    CHECK(tex.labels.size() == 4);               // their weights
    REQUIRE(tex.points.size() == 1);             // (s, t)
    CHECK(tex.points[0].style.role == cg::Role::Active);
    CHECK(scene.faces3.size() == 24 * 12);
    CHECK(scene.focus3.size() == 1);
    bool u_arrow = false;
    for (const auto& seg : scene.segments3)
        u_arrow = u_arrow || (seg.label == "u" && seg.min_pixels >= 30);
    CHECK(u_arrow);
    // A big image is shown every k-th texel.
    cg::Scene big;
    cg::TextureImage im = cg::checker_image(1024, 512, dvec3(0), dvec3(1));
    int shown = 0;
    const cg::Panel& p = cg::texdraw::add_image(im, big, "", shown);
    CHECK(shown == 8);
    CHECK(p.grids[0].width == 128);
}

TEST_CASE("texture-map: mip-mapping shows level 0 with the footprint and the level read",
          "[rays][texture-map]") {
    auto s = TextureMap::start(input_of(cg::parse_json(
        R"({"surface": {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "point": [0.3, 0.6, 0],
            "texture": {"checker": {"size": 16}, "filter": "mipmap"}, "footprint": 0.2})")));
    while (!TextureMap::done(s)) TextureMap::step(s, nullptr);
    cg::Scene scene;
    TextureMap::draw(s, scene);
    REQUIRE(scene.panels.size() == 2);
    CHECK(scene.panels[0].grids[0].width == 16);
    CHECK(scene.panels[1].grids[0].width < 16);  // a coarser level
    // The footprint (0.2 of 16 texels) round (s, t) on level 0, dashed.
    bool footprint = false;
    for (const auto& poly : scene.panels[0].polygons)
        footprint = footprint ||
                    (poly.style.dashed && poly.points[1].x - poly.points[0].x == Approx(0.2 * 16));
    CHECK(footprint);
    CHECK_FALSE(scene.panels[1].polygons.empty());  // the taps read there
}
