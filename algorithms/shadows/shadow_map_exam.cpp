// Shadow map exam problems: a directional light straight down from (0, 5, 0) (up (0, 0, −1),
// so x_L = x, y_L = −z and d = 5 − y), a 4 × 4 map over the box ±2 (texels one unit wide), the
// floor y = 0 over [−2, 2]², and a rectangular card at height 1 to 4 whose sides lie on texel
// boundaries. The eye, a single pixel, looks at one point P: on the floor (under the card or
// not) or on the card's top, never on a texel boundary. The question asks for the depth map,
// P's texel and depth, d_map and the verdict (bias 0.1).
#include "core/format.hpp"
#include "shadows/shadow_map.hpp"

namespace cg {

namespace {

ShadowMap::Triangle tri(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    return {a, b, c};
}

}  // namespace

ShadowMap::Input ShadowMap::exam_input(Rng& rng) {
    Input in;
    in.triangles = {tri({-2, 0, -2}, {2, 0, -2}, {2, 0, 2}),
                    tri({-2, 0, -2}, {2, 0, 2}, {-2, 0, 2})};
    // The card: texel columns i0..i1 and rows j0..j1 (x = −2 + i, z = 2 − j).
    const int i0 = int(rng.integer(0, 2)), i1 = int(rng.integer(i0, std::min(3, i0 + 2)));
    const int j0 = int(rng.integer(0, 2)), j1 = int(rng.integer(j0, std::min(3, j0 + 2)));
    const double h = double(rng.integer(1, 4));
    const double x0 = -2 + i0, x1 = -1 + i1, z0 = 1 - j1, z1 = 2 - j0;
    in.triangles.push_back(tri({x0, h, z0}, {x1, h, z0}, {x1, h, z1}));
    in.triangles.push_back(tri({x0, h, z0}, {x1, h, z1}, {x0, h, z1}));
    in.light.type = LightType::Directional;
    in.light.position = {0, 5, 0};
    in.light.target = {0, 0, 0};
    in.light.up = {0, 0, -1};
    in.light.extent = 2;
    in.light.near = 0.5;
    in.light.far = 10;
    in.map_size = 4;
    in.bias = 0.1;
    // P: a quarter-unit point inside a texel; on the card's top one time in four.
    static constexpr double kOffsets[] = {0.25, 0.5, 0.75};
    const bool on_card = rng.chance(0.25);
    const int ti = on_card ? int(rng.integer(i0, i1)) : int(rng.integer(0, 3));
    const int tj = on_card ? int(rng.integer(j0, j1)) : int(rng.integer(0, 3));
    const glm::dvec3 p{-2 + ti + kOffsets[rng.integer(0, 2)], on_card ? h : 0,
                       2 - tj - kOffsets[rng.integer(0, 2)]};
    // The eye looks at P from low in front (under the card's height, for a floor point), so
    // nothing is between them.
    in.eye.position = on_card ? p + glm::dvec3(0, 2, 3) : p + glm::dvec3(0, 0.5, 4.5);
    in.eye.target = p;
    in.eye.up = {0, 1, 0};
    in.eye.fov_deg = 30;
    in.eye.width = in.eye.height = 1;
    return in;
}

std::string ShadowMap::question(const Input& in) {
    const auto& c = in.triangles[2];
    return "A directional light looks straight down from (0, 5, 0) (its frame: r = (1, 0, 0), "
           "u = (0, 0, −1), f = (0, −1, 0), so x_L = x, y_L = −z and the depth is d = 5 − y). "
           "Its 4 × 4 shadow map covers x_L, y_L in [−2, 2]: texel (i, j) has i = ⌊4 s⌋, "
           "j = ⌊4 t⌋ with s = (x_L / 2 + 1) / 2, t = (y_L / 2 + 1) / 2. The scene: the floor "
           "y = 0 over [−2, 2]², and a card at height " +
           num(c[0].y) + " over x in [" + num(c[0].x) + ", " + num(c[1].x) + "], z in [" +
           num(c[0].z) + ", " + num(c[2].z) +
           "]. Render the depth map (depth_map: 4 rows, depth_map[j][i], j = 0 the bottom row; "
           "the depth sampled at each texel's centre). The eye sees P = " +
           num(in.eye.target) +
           ". Give P's depth (last/d_p), its texel (last/texel: [i, j]), the stored depth "
           "(last/d_map), and whether it is in shadow with bias 0.1 (last/in_shadow: "
           "d_P − bias > d_map).";
}

std::vector<std::string> ShadowMap::answer_fields(const Input&) {
    return {"depth_map", "last/d_p", "last/texel", "last/d_map", "last/in_shadow"};
}

}  // namespace cg
