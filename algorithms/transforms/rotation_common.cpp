#include "transforms/rotation_common.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/format.hpp"

namespace cg::rot {

using glm::dmat3;
using glm::dvec3;

double deg(double radians) {
    return radians * (180.0 / std::numbers::pi);
}
double rad(double degrees) {
    return degrees * (std::numbers::pi / 180.0);
}

CosSin cos_sin_deg(double d) {
    double r = std::fmod(d, 360.0);  // exact
    if (r < 0) r += 360.0;
    if (r >= 360.0) r -= 360.0;  // −1e-300 + 360 rounds to 360
    if (std::fmod(r, 30.0) == 0) {
        static const double h3 = std::sqrt(3.0) / 2;
        static const double sine[12] = {0, 0.5, h3, 1, h3, 0.5, 0, -0.5, -h3, -1, -h3, -0.5};
        const int k = static_cast<int>(r / 30);
        return {sine[(k + 3) % 12], sine[k]};
    }
    if (std::fmod(r, 45.0) == 0) {
        static const double h2 = std::sqrt(0.5);
        const int k = static_cast<int>(r / 45);  // 1, 3, 5 or 7
        return {k == 1 || k == 7 ? h2 : -h2, k < 4 ? h2 : -h2};
    }
    const double x = rad(r > 180 ? r - 360 : r);
    return {std::cos(x), std::sin(x)};
}

double wrap_deg(double d) {
    double r = std::fmod(d, 360.0);
    if (r > 180) r -= 360;
    if (r <= -180) r += 360;
    return r == 0 ? 0.0 : r;  // no −0
}

char axis_name(int axis) {
    return static_cast<char>('x' + axis);
}

dmat3 rotation(int axis, CosSin cs) {
    // R e_j = c e_j + s e_k, R e_k = −s e_j + c e_k with (i, j, k) a cyclic order of x, y, z.
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    dmat3 m(1.0);
    m[j][j] = cs.c;
    m[j][k] = cs.s;
    m[k][j] = -cs.s;
    m[k][k] = cs.c;
    return m;
}

std::vector<std::vector<double>> rows3(const dmat3& m) {
    return {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}};
}

std::vector<std::vector<double>> rows4(const dmat3& m) {
    return {{m[0][0], m[1][0], m[2][0], 0},
            {m[0][1], m[1][1], m[2][1], 0},
            {m[0][2], m[1][2], m[2][2], 0},
            {0, 0, 0, 1}};
}

double clean(double x) {
    return std::fabs(x) < 1e-15 ? 0.0 : x;
}

std::string matrix_text(const dmat3& m, int digits) {
    std::string t = "[";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " " : "") + num(clean(m[c][r]), digits);
        t += r < 2 ? "; " : "]";
    }
    return t;
}

std::string matrix_tex(const dmat3& m, bool homogeneous, int digits) {
    const int n = homogeneous ? 4 : 3;
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const double v = r < 3 && c < 3 ? m[c][r] : (r == c ? 1.0 : 0.0);
            t += (c ? " & " : "") + tex(clean(v), digits);
        }
        t += r + 1 < n ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

std::string vector_tex(dvec3 v, int digits) {
    return "\\begin{bmatrix} " + tex(clean(v.x), digits) + " \\\\ " + tex(clean(v.y), digits) +
           " \\\\ " + tex(clean(v.z), digits) + " \\end{bmatrix}";
}

double max_diff(const dmat3& a, const dmat3& b) {
    double d = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) d = std::max(d, std::fabs(a[c][r] - b[c][r]));
    return d;
}

dvec3 perpendicular(dvec3 n) {
    const dvec3 a = glm::abs(n);
    const dvec3 e = a.x <= a.y && a.x <= a.z ? dvec3(1, 0, 0)
                    : a.y <= a.z             ? dvec3(0, 1, 0)
                                             : dvec3(0, 0, 1);
    return glm::normalize(glm::cross(n, e));
}

// ---- the house ----

namespace {

struct HouseFace {
    std::vector<dvec3> points;  // local coordinates, counter-clockwise seen from outside
    std::uint32_t rgba;
};

const std::vector<HouseFace>& house_faces() {
    constexpr std::uint32_t wall = 0xd9c9a3ff, roof = 0xb5523bff, front = 0xe8b04bff,
                            door = 0x5a3d2bff;
    static const std::vector<HouseFace> faces = {
        {{{-.5, -.45, .35}, {.5, -.45, .35}, {.5, .15, .35}, {0, .5, .35}, {-.5, .15, .35}}, front},
        {{{-.5, .15, -.35}, {0, .5, -.35}, {.5, .15, -.35}, {.5, -.45, -.35}, {-.5, -.45, -.35}},
         wall},
        {{{.5, -.45, .35}, {.5, -.45, -.35}, {.5, .15, -.35}, {.5, .15, .35}}, wall},
        {{{-.5, -.45, -.35}, {-.5, -.45, .35}, {-.5, .15, .35}, {-.5, .15, -.35}}, wall},
        {{{-.5, -.45, -.35}, {.5, -.45, -.35}, {.5, -.45, .35}, {-.5, -.45, .35}}, wall},
        {{{-.5, .15, .35}, {.5, .15, .35}, {.5, .5, 0}, {-.5, .5, 0}}, roof},
        {{{.5, .15, -.35}, {-.5, .15, -.35}, {-.5, .5, 0}, {.5, .5, 0}}, roof},
        {{{-.12, -.45, .352}, {.12, -.45, .352}, {.12, -.1, .352}, {-.12, -.1, .352}}, door},
    };
    return faces;
}

dvec3 place(const HousePlacement& h, dvec3 p) {
    return h.centre + h.size * (p.x * h.right + p.y * h.up + p.z * h.front);
}

}  // namespace

void draw_house(Scene& scene, const HousePlacement& h, const dmat3& transform, bool ghost) {
    for (const HouseFace& f : house_faces()) {
        Face3 face;
        for (const dvec3& p : f.points) face.points.push_back(transform * place(h, p));
        if (ghost) {
            face.style = {Role::Construction, 1.0f, true, 0};
            face.alpha = 0.08f;
        } else {
            face.style = {Role::Subject, 1.0f, false, f.rgba};
            face.alpha = 0.85f;
            face.two_sided = false;
        }
        scene.faces3.push_back(std::move(face));
    }
}

std::vector<dvec3> house_points(const HousePlacement& h) {
    std::vector<dvec3> out;
    for (const HouseFace& f : house_faces())
        for (const dvec3& p : f.points) out.push_back(place(h, p));
    return out;
}

void draw_arc(Scene& scene, dvec3 centre, dvec3 normal, dvec3 start, double radius, double from_deg,
              double to_deg, Style style, bool arrow, const std::string& label) {
    const dvec3 v = glm::cross(normal, start);
    const int n = std::max(2, static_cast<int>(std::ceil(std::fabs(to_deg - from_deg) / 7.5)));
    auto at = [&](double t) {
        const double a = rad(from_deg + (to_deg - from_deg) * t);
        return centre + radius * (std::cos(a) * start + std::sin(a) * v);
    };
    for (int i = 0; i < n; ++i) {
        const bool last = i + 1 == n;
        scene.segments3.push_back({at(double(i) / n), at(double(i + 1) / n),
                                   i == n / 2 ? label : "", style, arrow && last});
    }
}

void draw_circle(Scene& scene, dvec3 centre, dvec3 normal, double radius, Style style,
                 int segments) {
    const dvec3 u = perpendicular(normal), v = glm::cross(normal, u);
    for (int i = 0; i < segments; ++i) {
        const double a = 2 * std::numbers::pi * i / segments,
                     b = 2 * std::numbers::pi * (i + 1) / segments;
        scene.segments3.push_back({centre + radius * (std::cos(a) * u + std::sin(a) * v),
                                   centre + radius * (std::cos(b) * u + std::sin(b) * v), "", style,
                                   false});
    }
}

}  // namespace cg::rot

namespace cg::rot {

bool valid_order(const std::string& order) {
    return order.size() == 3 && order.find_first_not_of("xyz") == std::string::npos &&
           order[0] != order[1] && order[1] != order[2] && order[0] != order[2];
}

glm::dmat3 euler_matrix(const std::string& order, glm::dvec3 angles_deg) {
    glm::dmat3 m(1.0);
    for (int n = 0; n < 3; ++n) m = rotation(order[n] - 'x', cos_sin_deg(angles_deg[n])) * m;
    return m;
}

glm::dvec3 euler_xyz_of(const glm::dmat3& m) {
    // R = R_z(c) R_y(b) R_x(a): row 2 is (−sin b, cos b sin a, cos b cos a), column 0 is
    // (cos c cos b, sin c cos b, −sin b).
    const double cb = std::hypot(m[0][0], m[0][1]);
    const double b = std::atan2(-m[0][2], cb);
    if (cb < 1e-12) {  // locked: only c − a (b = 90°) or c + a (b = −90°) is defined; a = 0
        const double c = std::atan2(-m[1][0], m[1][1]);
        return {0.0, wrap_deg(deg(b)), wrap_deg(deg(c))};
    }
    return {wrap_deg(deg(std::atan2(m[1][2], m[2][2]))), deg(b),
            wrap_deg(deg(std::atan2(m[0][1], m[0][0])))};
}

}  // namespace cg::rot
