// Phong lighting exam problems: "compute the Blinn-Phong colour at P". The point sits at a
// small integer position with an axis normal (now and then an unnormalised one such as
// (0, 0, 2)); the eye and the point lights lie along 3-4-5 directions from it, so v and l are
// short decimals such as (0.6, 0, 0.8); coefficients are tenths, shininess one of the usual
// exponents. One or two lights, now and then directional, attenuated with (1, 0.1, 0.01)-style
// constants, coloured, or behind the surface (it adds nothing). Mostly Blinn-Phong, sometimes
// classic Phong.
#include <array>

#include "core/format.hpp"
#include "rays/phong_lighting.hpp"

namespace cg {

namespace {

using glm::dvec3;

template <class T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& values) {
    return values[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(N) - 1))];
}

double tenth(Rng& rng, int lo, int hi) {
    return static_cast<double>(rng.integer(lo, hi)) / 10;
}

// A 3-4-5 direction in the upper half-space z ≥ 0 (before turning to the normal's frame).
dvec3 nice_up(Rng& rng) {
    static const std::array<dvec3, 9> dirs{{{0, 0, 1},
                                            {0.6, 0, 0.8},
                                            {-0.6, 0, 0.8},
                                            {0, 0.6, 0.8},
                                            {0, -0.8, 0.6},
                                            {0.8, 0, 0.6},
                                            {-0.8, 0, 0.6},
                                            {0.48, 0.64, 0.6},
                                            {0, 0.8, 0.6}}};
    return pick(rng, dirs);
}

// The world axis the normal points along, and a map from "up = z" to it.
dvec3 turn(dvec3 v, int axis, double sign) {
    switch (axis) {
        case 0:
            return {sign * v.z, v.x, v.y};
        case 1:
            return {v.y, sign * v.z, v.x};
        default:
            return {v.x, v.y, sign * v.z};
    }
}

std::string color_text(const PhongLighting::Color& c, bool rgb) {
    return rgb ? num(c) : num(c.x);
}

}  // namespace

PhongLighting::Input PhongLighting::exam_input(Rng& rng) {
    Input in;
    in.model = rng.chance(0.75) ? Model::BlinnPhong : Model::Phong;
    in.point = {static_cast<double>(rng.integer(-2, 2)), static_cast<double>(rng.integer(-2, 2)),
                static_cast<double>(rng.integer(-2, 2))};
    const int axis = rng.chance(0.6) ? 2 : static_cast<int>(rng.integer(0, 2));
    const double sign = rng.chance(0.8) ? 1 : -1;
    in.normal = turn({0, 0, rng.chance(0.2) ? 2.0 : 1.0}, axis, sign);
    in.eye = in.point + static_cast<double>(rng.integer(1, 4)) * 5 * turn(nice_up(rng), axis, sign);
    in.rgb = rng.chance(0.2);
    auto coefficient = [&] {
        if (!in.rgb) return Color(tenth(rng, 1, 9));
        return Color(tenth(rng, 0, 10), tenth(rng, 0, 10), tenth(rng, 0, 10));
    };
    in.ambient = Color(pick(rng, std::array<double, 4>{0.1, 0.2, 0.5, 1}));
    in.material.ka = coefficient();
    in.material.kd = coefficient();
    in.material.ks = coefficient();
    in.material.shininess = pick(rng, std::array<double, 7>{1, 2, 4, 5, 10, 20, 50});
    const int n_lights = rng.chance(0.7) ? 1 : 2;
    for (int i = 0; i < n_lights; ++i) {
        Light L;
        dvec3 dir = nice_up(rng);
        if (rng.chance(0.12)) dir.z = -dir.z;  // behind the surface
        dir = turn(dir, axis, sign);
        L.intensity = in.rgb ? Color(tenth(rng, 2, 10), tenth(rng, 2, 10), tenth(rng, 2, 10))
                             : Color(pick(rng, std::array<double, 4>{1, 1, 0.8, 0.5}));
        if (rng.chance(0.25)) {
            L.directional = true;
            L.direction = -static_cast<double>(rng.integer(1, 2)) * 5 * dir;
        } else {
            L.position = in.point + static_cast<double>(rng.integer(1, 3)) * 5 * dir;
            if (rng.chance(0.3))
                L.attenuation =
                    pick(rng, std::array<dvec3, 3>{{{1, 0.1, 0.01}, {0.5, 0.1, 0}, {1, 0, 0.04}}});
        }
        in.lights.push_back(L);
    }
    return in;
}

std::string PhongLighting::question(const Input& in) {
    const bool rgb = in.rgb;
    std::string q = std::string("Compute the ") +
                    (in.model == Model::BlinnPhong ? "Blinn-Phong" : "Phong") +
                    " colour at P = " + num(in.point) + " with normal " + num(in.normal) +
                    ", seen from the eye E = " + num(in.eye) +
                    ". Ambient light I_a = " + color_text(in.ambient, rgb) +
                    "; material k_a = " + color_text(in.material.ka, rgb) +
                    ", k_d = " + color_text(in.material.kd, rgb) +
                    ", k_s = " + color_text(in.material.ks, rgb) +
                    ", shininess p = " + num(in.material.shininess) + ". ";
    for (std::size_t i = 0; i < in.lights.size(); ++i) {
        const Light& L = in.lights[i];
        q += "Light " + std::to_string(i) + ": ";
        if (L.directional)
            q += "directional, its light travelling along " + num(L.direction);
        else
            q += "a point light at " + num(L.position);
        q += ", intensity " + color_text(L.intensity, rgb);
        if (!L.directional && L.attenuation != dvec3(1, 0, 0))
            q += ", attenuated by 1/(c1 + c2 r + c3 r²) with (c1, c2, c3) = " + num(L.attenuation);
        q += ". ";
    }
    q += "Give the ambient, diffuse and specular terms (summed over the lights) and the "
         "intensity" +
         std::string(rgb ? " as [r, g, b]" : "") +
         ". Negative dot products count as 0, and a light behind the surface adds no highlight.";
    return q;
}

std::vector<std::string> PhongLighting::answer_fields() {
    return {"ambient", "diffuse", "specular", "intensity"};
}

}  // namespace cg
