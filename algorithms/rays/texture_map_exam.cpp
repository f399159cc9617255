// Texture-map exam problems in the course's style: "the point P on this sphere (or plane,
// cylinder, triangle) is textured with the 4 × 4 texture below; give (u, v), the texel read and
// the colour (nearest), or the four texels' weights (bilinear)". The numbers are chosen so that
// (u, v) are multiples of 1/16: longitudes and polar angles on a 45° grid, plane points on
// eighths of the scale, barycentric weights in quarters, cylinder heights in halves. Grey texels
// are quarters. Now and then (about one time in four) a degenerate case: a sphere's pole (every
// u names it; the algorithm reports u = ½), a point beyond the texture with clamp, a point on a
// texel border (nearest takes the texel above and to the right), or a mipmap read with a
// footprint of 2^λ/4.
#include <array>
#include <cmath>

#include "core/format.hpp"
#include "rays/ray_quadric.hpp"
#include "rays/texture_map.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

Texture grey_grid(Rng& rng, int w, int h) {
    Texture t;
    t.source = "grid";
    t.image.width = w;
    t.image.height = h;
    for (int k = 0; k < w * h; ++k)
        t.image.texels.push_back(TexColor(0.25 * static_cast<double>(rng.integer(0, 4))));
    return t;
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TextureMap::Input TextureMap::exam_input(Rng& rng) {
    Input in;
    const bool degenerate = rng.chance(0.25);
    const int kind = static_cast<int>(rng.integer(0, 3));
    in.texture = grey_grid(rng, 4, 4);
    in.texture.filter = rng.chance(0.5) ? TexFilter::Nearest : TexFilter::Bilinear;
    in.texture.wrap = rng.chance(0.7) ? TexWrap::Repeat : TexWrap::Clamp;
    switch (kind) {
        case 0: {  // the plane z = 0, u along x, scale 1, 2 or 4
            UvSurface& s = in.surface;
            s.kind = UvKind::Plane;
            s.origin = {0, 0, 0};
            s.normal = {0, 0, 1};
            s.u_axis = {1, 0, 0};
            s.scale = pick(rng, std::array<double, 3>{1, 2, 4});
            const double u = static_cast<double>(rng.integer(-4, 20)) / 16,
                         v = static_cast<double>(rng.integer(-4, 20)) / 16;
            in.point = {s.scale * u, s.scale * v, 0};
            if (degenerate) {  // on a texel border, or beyond the texture with clamp
                in.point = {s.scale * 0.5, s.scale * 1.25, 0};
                in.texture.wrap = TexWrap::Clamp;
            }
            break;
        }
        case 1: {  // a sphere, longitude and polar angle on a 45° grid
            in.surface.kind = UvKind::Quadric;
            in.surface.quadric.kind = QuadricKind::Sphere;
            in.surface.quadric.r = pick(rng, std::array<double, 2>{1, 2});
            const double r = in.surface.quadric.r;
            const double phi = 45.0 * static_cast<double>(rng.integer(-3, 4)) * kPi / 180;
            double theta = 45.0 * static_cast<double>(rng.integer(1, 3)) * kPi / 180;
            if (degenerate) theta = 0;  // the north pole
            in.point = {r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                        r * std::cos(theta)};
            break;
        }
        case 2: {  // the cylinder x² + y² = 1 cut to 0 ≤ z ≤ 2
            in.surface.kind = UvKind::Quadric;
            Quadric& q = in.surface.quadric;
            q.kind = QuadricKind::Cylinder;
            q.zmin = 0;
            q.zmax = 2;
            const double phi = 90.0 * static_cast<double>(rng.integer(-1, 2)) * kPi / 180;
            const double z = 0.5 * static_cast<double>(rng.integer(1, 3));
            in.point = {std::round(std::cos(phi)), std::round(std::sin(phi)), z};
            break;
        }
        default: {  // a triangle with (u, v) at its corners
            UvSurface& s = in.surface;
            s.kind = UvKind::Triangle;
            s.p = {dvec3(0, 0, 0), dvec3(4, 0, 0), dvec3(0, 4, 0)};
            s.uv = {dvec2(0, 0), dvec2(1, 0), dvec2(0, 1)};
            if (rng.chance(0.5)) s.uv = {dvec2(0.25, 0.25), dvec2(0.75, 0.25), dvec2(0.25, 0.75)};
            const double beta = 0.25 * static_cast<double>(rng.integer(0, 3));
            const double gamma =
                0.25 * static_cast<double>(rng.integer(0, 3 - static_cast<int>(beta * 4)));
            in.point = s.p[0] + beta * (s.p[1] - s.p[0]) + gamma * (s.p[2] - s.p[0]);
            break;
        }
    }
    if (!degenerate && rng.chance(0.2)) {  // mipmapped, λ on a half grid
        in.texture.filter = TexFilter::Mipmap;
        in.footprint = std::exp2(0.5 * static_cast<double>(rng.integer(0, 4))) / 4;
    }
    return in;
}

std::string TextureMap::question(const Input& in) {
    const Texture& t = in.texture;
    std::string s = "The point P = " + num(in.point, 4) + " on ";
    switch (in.surface.kind) {
        case UvKind::Plane:
            s += "the plane through " + num(in.surface.origin) + " with normal " +
                 num(in.surface.normal) + ", u axis " + num(in.surface.u_axis) + " and scale " +
                 num(in.surface.scale) + " (u = (P − O)·a/s, v = (P − O)·(n × a)/s)";
            break;
        case UvKind::Triangle:
            s += "the triangle " + num(in.surface.p[0]) + ", " + num(in.surface.p[1]) + ", " +
                 num(in.surface.p[2]) + " with (u, v) " + num(in.surface.uv[0]) + ", " +
                 num(in.surface.uv[1]) + ", " + num(in.surface.uv[2]) + " at its corners";
            break;
        case UvKind::Quadric: {
            const Quadric& q = in.surface.quadric;
            s += "the " + std::string(quadric_kind_name(q.kind)) + " " + quadric_equation(q, false);
            if (q.world_from_model != glm::dmat4(1.0))
                s += " (placed by a transform; work in model space)";
            if (q.kind == QuadricKind::Sphere || q.kind == QuadricKind::Ellipsoid)
                s += " (u = ½ + atan2(y, x)/(2π), v = 1 − acos(z/r)/π)";
            else if (std::isfinite(q.zmin) && std::isfinite(q.zmax))
                s += ", " + num(q.zmin) + " ≤ z ≤ " + num(q.zmax) +
                     " (u = ½ + atan2(y, x)/(2π), v = (z − zmin)/(zmax − zmin))";
            else
                s += " (u = ½ + atan2(y, x)/(2π), v = z)";
            break;
        }
    }
    bool grey = true;
    for (const TexColor& c : t.image.texels) grey = grey && c.x == c.y && c.y == c.z;
    s += " is textured with the " + std::to_string(t.image.width) + " × " +
         std::to_string(t.image.height) + " " + (grey ? "grey " : "") + "texture";
    if (t.image.width * t.image.height <= 64) {
        s += " (rows from the top, v = 1, down):";
        for (int j = t.image.height - 1; j >= 0; --j) {
            s += " [";
            for (int i = 0; i < t.image.width; ++i)
                s += (i ? " " : "") + (grey ? num(t.image.at(i, j).x) : num(t.image.at(i, j)));
            s += "]";
        }
    } else {
        s += " " + t.source;
    }
    s += std::string(", wrap ") + wrap_id(t.wrap) + ", filter " + filter_id(t.filter);
    if (t.filter == TexFilter::Mipmap)
        s += " with a footprint of " + num(in.footprint, 4) +
             " in (u, v) (λ = log₂(footprint · 4); levels blended trilinearly)";
    s += ". Give (u, v) (uv), the texel (i, j) read — for bilinear the lower-left of the four, "
         "texel centres at ((i + ½)/W, (j + ½)/H), j from the bottom — (texel), the filter's "
         "weights (weights) and the colour (color).";
    return s;
}

std::vector<std::string> TextureMap::answer_fields() {
    return {"uv", "texel", "weights", "color"};
}

}  // namespace cg
