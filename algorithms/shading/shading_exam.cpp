// Shading exam problems: "what colour does pixel (i, j) get?" under one of the three models.
// The light is directional and shines straight into the screen (its light travels along
// (0, 0, 1), so l = (0, 0, −1)), there is no highlight (k_s = 0), and the ambient and diffuse
// coefficients are tenths: a unit normal n then lights to k_a + k_d·max(−n_z, 0), and the
// problem is the interpolation, not the lighting model.
//   - Gouraud and Phong: one right triangle with legs of 8 pixels, so the barycentric
//     coordinates of a pixel centre are sixteenths; 3-4-5 normals at the vertices ((0, 0, −1),
//     (0.6, 0, −0.8), (0, 0.8, −0.6), …, given unnormalised as (3, 0, −4) now and then).
//   - flat: a square of side 8 cut along its diagonal into two triangles whose planes rise by
//     0.75 per pixel along x or y (face normals (0.6, 0, −0.8) and the like) or lie flat.
// The pixel asked about is inside a triangle, off its edges; about one problem in ten asks
// about a pixel no triangle covers (the answer is none).
#include <array>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "shading/shading.hpp"

namespace cg {

namespace {

using glm::dvec3;

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

PhongLighting::Input exam_lighting(Rng& rng, dvec3 eye) {
    PhongLighting::Input L;
    L.model = PhongLighting::Model::Phong;
    L.eye = eye;
    L.ambient = dvec3(1.0);
    L.material.ka = dvec3(pick(rng, std::array<double, 3>{0, 0.1, 0.2}));
    L.material.kd = dvec3(pick(rng, std::array<double, 3>{0.5, 0.8, 1}));
    L.material.ks = dvec3(0.0);
    L.material.shininess = 1;
    PhongLighting::Light light;
    light.directional = true;
    light.direction = {0, 0, 1};
    light.intensity = dvec3(1.0);
    L.lights.push_back(light);
    return L;
}

// A pixel no triangle covers (for the "none" problems).
std::array<long long, 2> outside_pixel(Rng& rng, const Shading::Input& in) {
    const Shading::Result r = Shading::render(in);
    std::vector<std::array<long long, 2>> empty;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i)
            if (r.at(i, j).triangle < 0) empty.push_back({i, j});
    if (empty.empty()) return in.pixel;
    return empty[static_cast<std::size_t>(
        rng.integer(0, static_cast<long long>(empty.size()) - 1))];
}

Shading::Input smooth_problem(Rng& rng, Shading::Model model) {
    Shading::Input in;
    in.width = 12;
    in.height = 10;
    in.model = model;
    const double x0 = static_cast<double>(rng.integer(1, 3)), y0 = 1;
    // The right angle at a corner of the 8 × 8 square: (sx, sy) = which way the legs go.
    const double sx = rng.chance(0.5) ? 1 : -1, sy = rng.chance(0.5) ? 1 : -1;
    const dvec3 corner{sx > 0 ? x0 : x0 + 8, sy > 0 ? y0 : y0 + 8, 0};
    const double z = static_cast<double>(rng.integer(5, 10));
    in.mesh.vertices = {corner + dvec3(0, 0, z), corner + dvec3(8 * sx, 0, z + 2),
                        corner + dvec3(0, 8 * sy, z + 4)};
    static const std::array<dvec3, 9> normals{{{0, 0, -1},
                                               {3, 0, -4},
                                               {-3, 0, -4},
                                               {0, 3, -4},
                                               {0, -3, -4},
                                               {4, 0, -3},
                                               {0, 4, -3},
                                               {-4, 0, -3},
                                               {0, -4, -3}}};
    for (int k = 0; k < 3; ++k) {
        dvec3 n = pick(rng, normals);
        if (!rng.chance(0.3)) n /= glm::length(n);  // unit (0.6, 0, −0.8), mostly
        in.mesh.normals.push_back(n);
    }
    in.mesh.triangles = {{0, 1, 2}};
    in.lighting = exam_lighting(rng, {6, 5, -20});
    in.has_pixel = true;
    // A centre strictly inside: legs' coordinates u, v (centres at halves) with u + v < 8.
    const long long u = rng.integer(0, 6), v = rng.integer(0, 6 - u);
    in.pixel = {static_cast<long long>(corner.x + sx * (u + 0.5) - 0.5),
                static_cast<long long>(corner.y + sy * (v + 0.5) - 0.5)};
    return in;
}

Shading::Input flat_problem(Rng& rng) {
    Shading::Input in;
    in.width = 12;
    in.height = 10;
    in.model = Shading::Model::Flat;
    const double x0 = static_cast<double>(rng.integer(1, 3)), y0 = 1;
    // Plane gradients (dz/dx, dz/dy) of the lower-right and upper-left triangles, equal sums
    // so that they meet along the diagonal.
    static const std::array<std::array<glm::dvec2, 2>, 6> gradients{{
        {{{0.75, 0}, {0, 0.75}}},
        {{{0, 0.75}, {0.75, 0}}},
        {{{-0.75, 0}, {0, -0.75}}},
        {{{0, -0.75}, {-0.75, 0}}},
        {{{0.75, 0}, {0.75, 0}}},
        {{{0, 0}, {0, 0}}},
    }};
    const auto& g = pick(rng, gradients);
    const double z = static_cast<double>(rng.integer(10, 14));
    const double z11 = z + 8 * (g[0].x + g[0].y);
    in.mesh.vertices = {{x0, y0, z},
                        {x0 + 8, y0, z + 8 * g[0].x},
                        {x0 + 8, y0 + 8, z11},
                        {x0, y0 + 8, z + 8 * g[1].y}};
    in.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    in.lighting = exam_lighting(rng, {6, 5, -20});
    in.has_pixel = true;
    // Off the diagonal: u ≠ v in the square's own pixel coordinates.
    long long u = rng.integer(0, 7), v = rng.integer(0, 7);
    if (u == v) v = (v + 1 + rng.integer(0, 6)) % 8;
    in.pixel = {static_cast<long long>(x0) + u, static_cast<long long>(y0) + v};
    return in;
}

std::string lighting_text(const PhongLighting::Input& L) {
    auto c = [&](const dvec3& v) { return L.rgb ? num(v) : num(v.x); };
    std::string t = "The eye is at " + num(L.eye) + "; ambient light I_a = " + c(L.ambient) +
                    "; the material has k_a = " + c(L.material.ka) + ", k_d = " + c(L.material.kd) +
                    ", k_s = " + c(L.material.ks);
    if (L.material.ks != dvec3(0.0))
        t += ", shininess p = " + num(L.material.shininess) + " (" +
             (L.model == PhongLighting::Model::Phong ? "Phong" : "Blinn-Phong") + " highlight)";
    t += ".";
    for (std::size_t i = 0; i < L.lights.size(); ++i) {
        const auto& light = L.lights[i];
        t += " Light " + std::to_string(i) + ": " +
             (light.directional ? "directional, its light travelling along " + num(light.direction)
                                : "a point light at " + num(light.position)) +
             ", intensity " + c(light.intensity);
        if (!light.directional && light.attenuation != dvec3(1, 0, 0))
            t += ", attenuated by 1/(c1 + c2 r + c3 r²), (c1, c2, c3) = " + num(light.attenuation);
        t += ".";
    }
    return t;
}

}  // namespace

Shading::Input Shading::exam_input(Rng& rng) {
    const long long kind = rng.integer(0, 2);
    Input in = kind == 0   ? flat_problem(rng)
               : kind == 1 ? smooth_problem(rng, Model::Gouraud)
                           : smooth_problem(rng, Model::Phong);
    if (rng.chance(0.1)) in.pixel = outside_pixel(rng, in);
    return in;
}

std::string Shading::question(const Input& in) {
    const auto& mesh = in.mesh;
    std::string q = "A mesh on a " + std::to_string(in.width) + " × " + std::to_string(in.height) +
                    " image (x, y in pixels with y up, z the depth: smaller is nearer). ";
    if (mesh.vertices.size() <= 12) {
        q += "Vertices: ";
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
            q += (v ? ", " : "") + std::string("V") + std::to_string(v) + " = " +
                 num(mesh.vertices[v]);
        q += ". ";
        if (!mesh.normals.empty()) {
            q += "Vertex normals: ";
            for (std::size_t v = 0; v < mesh.normals.size(); ++v)
                q += (v ? ", " : "") + std::string("n") + std::to_string(v) + " = " +
                     num(mesh.normals[v]);
            q += ". ";
        }
    } else {
        q += std::to_string(mesh.vertices.size()) + " vertices (see the input)" +
             (mesh.normals.empty() ? "" : ", with normals") + ". ";
    }
    if (mesh.triangles.size() <= 12) {
        q += "Triangles: ";
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
            q += (k ? ", " : "") + std::string("T") + std::to_string(k) + " = (V" +
                 std::to_string(mesh.triangles[k][0]) + ", V" +
                 std::to_string(mesh.triangles[k][1]) + ", V" +
                 std::to_string(mesh.triangles[k][2]) + ")";
        q += ". ";
    } else {
        q += std::to_string(mesh.triangles.size()) + " triangles. ";
    }
    q += lighting_text(in.lighting) + " ";
    switch (in.model) {
        case Model::Flat:
            q += "Flat shading: each triangle is lit once, at its centroid, with its face normal "
                 "(P1 − P0) × (P2 − P0) normalised and turned toward the viewer (negative z). ";
            break;
        case Model::Gouraud:
            q += "Gouraud shading: light each vertex with its normal" +
                 std::string(mesh.normals.empty()
                                 ? " (the area-weighted average of its faces' normals)"
                                 : " (normalised)") +
                 ", then interpolate the colours linearly (barycentrically) to each pixel "
                 "centre. ";
            break;
        case Model::Phong:
            q +=
                "Phong shading: interpolate the unit vertex normals" +
                std::string(mesh.normals.empty() ? " (area-weighted averages of the faces')" : "") +
                " linearly (barycentrically) to the pixel centre, normalise, and light the "
                "surface point there (z interpolated too). ";
            break;
    }
    const auto chosen = in.has_pixel ? std::array<int, 2>{static_cast<int>(in.pixel[0]),
                                                          static_cast<int>(in.pixel[1])}
                                     : render(in).pixel;
    const std::string pixel =
        "(" + std::to_string(chosen[0]) + ", " + std::to_string(chosen[1]) + ")";
    q += "A pixel (i, j) is covered by a triangle when its centre (i + ½, j + ½) is inside it "
         "(the top-left rule on edges); where triangles overlap, the smaller z wins. What colour "
         "does pixel " +
         pixel +
         " get (none if no triangle covers it), and how many lighting evaluations does the "
         "whole image take?";
    return q;
}

std::vector<std::string> Shading::answer_fields() {
    return {"pixel_color", "evaluations"};
}

}  // namespace cg
