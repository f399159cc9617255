// Sections: [helpers] [geometry] [spec] [validate] [advance] [narrate] [result and render]
// (the picture: shadow_map_draw.cpp)
#include "shadows/shadow_map.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec3;
using glm::dvec4;
using Phase = ShadowMap::Phase;
using Verdict = ShadowMap::Verdict;
using Frame = ShadowMap::Frame;
using Input = ShadowMap::Input;
using State = ShadowMap::State;

constexpr double kPi = 3.14159265358979323846;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineSetup = 1,
    kLineClear,
    kLineRasterise,
    kLineEyeRay,
    kLineTransform,
    kLineTexel,
    kLineCompare,
    kLineExact,
    kLineSummary
};

std::vector<double> vec3(const dvec3& v) {
    return {v.x, v.y, v.z};
}
std::vector<double> vec4(const dvec4& v) {
    return {v.x, v.y, v.z, v.w};
}
std::vector<std::vector<double>> rows4(const dmat4& m) {
    std::vector<std::vector<double>> r(4);
    for (int i = 0; i < 4; ++i) r[i] = {m[0][i], m[1][i], m[2][i], m[3][i]};
    return r;
}
std::string v4text(const dvec4& v, int digits = 4) {
    return "(" + num(v.x, digits) + ", " + num(v.y, digits) + ", " + num(v.z, digits) + ", " +
           num(v.w, digits) + ")";
}
std::string mtext(const dmat4& m, int digits = 4) {
    std::string t = "[";
    for (int i = 0; i < 4; ++i) {
        t += i ? "; " : "";
        for (int j = 0; j < 4; ++j) t += (j ? ", " : "") + num(m[j][i], digits);
    }
    return t + "]";
}
std::string mtex(const dmat4& m, int digits = 4) {
    std::string t = "\\begin{bmatrix}";
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) t += (j ? " & " : "") + tex(m[j][i], digits);
        t += i < 3 ? " \\\\ " : "";
    }
    return t + "\\end{bmatrix}";
}

// ---- [geometry] -----------------------------------------------------------------------------

// Möller–Trumbore, both sides, edges included: the ray parameter t of o + t d, or false.
bool hit(const ShadowMap::Triangle& tri, const dvec3& o, const dvec3& d, double& t) {
    const dvec3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const dvec3 pv = glm::cross(d, e2);
    const double det = glm::dot(e1, pv);
    if (det == 0 || !std::isfinite(det)) return false;
    const double inv = 1.0 / det;
    const dvec3 tv = o - tri[0];
    const double u = glm::dot(tv, pv) * inv;
    if (!(u >= 0 && u <= 1)) return false;
    const dvec3 qv = glm::cross(tv, e1);
    const double v = glm::dot(d, qv) * inv;
    if (!(v >= 0 && u + v <= 1)) return false;
    t = glm::dot(e2, qv) * inv;
    return std::isfinite(t);
}

// Whether triangle b lies in triangle a's plane (the same surface, for telling acne apart).
bool coplanar(const ShadowMap::Triangle& a, const ShadowMap::Triangle& b) {
    const dvec3 n = glm::cross(a[1] - a[0], a[2] - a[0]);
    const double len = glm::length(n);
    if (!(len > 0)) return false;
    double size = 0;
    for (const auto& p : a) size = std::max(size, glm::length(p - a[0]));
    for (const auto& q : b)
        if (std::fabs(glm::dot(n / len, q - a[0])) > 1e-9 * (size + glm::length(q - a[0])))
            return false;
    return true;
}

}  // namespace

const char* ShadowMap::verdict_id(Verdict v) {
    switch (v) {
        case Verdict::Pending:
            return "pending";
        case Verdict::Background:
            return "background";
        case Verdict::Outside:
            return "outside";
        case Verdict::Lit:
            return "lit";
        case Verdict::Shadow:
            return "shadow";
        case Verdict::Acne:
            return "acne";
        case Verdict::FalseShadow:
            return "false-shadow";
        case Verdict::FalseLit:
            return "false-lit";
    }
    return "pending";
}

char ShadowMap::verdict_char(Verdict v) {
    switch (v) {
        case Verdict::Pending:
            return '?';
        case Verdict::Background:
            return '.';
        case Verdict::Outside:
            return 'o';
        case Verdict::Lit:
            return 'L';
        case Verdict::Shadow:
            return 'S';
        case Verdict::Acne:
            return 'A';
        case Verdict::FalseShadow:
            return 'F';
        case Verdict::FalseLit:
            return 'K';
    }
    return '?';
}

namespace {
Frame look_at(const ShadowMap::Camera& c) {
    Frame f;
    f.origin = c.position;
    const dvec3 v = c.target - c.position;
    const dvec3 up = c.up / std::max({std::fabs(c.up.x), std::fabs(c.up.y), std::fabs(c.up.z)});
    f.forward = glm::normalize(v / std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}));
    f.right = glm::normalize(glm::cross(f.forward, up));
    f.up = glm::cross(f.right, f.forward);
    return f;
}
}  // namespace

// The light ray through texel (i, j)'s centre: a parallel ray from the light's plane
// (directional) or a ray from the light's position (spot) with d · f = 1, so that its t is the
// depth along f in both cases.
void ShadowMap::texel_ray(const Frame& f, int n, int i, int j, dvec3& o, dvec3& d) {
    const double x = (2.0 * (i + 0.5) / n - 1.0) * f.half;
    const double y = (2.0 * (j + 0.5) / n - 1.0) * f.half;
    if (f.perspective) {
        o = f.origin;
        d = f.forward + x * f.right + y * f.up;
    } else {
        o = f.origin + x * f.right + y * f.up;
        d = f.forward;
    }
}

ShadowMap::Frame ShadowMap::light_frame(const Light& l) {
    Frame f = look_at(l);
    f.perspective = l.type == LightType::Spot;
    f.half = f.perspective ? std::tan(l.fov_deg * kPi / 360.0) : l.extent;
    return f;
}

ShadowMap::Frame ShadowMap::eye_frame(const Eye& e) {
    Frame f = look_at(e);
    f.perspective = true;
    f.half = std::tan(e.fov_deg * kPi / 360.0);
    return f;
}

dmat4 ShadowMap::view_matrix(const Frame& f) {
    dmat4 m(1.0);  // m[column][row]
    const dvec3 rows[3] = {f.right, f.up, -f.forward};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[c][r] = rows[r][c];
        m[3][r] = -glm::dot(rows[r], f.origin);
    }
    return m;
}

int ShadowMap::rasterise(const Input& in, const Frame& light, int k, std::vector<double>& depth,
                         std::vector<int>& owner, int& written) {
    const int n = in.map_size;
    const auto& tri = in.triangles[k];
    int covered = 0;
    written = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            dvec3 o, d;
            texel_ray(light, n, i, j, o, d);
            double t;
            if (!hit(tri, o, d, t) || t < in.light.near || t > in.light.far) continue;
            ++covered;
            double& stored = depth[std::size_t(j) * n + i];
            if (t < stored) {
                stored = t;
                owner[std::size_t(j) * n + i] = k;
                ++written;
            }
        }
    return covered;
}

int ShadowMap::nearest(const Input& in, const dvec3& o, const dvec3& d, double& t) {
    int best = -1;
    t = 0;
    for (std::size_t k = 0; k < in.triangles.size(); ++k) {
        double tk;
        if (hit(in.triangles[k], o, d, tk) && tk > 0 && (best < 0 || tk < t)) t = tk, best = int(k);
    }
    return best;
}

ShadowMap::Lookup ShadowMap::lookup(const Input& in, const Frame& light, const Frame& eye,
                                    const dmat4& light_from_world, const std::vector<double>& depth,
                                    const std::vector<int>& owner, int i, int j) {
    Lookup l;
    l.i = i, l.j = j;
    const int w = in.eye.width, h = in.eye.height;
    const double aspect = double(w) / h;
    const double x = (2.0 * (i + 0.5) / w - 1.0) * eye.half * aspect;
    const double y = (2.0 * (j + 0.5) / h - 1.0) * eye.half;
    const dvec3 dir = eye.forward + x * eye.right + y * eye.up;
    double t;
    l.tri = nearest(in, eye.origin, dir, t);
    if (l.tri < 0) {
        l.verdict = Verdict::Background;
        return l;
    }
    l.p = eye.origin + t * dir;
    l.p_light = light_from_world * dvec4(l.p, 1.0);
    l.d_p = -l.p_light.z;
    const int n = in.map_size;
    bool inside = l.d_p >= in.light.near && l.d_p <= in.light.far;
    if (inside) {
        const double scale = light.perspective ? l.d_p * light.half : light.half;
        // A tiny extent can send a far-off point's coordinates past a double's range: it is
        // off the map either way, and the numbers stay finite for the narration.
        l.s = std::clamp((l.p_light.x / scale + 1) / 2, -1e300, 1e300);
        l.t = std::clamp((l.p_light.y / scale + 1) / 2, -1e300, 1e300);
        inside = l.s >= 0 && l.s < 1 && l.t >= 0 && l.t < 1;
    }
    if (!inside) {
        l.verdict = Verdict::Outside;
        return l;
    }
    l.ti = std::min(int(l.s * n), n - 1);
    l.tj = std::min(int(l.t * n), n - 1);
    const std::size_t at = std::size_t(l.tj) * n + l.ti;
    l.d_map = depth[at];
    l.map_tri = owner[at];
    l.map_shadow = l.d_p - in.bias > l.d_map;

    // The exact answer: the shadow ray from P toward the light, against every other triangle,
    // over the distance to the light (its plane, for a directional light).
    const dvec3 to = light.perspective ? light.origin - l.p : -light.forward * l.d_p;
    for (std::size_t k = 0; k < in.triangles.size() && !l.exact_shadow; ++k) {
        if (int(k) == l.tri) continue;
        double tk;
        if (hit(in.triangles[k], l.p, to, tk) && tk > 1e-9 && tk < 1) {
            l.exact_shadow = true;
            l.blocker = int(k);
        }
    }
    if (l.map_shadow == l.exact_shadow)
        l.verdict = l.map_shadow ? Verdict::Shadow : Verdict::Lit;
    else if (l.map_shadow)
        l.verdict = l.map_tri >= 0 && coplanar(in.triangles[l.tri], in.triangles[l.map_tri])
                        ? Verdict::Acne
                        : Verdict::FalseShadow;
    else
        l.verdict = Verdict::FalseLit;
    return l;
}

namespace {
void count(ShadowMap::Counts& c, Verdict v) {
    switch (v) {
        case Verdict::Background:
            ++c.background;
            break;
        case Verdict::Outside:
            ++c.outside;
            break;
        case Verdict::Lit:
            ++c.lit;
            break;
        case Verdict::Shadow:
            ++c.shadow;
            break;
        case Verdict::Acne:
            ++c.acne;
            break;
        case Verdict::FalseShadow:
            ++c.false_shadow;
            break;
        case Verdict::FalseLit:
            ++c.false_lit;
            break;
        case Verdict::Pending:
            break;
    }
}
}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ShadowMap::spec() {
    static const Spec spec{
        "shadow-map",
        "Shadow maps: depth from the light, looked up for each point the eye sees",
        "Shadows",
        {
            "light_from_world ← look-at(light);  d = −z_L, the depth along the light's axis",
            "clear the N × N map to far",
            "for each triangle: for each texel whose centre's light ray meets it at d in [near, "
            "far]: map[i, j] ← min(map[i, j], d)",
            "for each eye pixel: P ← the eye ray's nearest hit (none: background)",
            "    P_L ← light_from_world [P, 1];  d_P ← −z_L",
            "    (s, t) ← map coordinates of P_L;  (i, j) ← (⌊s N⌋, ⌊t N⌋)   ▷ outside: lit",
            "    shadow ← d_P − bias > map[i, j]",
            "    check: the shadow ray from P to the light   ▷ acne, false shadow, light leak",
            "the eye image, and how often the map disagreed with the shadow rays",
        },
        {
            {"setup", "the light's frame and light_from_world; the map cleared to far"},
            {"rasterise", "one triangle drawn into the depth map: nearer depths kept"},
            {"background", "the eye ray meets nothing: background"},
            {"outside",
             "P is outside the light's frustum (off the map, or nearer than near / beyond far): "
             "counted lit"},
            {"lit", "d_P − bias ≤ d_map: lit, and the shadow ray agrees"},
            {"shadow", "d_P − bias > d_map: in shadow, and the shadow ray agrees"},
            {"acne",
             "the map says shadow but P's own surface is what the texel holds: shadow acne (the "
             "bias is too small)"},
            {"false-shadow",
             "the map says shadow but the shadow ray reaches the light: the texel is shared with "
             "an occluder's edge (the map's resolution)"},
            {"false-lit",
             "the map says lit but the shadow ray is blocked: light leaking (a bias too large, or "
             "the map's resolution)"},
            {"summary", "the eye image, and the lookups that disagree with the shadow rays"},
        },
        {},  // no sliders
        {
            .predict = {{"lit", {"d_P", "d_map"}},
                        {"shadow", {"i", "j"}},
                        {"rasterise", {"written"}}},
            .mistakes =
                {
                    {"shadow", "i", "swap:j", "swapped i and j: read texel (j, i) of the map"},
                    {"lit", "d_map", "keep",
                     "read d_map of the previous lookup's texel instead of this one's"},
                    {"lit", "", "event:acne",
                     "compared d_P > d_map without the bias: the surface shadows itself"},
                    {"shadow", "d_P", "copy:z_L",
                     "took z_L itself as the depth, forgetting that the light looks along −z"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_number(double v, const std::string& field, double limit = ShadowMap::kMaxCoord) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
    if (std::fabs(v) > limit)
        throw InputError(field, "is too large (" + given(v) + "): at most " + given(limit) +
                                    " in size; scale the scene down");
}
void check_point(const dvec3& p, const std::string& field) {
    for (int i = 0; i < 3; ++i) check_number(p[i], field + "[" + std::to_string(i) + "]");
}
void check_camera(const ShadowMap::Camera& c, const std::string& name) {
    check_point(c.position, name + ".position");
    check_point(c.target, name + ".target");
    check_point(c.up, name + ".up");
    const dvec3 f = c.target - c.position;
    if (f == dvec3(0))
        throw InputError(name + ".target", "must differ from " + name +
                                               ".position: the view direction is target − "
                                               "position");
    if (c.up == dvec3(0)) throw InputError(name + ".up", "must not be the zero vector");
    // Scaled by the largest component first, so that a tiny up (1e-300) normalises.
    auto unit = [](const dvec3& v) {
        return glm::normalize(v / std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}));
    };
    const dvec3 fu = unit(f), uu = unit(c.up);
    if (glm::length(glm::cross(fu, uu)) < 1e-9)
        throw InputError(name + ".up",
                         "is parallel to the view direction (target − position): "
                         "it cannot say which way is up");
}
void check_fov(double fov, const std::string& field) {
    check_number(fov, field);
    if (!(fov > 0 && fov <= 170))
        throw InputError(field, "must be in (0, 170] degrees (got " + given(fov) + ")");
}

}  // namespace

void ShadowMap::validate(const Input& in) {
    if (in.triangles.empty())
        throw InputError("triangles",
                         "must have at least 1 triangle (got none): there is "
                         "nothing to cast or receive a shadow");
    if (in.triangles.size() > kMaxTriangles)
        throw InputError("triangles", "has " + std::to_string(in.triangles.size()) +
                                          " triangles; at most " + std::to_string(kMaxTriangles) +
                                          " are stepped");
    for (std::size_t k = 0; k < in.triangles.size(); ++k) {
        const std::string f = "triangles[" + std::to_string(k) + "]";
        for (int v = 0; v < 3; ++v)
            check_point(in.triangles[k][v], f + "[" + std::to_string(v) + "]");
        const auto& t = in.triangles[k];
        const dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
        const double area = glm::length(glm::cross(e1, e2));
        if (!(area > 1e-12 * glm::length(e1) * glm::length(e2)))
            throw InputError(f,
                             "has zero area (its vertices are collinear or coincide): it "
                             "covers no texel and no pixel");
    }
    const Light& l = in.light;
    check_camera(l, "light");
    if (l.type == LightType::Spot)
        check_fov(l.fov_deg, "light.fov_deg");
    else {
        check_number(l.extent, "light.extent");
        if (!(l.extent > 0))
            throw InputError("light.extent",
                             "must be > 0: the half-width of the light's "
                             "orthographic box (got " +
                                 given(l.extent) + ")");
    }
    check_number(l.near, "light.near");
    check_number(l.far, "light.far");
    if (l.near < 0 || (l.type == LightType::Spot && l.near == 0))
        throw InputError("light.near",
                         l.type == LightType::Spot
                             ? "must be > 0 for a spot light (got " + given(l.near) + ")"
                             : "must be ≥ 0 (got " + given(l.near) + ")");
    if (!(l.far > l.near))
        throw InputError("light.far", "must be greater than light.near (" + given(l.far) + " ≤ " +
                                          given(l.near) + ")");
    if (in.map_size < 1 || in.map_size > kMaxMap)
        throw InputError("map_size", "must be 1 to " + std::to_string(kMaxMap) + " (got " +
                                         std::to_string(in.map_size) + ")");
    check_number(in.bias, "bias", 1e300);
    if (in.bias < 0) throw InputError("bias", "must be ≥ 0 (got " + given(in.bias) + ")");
    check_camera(in.eye, "eye");
    check_fov(in.eye.fov_deg, "eye.fov_deg");
    if (in.eye.width < 1 || in.eye.width > kMaxEye)
        throw InputError("eye.width", "must be 1 to " + std::to_string(kMaxEye) + " pixels (got " +
                                          std::to_string(in.eye.width) + ")");
    if (in.eye.height < 1 || in.eye.height > kMaxEye)
        throw InputError("eye.height", "must be 1 to " + std::to_string(kMaxEye) + " pixels (got " +
                                           std::to_string(in.eye.height) + ")");
}

ShadowMap::State ShadowMap::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void ShadowMap::advance(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Setup: {
            s.light = light_frame(in.light);
            s.eye = eye_frame(in.eye);
            s.light_from_world = view_matrix(s.light);
            const std::size_t n = std::size_t(in.map_size) * in.map_size;
            s.depth.assign(n, in.light.far);
            s.owner.assign(n, -1);
            s.image.assign(std::size_t(in.eye.width) * in.eye.height, Verdict::Pending);
            s.last = Phase::Setup;
            s.phase = Phase::Rasterise;
            return;
        }
        case Phase::Rasterise:
            ++s.k;
            s.covered = rasterise(in, s.light, s.k, s.depth, s.owner, s.written);
            s.last = Phase::Rasterise;
            if (s.k + 1 == int(in.triangles.size())) s.phase = Phase::Lookup;
            return;
        case Phase::Lookup: {
            const int w = in.eye.width;
            const int i = int(s.next_pixel % w), j = int(s.next_pixel / w);
            s.look = lookup(in, s.light, s.eye, s.light_from_world, s.depth, s.owner, i, j);
            s.image[s.next_pixel] = s.look.verdict;
            count(s.counts, s.look.verdict);
            ++s.next_pixel;
            s.last = Phase::Lookup;
            if (s.next_pixel == (long long)s.image.size()) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string texel_text(int i, int j) {
    return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

void narrate_setup(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const bool spot = s.light.perspective;
    info.event = "setup";
    info.line = kLineSetup;
    info.narration =
        std::string(spot ? "A spot light" : "A directional light") + " at " +
        num(in.light.position, 4) + " looking at " + num(in.light.target, 4) +
        ": f = " + num(s.light.forward, 4) + ", r = " + num(s.light.right, 4) +
        ", u = " + num(s.light.up, 4) + "; light_from_world = " + mtext(s.light_from_world) +
        ". The depth is d = −z_L, the distance along f. The " + std::to_string(in.map_size) +
        " × " + std::to_string(in.map_size) + " map covers " +
        (spot ? "a " + num(in.light.fov_deg, 4) + "° pyramid"
              : "a box ±" + num(in.light.extent, 4) + " wide") +
        ", depths " + num(in.light.near, 4) + " to " + num(in.light.far, 4) +
        "; every texel is cleared to far = " + num(in.light.far, 4) + ".";
    info.math = "\\text{light\\_from\\_world} = " + mtex(s.light_from_world);
}

void narrate_rasterise(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "rasterise";
    info.line = kLineRasterise;
    const auto& t = in.triangles[s.k];
    double lo = 1e300, hi = -1e300;
    for (std::size_t q = 0; q < s.owner.size(); ++q)
        if (s.owner[q] == s.k) lo = std::min(lo, s.depth[q]), hi = std::max(hi, s.depth[q]);
    const std::string kk = std::to_string(s.k);
    info.narration =
        "Triangle " + kk + " " + num(t[0], 3) + ", " + num(t[1], 3) + ", " + num(t[2], 3) +
        " seen from the light: it covers " + std::to_string(s.covered) + " texel centre" +
        (s.covered == 1 ? "" : "s") + " and is the nearest surface so far at " +
        std::to_string(s.written) + " of them" +
        (s.written ? " (depths " + num(lo, 4) + (hi > lo ? " to " + num(hi, 4) : "") + ")" : "") +
        "." +
        (s.covered > s.written ? " Where it is farther than what the map holds, it is hidden "
                                 "from the light."
                               : "");
    info.math = "\\text{map}[i, j] \\leftarrow \\min(\\text{map}[i, j],\\, d)";
}

void narrate_lookup(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& l = s.look;
    const std::string px = "Pixel " + texel_text(l.i, l.j);
    if (l.verdict == Verdict::Background) {
        info.event = "background";
        info.line = kLineEyeRay;
        info.narration = px + ": the eye ray meets no triangle: background, nothing to light.";
        return;
    }
    const std::string head = px + " sees P = " + num(l.p, 4) + " on triangle " +
                             std::to_string(l.tri) +
                             "; P_L = light_from_world [P, 1] = " + v4text(l.p_light) +
                             ", d_P = −z_L = " + num(l.d_p, 4);
    info.math = "P_L = \\text{light\\_from\\_world}\\,[P, 1] = (" + tex(l.p_light.x, 4) + ", " +
                tex(l.p_light.y, 4) + ", " + tex(l.p_light.z, 4) + ", 1)";
    if (l.verdict == Verdict::Outside) {
        info.event = "outside";
        info.line = kLineTexel;
        const bool depth_out = l.d_p < in.light.near || l.d_p > in.light.far;
        info.narration =
            head +
            (depth_out ? ", outside [near, far] = [" + num(in.light.near, 4) + ", " +
                             num(in.light.far, 4) + "]"
                       : ", (s, t) = (" + num(l.s, 4) + ", " + num(l.t, 4) + ") off the map") +
            ": outside the light's frustum, the map knows nothing here; counted lit (a renderer "
            "would choose; a spot light's cone gives no light here at all).";
        return;
    }
    const std::string cmp = "d_P − bias = " + num(l.d_p, 4) + " − " + num(in.bias, 4) + " = " +
                            num(l.d_p - in.bias, 4) + (l.map_shadow ? " > " : " ≤ ") +
                            "d_map = " + num(l.d_map, 4);
    const std::string where = head + "; (s, t) = (" + num(l.s, 4) + ", " + num(l.t, 4) +
                              "), texel (i, j) = " + texel_text(l.ti, l.tj) + "; " + cmp;
    info.math += ",\\; d_P - \\text{bias} = " + tex(l.d_p - in.bias, 4) +
                 (l.map_shadow ? " > " : " \\le ") + "d_{map}[" + std::to_string(l.ti) + ", " +
                 std::to_string(l.tj) + "] = " + tex(l.d_map, 4);
    const std::string ray =
        l.exact_shadow ? "the shadow ray is blocked by triangle " + std::to_string(l.blocker)
                       : "the shadow ray reaches the light";
    info.line = kLineCompare;
    switch (l.verdict) {
        case Verdict::Lit:
            info.event = "lit";
            info.narration = where + ": lit; " + ray + ".";
            break;
        case Verdict::Shadow:
            info.event = "shadow";
            info.narration = where +
                             ": in shadow (something nearer the light holds the texel: "
                             "triangle " +
                             std::to_string(l.map_tri) + "); " + ray + ".";
            break;
        case Verdict::Acne:
            info.event = "acne";
            info.line = kLineExact;
            info.narration = where + ": the map says shadow, but " + ray +
                             ". The texel holds P's own surface, sampled at the texel's centre: "
                             "shadow acne — the bias (" +
                             num(in.bias, 4) +
                             ") is smaller than the depth's change across a texel.";
            break;
        case Verdict::FalseShadow:
            info.event = "false-shadow";
            info.line = kLineExact;
            info.narration = where + ": the map says shadow, but " + ray +
                             ". The texel's centre falls on triangle " + std::to_string(l.map_tri) +
                             ", an occluder whose edge crosses the texel: the map's resolution "
                             "(aliasing at the shadow's edge).";
            break;
        case Verdict::FalseLit:
            info.event = "false-lit";
            info.line = kLineExact;
            info.narration =
                where + ": the map says lit, but " + ray + ". " +
                (l.d_p - l.d_map > 0
                     ? "The bias is larger than the gap to the occluder: light leaks (peter "
                       "panning)."
                     : "The texel's centre misses the occluder whose edge crosses it: the map's "
                       "resolution (aliasing at the shadow's edge).");
            break;
        default:
            break;
    }
}

void narrate_summary(const State& s, StepInfo& info) {
    const auto& c = s.counts;
    info.event = "summary";
    info.line = kLineSummary;
    const int wrong = c.acne + c.false_shadow + c.false_lit;
    info.narration = "The eye image: " + std::to_string(c.lit) + " lit, " +
                     std::to_string(c.shadow) + " in shadow, " + std::to_string(c.outside) +
                     " outside the light's frustum, " + std::to_string(c.background) +
                     " background. " + std::to_string(wrong) +
                     " lookups disagree with the shadow rays: " + std::to_string(c.acne) +
                     " acne, " + std::to_string(c.false_shadow) + " false shadows, " +
                     std::to_string(c.false_lit) + " light leaks.";
}

void fill_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.vars = {{"N", (long long)in.map_size}, {"bias", in.bias}};
    if (s.last == Phase::Setup) {
        info.vars.push_back({"f", vec3(s.light.forward)});
        info.vars.push_back({"r", vec3(s.light.right)});
        info.vars.push_back({"u", vec3(s.light.up)});
        info.vars.push_back({"light_from_world", rows4(s.light_from_world)});
        info.vars.push_back({"far", in.light.far});
    } else if (s.last == Phase::Rasterise) {
        info.vars.push_back({"k", (long long)s.k});
        info.vars.push_back({"covered", (long long)s.covered});
        info.vars.push_back({"written", (long long)s.written});
    } else if (s.last == Phase::Lookup) {
        const auto& l = s.look;
        info.vars.push_back({"pixel", std::vector<double>{double(l.i), double(l.j)}});
        if (l.tri >= 0) {
            info.vars.push_back({"P", vec3(l.p)});
            info.vars.push_back({"P_L", vec4(l.p_light)});
            info.vars.push_back({"z_L", l.p_light.z});
            info.vars.push_back({"d_P", l.d_p});
            if (l.d_p >= in.light.near && l.d_p <= in.light.far) {
                info.vars.push_back({"s", l.s});
                info.vars.push_back({"t", l.t});
            }
            if (l.ti >= 0) {
                info.vars.push_back({"i", (long long)l.ti});
                info.vars.push_back({"j", (long long)l.tj});
                info.vars.push_back({"d_map", l.d_map});
                info.vars.push_back({"in shadow", l.map_shadow});
                info.vars.push_back({"shadow ray blocked", l.exact_shadow});
            }
        }
    } else {
        const auto& c = s.counts;
        info.vars.push_back({"lit", (long long)c.lit});
        info.vars.push_back({"shadow", (long long)c.shadow});
        info.vars.push_back({"acne", (long long)c.acne});
        info.vars.push_back({"false_shadow", (long long)c.false_shadow});
        info.vars.push_back({"false_lit", (long long)c.false_lit});
    }
}

}  // namespace

void ShadowMap::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Setup:
            narrate_setup(s, info);
            break;
        case Phase::Rasterise:
            narrate_rasterise(s, info);
            break;
        case Phase::Lookup:
            narrate_lookup(s, info);
            break;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            break;
    }
    fill_vars(s, info);
}

void ShadowMap::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and render] --------------------------------------------------------------------

ShadowMap::Result ShadowMap::result(const State& s) {
    State copy = s;
    return result(std::move(copy));
}

ShadowMap::Result ShadowMap::result(State&& s) {
    Result r;
    r.map_size = s.in->map_size;
    r.width = s.in->eye.width;
    r.height = s.in->eye.height;
    r.depth = std::move(s.depth);
    r.owner = std::move(s.owner);
    r.image = std::move(s.image);
    r.counts = s.counts;
    r.last = s.look;
    r.light_from_world = s.light_from_world;
    return r;
}

ShadowMap::Result ShadowMap::render(const Input& in) {
    Result r;
    r.map_size = in.map_size;
    r.width = in.eye.width;
    r.height = in.eye.height;
    const Frame light = light_frame(in.light), eye = eye_frame(in.eye);
    r.light_from_world = view_matrix(light);
    r.depth.assign(std::size_t(in.map_size) * in.map_size, in.light.far);
    r.owner.assign(r.depth.size(), -1);
    for (int k = 0; k < int(in.triangles.size()); ++k) {
        int written;
        rasterise(in, light, k, r.depth, r.owner, written);
    }
    r.image.resize(std::size_t(r.width) * r.height);
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            r.last = lookup(in, light, eye, r.light_from_world, r.depth, r.owner, i, j);
            r.image[std::size_t(j) * r.width + i] = r.last.verdict;
            count(r.counts, r.last.verdict);
        }
    return r;
}

}  // namespace cg
