// Colour spaces, the picture (3D): on the left the HSV hexcone (or HSL's double hexcone), V (or
// L) up and the hues round its rim, the sector of the step's hue outlined; on the right the RGB
// cube with its grey diagonal. The colour being converted is a large dot in its own colour in
// both solids, labelled once in each — in HSV/HSL in the cone, in RGB in the cube — with its
// chroma C as the cone's radius; colours done are small dots; an XYZ or YIQ colour outside the
// cube is shown clamped onto it. Seen from the front and above, framed on both solids.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <glm/geometric.hpp>

#include "colour/colour_spaces.hpp"
#include "core/format.hpp"

namespace cg {

using glm::dvec3;
using Space = ColourSpaces::Space;
using Phase = ColourSpaces::Phase;
using Input = ColourSpaces::Input;

namespace {

// The hexcone (or HSL's double hexcone) on the left, the RGB cube on the right. A colour's
// place in the cone: height V (or L), and in the horizontal plane the projection of the RGB
// cube along its grey diagonal, a = R − (G + B)/2, b = (√3/2)(G − B), whose hexagonal radius is
// the chroma (the pure hues at distance 1, 60° apart, hue counter-clockwise seen from above).
const dvec3 kCone{-1.15, -0.5, 0};
const dvec3 kCube{0.45, -0.5, -0.5};

dvec3 plane(const dvec3& rgb) {
    return {rgb.x - (rgb.y + rgb.z) / 2, 0, -std::sqrt(3.0) / 2 * (rgb.y - rgb.z)};
}

dvec3 in_cone(const dvec3& rgb, bool hsl) {
    const double mx = std::max({rgb.x, rgb.y, rgb.z}), mn = std::min({rgb.x, rgb.y, rgb.z});
    return kCone + plane(rgb) + dvec3(0, hsl ? (mx + mn) / 2 : mx, 0);
}

dvec3 in_cube(const dvec3& rgb) {
    return kCube + rgb;
}

const dvec3 kHues[6] = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {1, 0, 1}};
const char* const kHueNames[6] = {"red 0°",    "yellow 60°", "green 120°",
                                  "cyan 180°", "blue 240°",  "magenta 300°"};

bool cone_space(Space s) {
    return s == Space::Hsv || s == Space::Hsl;
}

// "HSV (144, 0.625, 0.8)": a colour written in its space.
std::string named(Space s, const dvec3& v) {
    std::string name = ColourSpaces::name(s);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return name + " " + num(v, 4);
}

void draw_cone(Scene& scene, bool hsl, int sector) {
    const double rim = hsl ? 0.5 : 1.0;
    const dvec3 black = kCone, white = kCone + dvec3(0, 1, 0), centre = kCone + dvec3(0, rim, 0);
    for (int i = 0; i < 6; ++i) {
        const dvec3 a = kCone + plane(kHues[i]) + dvec3(0, rim, 0);
        const dvec3 b = kCone + plane(kHues[(i + 1) % 6]) + dvec3(0, rim, 0);
        const dvec3 mid = (kHues[i] + kHues[(i + 1) % 6]) / 2.0;
        const bool active = i == sector;
        scene.faces3.push_back({{centre, a, b},
                                {Role::Neutral, active ? 2.5f : 1.0f, false, pack_rgba(mid)},
                                active ? 0.85f : 0.45f,
                                active,
                                true});
        scene.faces3.push_back({{black, b, a},
                                {Role::Neutral, 1.0f, false, pack_rgba(mid * 0.5)},
                                0.12f,
                                false,
                                true});
        if (hsl)
            scene.faces3.push_back({{white, a, b},
                                    {Role::Neutral, 1.0f, false, pack_rgba(mid * 0.5 + 0.5)},
                                    0.12f,
                                    false,
                                    true});
        scene.segments3.push_back({a, b, "", {Role::Construction, 1.0f}, false});
        scene.segments3.push_back({black, a, "", {Role::Construction, 1.0f}, false});
        if (hsl) scene.segments3.push_back({white, a, "", {Role::Construction, 1.0f}, false});
        // The hue's dot in its colour; its name in dark text (yellow or cyan text would not read
        // on white), yielding to the colour's own labels.
        scene.points3.push_back({a, "", {Role::Neutral, 1.0f, false, pack_rgba(kHues[i])}, 4.0f});
        scene.labels3.push_back({a, kHueNames[i], {Role::Neutral}, -1});
    }
    scene.segments3.push_back({black, white, "", {Role::Construction, 1.0f, true}, false});
    scene.labels3.push_back({black - dvec3(0, 0.12, 0),
                             hsl ? "HSL double hexcone: L up" : "HSV hexcone: V up",
                             {Role::Neutral}});
}

void draw_cube(Scene& scene) {
    for (int c = 0; c < 8; ++c) {
        const dvec3 p(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        for (int axis = 0; axis < 3; ++axis)
            if (!(c >> axis & 1)) {
                dvec3 q = p;
                q[axis] = 1;
                scene.segments3.push_back(
                    {in_cube(p), in_cube(q), "", {Role::Construction, 1.0f}, false});
            }
        scene.points3.push_back({in_cube(p), "", {Role::Neutral, 1.0f, false, pack_rgba(p)}, 4.0f});
    }
    scene.segments3.push_back(
        {in_cube(dvec3(0)), in_cube(dvec3(1)), "", {Role::Construction, 1.0f, true}, false});
    scene.labels3.push_back({in_cube({1, 0, 0}) + dvec3(0.1, 0, 0), "R", {Role::Neutral}});
    scene.labels3.push_back({in_cube({0, 1, 0}) + dvec3(0, 0.1, 0), "G", {Role::Neutral}});
    scene.labels3.push_back({in_cube({0, 0, 1}) + dvec3(0, 0, 0.1), "B", {Role::Neutral}});
    scene.labels3.push_back(
        {in_cube(dvec3(0.5, 0, 0)) - dvec3(0, 0.12, 0), "RGB cube", {Role::Neutral}});
}

// The RGB the colour's input stands for (what the run computes by the end of its first part).
dvec3 rgb_of(const Input& in, std::size_t k) {
    Input one{in.from, Space::Rgb, {in.colors[k]}};
    return ColourSpaces::convert(one).rgb[0];
}

}  // namespace

void ColourSpaces::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const bool hsl = in.from == Space::Hsl || in.to == Space::Hsl;
    scene.extent3 = 1.7;
    const bool working = s.k >= 0;
    int sector = -1;
    if (working && (s.last == Phase::FromSector || s.last == Phase::FromAddM)) sector = s.w.sector;
    if (working && s.last == Phase::ToHue && s.w.chroma > 0)
        sector = std::min(5, static_cast<int>(std::floor(s.w.out.x / 60)));
    draw_cone(scene, hsl, sector);
    draw_cube(scene);
    // Both solids, seen from the front and above so the hexagon of hues opens up.
    scene.view3 = {glm::normalize(dvec3(-0.25, -0.48, -0.8)), dvec3(0, 1, 0), false};
    add_focus(scene, kCone - dvec3(1, 0.15, 1), in_cube(dvec3(1)) + dvec3(0, 0.15, 0));

    // The colours: finished ones small, the current one large with its construction.
    const std::size_t n = in.colors.size();
    const std::size_t current = s.k < 0 ? 0 : static_cast<std::size_t>(s.k);
    for (std::size_t k = 0; k < n; ++k) {
        if (k != current && n > 40 && k % (n / 40 + 1) != 0) continue;  // a sample of many
        const dvec3 c = k < s.done.rgb.size() ? s.done.rgb[k] : rgb_of(in, k);
        const bool big = k == current;
        // Each solid's point says the colour in that solid's space, once: the cone in HSV or
        // HSL (the input, or the result once known), the cube in RGB, or in the other space
        // of the conversion (CMY, XYZ, YIQ) with its RGB.
        const bool finished = k < s.done.colors.size();
        std::string cone, cube;
        if (big) {
            if (cone_space(in.from))
                cone =
                    named(in.from, in.colors[k]) +
                    (cone_space(in.to) && finished ? " → " + named(in.to, s.done.colors[k]) : "");
            else if (cone_space(in.to) && finished)
                cone = named(in.to, s.done.colors[k]);
            if (in.from == Space::Rgb || cone_space(in.from))
                cube = named(Space::Rgb, c);
            else
                cube = named(in.from, in.colors[k]) + " → " + named(Space::Rgb, c);
            if (!cone_space(in.to) && in.to != Space::Rgb && finished)
                cube += " → " + named(in.to, s.done.colors[k]);
        }
        // The dots in the colour itself; their labels in the step's orange (a white or yellow
        // colour's own text would not read).
        scene.points3.push_back(
            {in_cone(c, hsl), "", {Role::Active, 2.0f, false, pack_rgba(c)}, big ? 10.0f : 5.0f});
        scene.points3.push_back(
            {in_cube(c), "", {Role::Active, 2.0f, false, pack_rgba(c)}, big ? 10.0f : 5.0f});
        if (!cone.empty()) scene.labels3.push_back({in_cone(c, hsl), cone, {Role::Active}});
        if (!cube.empty()) scene.labels3.push_back({in_cube(c), cube, {Role::Active}});
        if (!big) continue;
        const dvec3 p = in_cone(c, hsl);
        const dvec3 axis = kCone + dvec3(0, p.y - kCone.y, 0);
        const double mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
        if (mx > mn)
            scene.segments3.push_back(
                {axis, p, "C = " + num(mx - mn, 3), {Role::Active, 1.5f, true}, false});
        scene.segments3.push_back(
            {in_cube(dvec3(0)), in_cube(c), "", {Role::Construction, 1.0f, true}, true});
        if (s.k >= 0 && s.w.out_of_gamut && static_cast<std::size_t>(s.k) == k &&
            s.last >= Phase::FromGamut) {
            const dvec3 u = s.w.unclamped;
            if (glm::length(u) < 4)
                scene.segments3.push_back(
                    {in_cube(u), in_cube(c), "clamped", {Role::Discarded, 2.0f, true}, true});
            scene.labels3.push_back(
                {in_cube(c) + dvec3(0, 0.15, 0), "out of gamut", {Role::Discarded}});
        }
    }
}

}  // namespace cg
