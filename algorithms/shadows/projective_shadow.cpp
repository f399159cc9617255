// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and flatten] [draw]
#include "shadows/projective_shadow.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec3;
using glm::dvec4;
using Case = ProjectiveShadow::Case;
using Phase = ProjectiveShadow::Phase;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineSetup = 1,
    kLineFlip,
    kLineMatrix,
    kLineVertex,
    kLineDivide,
    kLineNone,
    kLinePolygon
};

bool finite3(const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite4(const dvec4& v) {
    return finite3(dvec3(v)) && std::isfinite(v.w);
}
double dot4(const dvec4& a, const dvec4& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}
bool directional(const ProjectiveShadow::Input& in) {
    return in.light.w == 0;
}

std::string v4text(const dvec4& v, int digits = 4) {
    return "[" + num(v.x, digits) + ", " + num(v.y, digits) + ", " + num(v.z, digits) + ", " +
           num(v.w, digits) + "]";
}
std::string v4tex(const dvec4& v, int digits = 4) {
    return "\\begin{bmatrix}" + tex(v.x, digits) + " \\\\ " + tex(v.y, digits) + " \\\\ " +
           tex(v.z, digits) + " \\\\ " + tex(v.w, digits) + "\\end{bmatrix}";
}
std::vector<std::vector<double>> rows4(const dmat4& m) {
    std::vector<std::vector<double>> r(4);
    for (int i = 0; i < 4; ++i) r[i] = {m[0][i], m[1][i], m[2][i], m[3][i]};
    return r;
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
std::vector<double> vec4(const dvec4& v) {
    return {v.x, v.y, v.z, v.w};
}
std::vector<double> vec3(const dvec3& v) {
    return {v.x, v.y, v.z};
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

// P oriented so that the light is on its positive side, and h_L = P · L.
struct Oriented {
    dvec4 plane;
    double h;
    bool flipped;
};
Oriented orient(const ProjectiveShadow::Input& in) {
    dvec4 plane(in.normal, in.d);
    double h = dot4(plane, in.light);
    const bool flipped = h < 0;
    if (flipped) plane = -plane, h = -h;
    return {plane, h, flipped};
}

}  // namespace

dmat4 ProjectiveShadow::shadow_matrix(const dvec4& plane, const dvec4& light) {
    const double h = dot4(plane, light);
    dmat4 m(0.0);  // m[column j][row i] = h δ_ij − L_i P_j
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) m[j][i] = (i == j ? h : 0.0) - light[i] * plane[j];
    return m;
}

Case ProjectiveShadow::classify(const dvec4& plane, const dmat4& m, const dvec3& p, dvec4& image,
                                dvec3& shadow) {
    const dvec4 hp(p, 1.0);
    image = m * hp;
    const double h_p = dot4(plane, hp);
    auto matrix_point = [&] {
        const dvec3 q = dvec3(image) / image.w;
        return image.w != 0 && finite3(q) ? q : p;
    };
    if (h_p < 0) {
        shadow = matrix_point();
        return Case::BehindPlane;
    }
    if (h_p == 0) {
        shadow = p;
        return Case::OnPlane;
    }
    if (image.w < 0) {
        shadow = matrix_point();
        return Case::AboveLight;
    }
    if (image.w == 0) {
        shadow = p;
        return Case::LevelWithLight;
    }
    const dvec3 q = dvec3(image) / image.w;
    if (!finite3(q)) {  // w' so small the point overflows: at infinity, as for w' = 0
        shadow = p;
        return Case::LevelWithLight;
    }
    shadow = q;
    return Case::Shadow;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ProjectiveShadow::spec() {
    static const Spec spec{
        "projective-shadow",
        "Projective shadows: the shadow matrix",
        "Shadows",
        {
            "P ← [n, d];  L ← [L, 1] (point) or [l, 0] (toward the sun);  h_L ← P · L = n · L + d "
            "w",
            "if h_L < 0: P ← −P, h_L ← −h_L   ▷ the same plane, the light on its positive side",
            "M ← h_L I − L Pᵀ                   ▷ M_ij = h_L δ_ij − L_i P_j",
            "for each vertex p_k:  p′ ← M [p_k, 1]   ▷ on the line through p_k and L, and on the "
            "plane",
            "    if w′ > 0 and P · p_k ≥ 0:  s_k ← (x′, y′, z′) / w′",
            "    else: no shadow (level with or above the light, or behind the plane)",
            "the shadow polygon s_0 s_1 …: drawn dark, flattened onto the plane",
        },
        {
            {"setup",
             "the plane as a row P, the light as L, and the light's height h_L = P · L > 0"},
            {"flip-plane",
             "h_L < 0 as given: the plane's orientation is reversed so the light is on its "
             "positive side"},
            {"matrix", "the shadow matrix M = h_L I − L Pᵀ, entry by entry"},
            {"vertex", "p′ = M p, the divide by w′ > 0: the vertex's shadow on the plane"},
            {"on-plane", "the vertex lies on the plane: it is its own shadow (p′ = h_L p)"},
            {"level-with-light",
             "w′ = 0: the vertex is as high as the light, its ray never meets the plane: no "
             "shadow"},
            {"above-light",
             "w′ < 0: the vertex is higher than the light; M's point lies behind the light (an "
             "anti-shadow): no shadow"},
            {"behind-plane",
             "the vertex is on the plane's far side; M's point is a false shadow between light and "
             "vertex: no shadow"},
            {"polygon", "the shadow polygon: the flattened copy, drawn dark on the plane"},
        },
        {},  // no sliders
        {
            .predict = {{"setup", {"h_L"}}, {"vertex", {"w'", "s_k"}}},
            .mistakes =
                {
                    {"matrix", "M", "transpose", "built the outer product as P Lᵀ instead of L Pᵀ"},
                    {"setup", "h_L", "negate",
                     "took the light's height with the wrong sign (P · L read as −P · L)"},
                    {"vertex", "w'", "negate",
                     "took w′ = h_p − h_L: the divide then puts the shadow on the wrong side"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void ProjectiveShadow::validate(const Input& in) {
    for (int i = 0; i < 3; ++i)
        check_finite(in.normal[i], "plane.normal[" + std::to_string(i) + "]");
    check_finite(in.d, "plane.d");
    for (int i = 0; i < 4; ++i) check_finite(in.light[i], "light[" + std::to_string(i) + "]");
    if (in.normal == dvec3(0))
        throw InputError("plane.normal",
                         "must not be the zero vector: n · x + d = 0 is then no plane");
    if (in.light.w != 0 && in.light.w != 1)
        throw InputError("light[3]",
                         "must be 1 (a point light [x, y, z, 1]) or 0 (a directional light [l_x, "
                         "l_y, l_z, 0]), got " +
                             given(in.light.w));
    if (directional(in) && dvec3(in.light) == dvec3(0))
        throw InputError("light",
                         "a directional light [l_x, l_y, l_z, 0] needs a non-zero direction");
    if (in.polygon.size() < 3)
        throw InputError("polygon", "must have at least 3 vertices (got " +
                                        std::to_string(in.polygon.size()) + ")");
    if (in.polygon.size() > kMaxVertices)
        throw InputError("polygon", "has " + std::to_string(in.polygon.size()) +
                                        " vertices; at most " + std::to_string(kMaxVertices) +
                                        " are stepped");
    for (std::size_t k = 0; k < in.polygon.size(); ++k)
        for (int i = 0; i < 3; ++i)
            check_finite(in.polygon[k][i],
                         "polygon[" + std::to_string(k) + "][" + std::to_string(i) + "]");
    const Oriented o = orient(in);
    if (!std::isfinite(o.h))
        throw InputError(
            "light",
            "is too large: n · L + d w overflows a double; scale the light and the plane down");
    if (o.h == 0)
        throw InputError(
            "light", directional(in)
                         ? "the directional light is parallel to the plane (n · l = 0): its rays "
                           "never reach the plane, so it casts no shadow on it"
                         : "the point light lies on the plane (n · L + d = 0): the shadow matrix "
                           "would send every point to the light; move the light off the plane");
    const dmat4 m = shadow_matrix(o.plane, in.light);
    for (int j = 0; j < 4; ++j)
        if (!finite4(m[j]))
            throw InputError("light",
                             "is too large: the shadow matrix's entries overflow a double; scale "
                             "the light and the plane down");
    for (std::size_t k = 0; k < in.polygon.size(); ++k) {
        const dvec4 p(in.polygon[k], 1.0);
        if (!finite4(m * p) || !std::isfinite(dot4(o.plane, p)))
            throw InputError("polygon[" + std::to_string(k) + "]",
                             "is too large: M p overflows a double; scale the scene down");
    }
}

ProjectiveShadow::State ProjectiveShadow::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void ProjectiveShadow::advance(State& s) {
    s.last = s.phase;
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Setup: {
            const Oriented o = orient(in);
            s.plane = o.plane;
            s.h_light = o.h;
            s.flipped = o.flipped;
            s.phase = Phase::Matrix;
            return;
        }
        case Phase::Matrix:
            s.m = shadow_matrix(s.plane, in.light);
            s.shadow.reserve(in.polygon.size());
            s.phase = Phase::Vertex;
            return;
        case Phase::Vertex: {
            ++s.k;
            dvec4 image;
            dvec3 shadow;
            s.cases[s.k] = classify(s.plane, s.m, in.polygon[s.k], image, shadow);
            s.shadow.push_back(shadow);
            if (std::size_t(s.k) + 1 == in.polygon.size()) s.phase = Phase::Polygon;
            return;
        }
        case Phase::Polygon:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = ProjectiveShadow::State;

std::string light_text(const ProjectiveShadow::Input& in) {
    return directional(in)
               ? "a directional light L = " + v4text(in.light) + " (the sun, in the direction " +
                     num(dvec3(in.light), 4) + " from the scene; its rays travel along −l)"
               : "a point light L = " + v4text(in.light) + " at " + num(dvec3(in.light), 4);
}

void narrate_setup(const State& s, StepInfo& info) {
    const auto& in = *s.in;
    const std::string plane = "The plane n · x + d = 0 with n = " + num(in.normal, 4) +
                              ", d = " + num(in.d, 4) + "; " + light_text(in) + ". ";
    const double given = s.flipped ? -s.h_light : s.h_light;
    const std::string h = directional(in) ? "h_L = P · L = n · l = " : "h_L = P · L = n · L + d = ";
    if (s.flipped) {
        info.event = "flip-plane";
        info.line = kLineFlip;
        info.narration = plane + h + num(given, 6) +
                         " < 0: the light is on the plane's negative side. (−n, −d) is the same "
                         "plane, so P ← " +
                         v4text(s.plane) + " and h_L = " + num(s.h_light, 6) +
                         " > 0: now w′ > 0 will mean a vertex below the light.";
    } else {
        info.event = "setup";
        info.line = kLineSetup;
        info.narration =
            plane + "As a row P = " + v4text(s.plane) + ", and " + h + num(s.h_light, 6) +
            " > 0: the light is on the plane's positive side" +
            (directional(in)
                 ? "."
                 : ", h_L / |n| = " + num(s.h_light / glm::length(in.normal), 4) + " above it.");
    }
    info.math = "h_L = P \\cdot L = " + tex(s.h_light, 6) + ",\\; P = " + v4tex(s.plane) +
                ",\\; L = " + v4tex(in.light);
}

void narrate_matrix(const State& s, StepInfo& info) {
    const auto& in = *s.in;
    info.event = "matrix";
    info.line = kLineMatrix;
    const dvec4& P = s.plane;
    const dvec4& L = in.light;
    info.narration =
        "M = h_L I − L Pᵀ, each entry M_ij = h_L δ_ij − L_i P_j: the diagonal is h_L − L_i P_i (" +
        num(s.h_light - L.x * P.x, 4) + ", " + num(s.h_light - L.y * P.y, 4) + ", " +
        num(s.h_light - L.z * P.z, 4) + ", " + num(s.h_light - L.w * P.w, 4) +
        "), the rest −L_i P_j; row i is L_i times −P plus h_L in column i. M = " + mtext(s.m) +
        " (rows). Its bottom row −w_L P + h_L e_4 = " +
        v4text(dvec4(s.m[0][3], s.m[1][3], s.m[2][3], s.m[3][3])) + " gives w′.";
    info.math =
        "M = h_L I - L P^T = \\begin{bmatrix} h_L - L_x n_x & -L_x n_y & -L_x n_z & -L_x d \\\\ "
        "-L_y n_x & h_L - L_y n_y & -L_y n_z & -L_y d \\\\ -L_z n_x & -L_z n_y & h_L - L_z n_z & "
        "-L_z d "
        "\\\\ -w n_x & -w n_y & -w n_z & h_L - w d \\end{bmatrix} = " +
        mtex(s.m);
}

void narrate_vertex(const State& s, StepInfo& info) {
    const auto& in = *s.in;
    const int k = s.k;
    const dvec3 p = in.polygon[k];
    const dvec4 q = s.m * dvec4(p, 1.0);  // p' = M p, as classify computed it
    const double h_p = dot4(s.plane, dvec4(p, 1.0));
    const std::string kk = std::to_string(k);
    const std::string head = "Vertex p" + kk + " = " + num(p, 4) +
                             ", h_p = P · p = " + num(h_p, 4) +
                             ": p′ = M [p, 1] = " + v4text(q, 6) + ", w′ = " + num(q.w, 6);
    const std::string mp = "p' = M p = " + v4tex(q, 6);
    const dvec3 s_k = s.shadow[k];
    switch (s.cases[k]) {
        case Case::Shadow:
            info.event = "vertex";
            info.line = kLineDivide;
            info.narration =
                head + " > 0; divide by w′: s" + kk + " = (" + num(q.x, 6) + ", " + num(q.y, 6) +
                ", " + num(q.z, 6) + ") / " + num(q.w, 6) + " = " + num(s_k, 4) +
                ", on the plane (n · s + d = " + num(dot4(s.plane, dvec4(s_k, 1.0)), 3) + ").";
            info.math = mp + ",\\; s_{" + kk + "} = " + tex(s_k, 4);
            return;
        case Case::OnPlane:
            info.event = "on-plane";
            info.line = kLineDivide;
            info.narration = head + " = h_L: p" + kk +
                             " lies on the plane (h_p = 0), so p′ = h_L p and "
                             "the divide gives p back: it is its own shadow, s" +
                             kk + " = " + num(s_k, 4) + ".";
            info.math = mp + " = " + tex(s.h_light, 6) +
                        " \\begin{bmatrix} p \\\\ 1 \\end{bmatrix},\\; s_{" + kk + "} = p_{" + kk +
                        "}";
            return;
        case Case::LevelWithLight:
            info.event = "level-with-light";
            info.line = kLineNone;
            info.narration =
                head + (q.w == 0 ? "" : " (so small that the divide overflows)") +
                ": the vertex is as high as the light (h_p = h_L), so the ray from the "
                "light through it runs parallel to the plane and never meets it. p′ is "
                "a point at infinity: no shadow.";
            info.math = mp + ",\\; w' = h_L - h_p = 0";
            return;
        case Case::AboveLight:
            info.event = "above-light";
            info.line = kLineNone;
            info.narration =
                head + " < 0: the vertex is higher than the light (h_p = " + num(h_p, 4) +
                " > h_L = " + num(s.h_light, 4) +
                "). The ray from the light through it "
                "goes up, away from the plane; dividing anyway gives " +
                num(s_k, 4) +
                ", where the line meets the plane behind the light — an anti-shadow. No "
                "shadow (a renderer must not draw it).";
            info.math = mp + ",\\; w' < 0";
            return;
        case Case::BehindPlane:
            info.event = "behind-plane";
            info.line = kLineNone;
            info.narration =
                head +
                ": h_p < 0, the vertex is on the plane's far side from the light. "
                "The matrix still gives " +
                num(s_k, 4) +
                ", where the segment from the light to the vertex crosses the plane — a "
                "false shadow. No shadow is cast on the lit side.";
            info.math = mp + ",\\; P \\cdot p = " + tex(h_p, 4) + " < 0";
            return;
        case Case::Pending:
            return;
    }
}

void narrate_polygon(const State& s, StepInfo& info) {
    info.event = "polygon";
    info.line = kLinePolygon;
    std::string pts;
    int valid = 0;
    for (std::size_t k = 0; k < s.shadow.size(); ++k) {
        const bool ok = s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane;
        valid += ok;
        pts += (k ? ", " : "") + (ok ? num(s.shadow[k], 4) : std::string("none"));
    }
    const int n = int(s.shadow.size());
    info.narration =
        "The shadow polygon: " + pts + ". " +
        (valid == n ? "Every vertex casts a shadow: this flattened copy, drawn dark on the "
                      "plane (with a depth offset), is the shadow."
                    : std::to_string(n - valid) + " of " + std::to_string(n) +
                          " vertices cast none: the matrix alone would draw a wrong "
                          "shape; the polygon must first be clipped to the region "
                          "between the plane and the light's height.");
    info.math = "s_k = \\frac{(M p_k)_{xyz}}{(M p_k)_w}";
}

void fill_vars(const State& s, StepInfo& info) {
    const auto& in = *s.in;
    info.vars = {{"n", vec3(in.normal)}, {"d", in.d}, {"L", vec4(in.light)}};
    info.vars.push_back({"P", vec4(s.plane)});
    info.vars.push_back({"h_L", s.h_light});
    if (s.last >= Phase::Matrix) info.vars.push_back({"M", rows4(s.m)});
    if (s.last == Phase::Vertex) {
        const int k = s.k;
        const dvec3 p = in.polygon[k];
        info.vars.push_back({"k", (long long)k});
        info.vars.push_back({"p_k", vec3(p)});
        info.vars.push_back({"h_p", dot4(s.plane, dvec4(p, 1.0))});
        const dvec4 q = s.m * dvec4(p, 1.0);
        info.vars.push_back({"p'_k", vec4(q)});
        info.vars.push_back({"w'", q.w});
        const bool ok = s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane;
        if (ok) info.vars.push_back({"s_k", vec3(s.shadow[k])});
        info.vars.push_back({"casts a shadow", ok});
    }
    if (s.last == Phase::Polygon) {
        std::vector<std::vector<double>> pts;
        for (std::size_t k = 0; k < s.shadow.size(); ++k)
            if (s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane)
                pts.push_back(vec3(s.shadow[k]));
        info.vars.push_back({"shadow", pts});
    }
}

}  // namespace

void ProjectiveShadow::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Setup:
            narrate_setup(s, info);
            break;
        case Phase::Matrix:
            narrate_matrix(s, info);
            break;
        case Phase::Vertex:
            narrate_vertex(s, info);
            break;
        case Phase::Polygon:
        case Phase::Done:
            narrate_polygon(s, info);
            break;
    }
    fill_vars(s, info);
}

void ProjectiveShadow::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and flatten] -------------------------------------------------------------------

ProjectiveShadow::Result ProjectiveShadow::result(const State& s) {
    Result r;
    r.matrix = s.m;
    r.flipped = s.flipped;
    r.shadow = s.shadow;
    r.valid.resize(s.shadow.size());
    for (std::size_t k = 0; k < s.shadow.size(); ++k)
        r.valid[k] = s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane;
    return r;
}

ProjectiveShadow::Result ProjectiveShadow::result(State&& s) {
    Result r;
    r.matrix = s.m;
    r.flipped = s.flipped;
    r.valid.resize(s.shadow.size());
    for (std::size_t k = 0; k < s.shadow.size(); ++k)
        r.valid[k] = s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane;
    r.shadow = std::move(s.shadow);
    return r;
}

ProjectiveShadow::Result ProjectiveShadow::flatten(const Input& in) {
    Result r;
    const Oriented o = orient(in);
    r.flipped = o.flipped;
    r.matrix = shadow_matrix(o.plane, in.light);
    r.shadow.resize(in.polygon.size());
    r.valid.resize(in.polygon.size());
    for (std::size_t k = 0; k < in.polygon.size(); ++k) {
        dvec4 image;
        const Case c = classify(o.plane, r.matrix, in.polygon[k], image, r.shadow[k]);
        r.valid[k] = c == Case::Shadow || c == Case::OnPlane;
    }
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

// The plane as a quad around the polygon's foot and its shadow, the light (a point, or an arrow
// coming down from the sun's direction), the polygon, the rays from the light through each
// vertex done so far to the plane, and the shadow polygon, dark on the plane.
void ProjectiveShadow::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const bool started = s.phase != Phase::Setup;
    const Oriented o = started ? Oriented{s.plane, s.h_light, s.flipped} : orient(in);
    // The unit normal and the signed distance, scaled first by n's largest component so that
    // nothing over- or underflows.
    const dvec3 n(o.plane);
    const double big = std::max({std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)});
    const dvec3 ns = n / big;
    const double len = glm::length(ns);
    const dvec3 un = ns / len;
    const bool sun = directional(in);
    const dvec3 L(in.light);
    auto foot = [&](const dvec3& p) {
        return p - ((glm::dot(ns, p) + o.plane.w / big) / len) * un;
    };

    // The plane's quad: a frame (u, v) in it, covering the feet of the polygon, its shadow
    // points and (for a point light) the light's foot, with a margin.
    const dvec3 a = std::fabs(un.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    const dvec3 u = glm::normalize(glm::cross(un, a)), v = glm::cross(un, u);
    std::vector<dvec3> cover;
    for (const dvec3& p : in.polygon) cover.push_back(foot(p));
    for (std::size_t k = 0; k < s.shadow.size(); ++k)
        if (s.cases[k] == Case::Shadow) cover.push_back(s.shadow[k]);
    if (!sun) cover.push_back(foot(L));
    {  // the anti-shadows and false shadows the matrix gives, when not too far off
        double reach = 0;
        for (const dvec3& c : cover) reach = std::max(reach, glm::length(c - cover.front()));
        for (std::size_t k = 0; k < s.shadow.size(); ++k)
            if ((s.cases[k] == Case::AboveLight || s.cases[k] == Case::BehindPlane) &&
                glm::length(s.shadow[k] - cover.front()) <= 3 * reach + 1)
                cover.push_back(s.shadow[k]);
    }
    const dvec3 origin = foot(dvec3(0));
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const dvec3& c : cover) {
        const double cu = glm::dot(c - origin, u), cv = glm::dot(c - origin, v);
        u0 = std::min(u0, cu), u1 = std::max(u1, cu), v0 = std::min(v0, cv), v1 = std::max(v1, cv);
    }
    const double margin = 0.15 * std::max({u1 - u0, v1 - v0, 1e-9}) + 0.5;
    u0 -= margin, u1 += margin, v0 -= margin, v1 += margin;
    scene.faces3.push_back({{origin + u0 * u + v0 * v, origin + u1 * u + v0 * v,
                             origin + u1 * u + v1 * v, origin + u0 * u + v1 * v},
                            {Role::Window, 1.0f},
                            0.18f});
    const dvec3 centre = origin + 0.5 * (u0 + u1) * u + 0.5 * (v0 + v1) * v;
    scene.labels3.push_back({origin + u0 * u + v0 * v, "plane", {Role::Window}});
    Segment3 normal{centre,
                    centre + un * 0.25 * std::max(u1 - u0, v1 - v0) * 0.4,
                    "n",
                    {Role::Window, 1.5f},
                    true};
    normal.min_pixels = 30;  // a normal that must be seen whatever the zoom
    scene.segments3.push_back(normal);

    // The polygon.
    dvec3 middle(0);
    for (const dvec3& p : in.polygon) middle += p / double(in.polygon.size());
    scene.faces3.push_back({in.polygon, {Role::Subject, 2.0f}, 0.55f});
    for (std::size_t k = 0; k < in.polygon.size(); ++k) {
        const bool now = s.last == Phase::Vertex && int(k) == s.k;
        scene.points3.push_back({in.polygon[k],
                                 "p" + std::to_string(k),
                                 {now ? Role::Active : Role::Subject},
                                 now ? 6.0f : 4.0f});
    }

    // The light.
    const double size = std::max(u1 - u0, v1 - v0);
    dvec3 ldir(0);  // toward the light, unit (the sun)
    if (sun) {
        ldir = glm::normalize(L);
        const dvec3 from = middle + ldir * 0.6 * size;
        scene.segments3.push_back(
            {from, from - ldir * 0.25 * size, "sun", {Role::Active, 3.0f}, true});
    } else {
        scene.points3.push_back({L, "L", {Role::Active}, 8.0f});
    }

    // Rays through the vertices done so far, and the shadow points.
    for (std::size_t k = 0; k < s.shadow.size(); ++k) {
        const dvec3 p = in.polygon[k];
        const bool now = s.last == Phase::Vertex && int(k) == s.k;
        const dvec3 src = sun ? p + ldir * 0.6 * size : L;
        const Case c = s.cases[k];
        if (c == Case::Shadow || c == Case::OnPlane) {
            scene.segments3.push_back({src, p, "", {Role::Construction, 1.0f, true}, false});
            scene.segments3.push_back(
                {p, s.shadow[k], "", {now ? Role::Active : Role::Kept, now ? 2.5f : 1.5f}, false});
            scene.points3.push_back(
                {s.shadow[k], "s" + std::to_string(k), {Role::Kept}, now ? 6.0f : 4.0f});
        } else {
            // No shadow: the ray from the light through the vertex, a little past it.
            const dvec3 dir = p - src;
            const double len = glm::length(dir);
            const dvec3 past = len > 0 ? p + dir / len * 0.2 * size : p;
            scene.segments3.push_back({src,
                                       past,
                                       now ? "no shadow" : "",
                                       {Role::Discarded, now ? 2.5f : 1.5f, true},
                                       false});
            // The point the matrix gives anyway (the anti-shadow behind the light, or the false
            // shadow between light and vertex), when it is near enough to show.
            const bool wrong = c == Case::AboveLight || c == Case::BehindPlane;
            const dvec3 q = s.shadow[k];
            if (wrong && q != p && glm::length(q - centre) <= size) {
                scene.segments3.push_back({src, q, "", {Role::Discarded, 1.0f, true}, false});
                scene.points3.push_back(
                    {q,
                     now ? (c == Case::AboveLight ? "anti-shadow" : "false shadow") : "",
                     {Role::Discarded},
                     now ? 5.0f : 3.5f});
            }
        }
    }
    // The shadow polygon, once every vertex is done and all cast one.
    if (s.phase == Phase::Done || s.last == Phase::Polygon) {
        std::vector<dvec3> pts;
        for (std::size_t k = 0; k < s.shadow.size(); ++k)
            if (s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane)
                pts.push_back(s.shadow[k]);
        if (pts.size() >= 3)
            scene.faces3.push_back({pts, {Role::Neutral, 2.0f, false, 0x202020ffu}, 0.75f});
    } else if (s.shadow.size() >= 2) {
        for (std::size_t k = 1; k < s.shadow.size(); ++k) {
            const bool a_ok = s.cases[k - 1] == Case::Shadow || s.cases[k - 1] == Case::OnPlane;
            const bool b_ok = s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane;
            if (a_ok && b_ok)
                scene.segments3.push_back({s.shadow[k - 1],
                                           s.shadow[k],
                                           "",
                                           {Role::Neutral, 2.0f, false, 0x202020ffu},
                                           false});
        }
    }
    // The camera frames the construction: the polygon, the light (or the sun's arrow) and the
    // shadow points that fall on the plane.
    {
        dvec3 lo = middle, hi = middle;
        auto take = [&](const dvec3& p) {
            if (finite3(p)) lo = glm::min(lo, p), hi = glm::max(hi, p);
        };
        for (const dvec3& p : in.polygon) take(p);
        if (sun) take(middle + ldir * 0.6 * size);
        else if (glm::length(L - centre) <= 4 * size) take(L);
        for (std::size_t k = 0; k < s.shadow.size(); ++k)
            if (s.cases[k] == Case::Shadow || s.cases[k] == Case::OnPlane) take(s.shadow[k]);
        if (finite3(lo) && finite3(hi)) add_focus(scene, lo, hi);
    }
    // Inputs near the limits of a double (coordinates of 1e300) leave nothing worth drawing
    // where the picture's own arithmetic overflows: such primitives are left out.
    drop_non_finite3(scene);
}

}  // namespace cg
