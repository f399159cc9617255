// Sections: [helpers] [spec] [validate] [advance] [narrate]; the picture is in
// ray_quadric_draw.cpp.
#include "rays/ray_quadric.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Phase = RayQuadric::Phase;
using Verdict = RayQuadric::Verdict;

// ---- [helpers] ------------------------------------------------------------------------------

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineModel = 1,
    kLineCoefficients,
    kLineLinear,
    kLineDiscriminant,
    kLineRoots,
    kLineNearest,
    kLinePoint,
    kLineNormal,
};

// How a kind's equation is written: each squared coordinate over a named parameter squared
// ("" for none, nullptr when the coordinate does not appear), the sign of the z² term, a
// linear −z term (paraboloid), and the constant on the right ("r^2", "1" or none).
struct Shape {
    const char *x, *y, *z;
    bool z_negative;
    bool minus_z;
    const char* rhs;  // F = ... − rhs
};

Shape shape_of(QuadricKind k) {
    switch (k) {
        case QuadricKind::Sphere:
            return {"", "", "", false, false, "r^2"};
        case QuadricKind::Ellipsoid:
            return {"a", "b", "c", false, false, "1"};
        case QuadricKind::Paraboloid:
            return {"p", "q", nullptr, false, true, nullptr};
        case QuadricKind::Hyperboloid:
            return {"a", "b", "c", true, false, "1"};
        case QuadricKind::Cone:
            return {"p", "q", "r", true, false, nullptr};
        case QuadricKind::Cylinder:
            return {"p", "q", nullptr, false, false, "1"};
    }
    return {"", "", "", false, false, nullptr};
}

// "\frac{E_x d_x}{a^2}" or "E_x d_x" for an unnamed (unit) parameter.
std::string over(const std::string& e, const char* param) {
    return *param ? "\\frac{" + e + "}{" + param + "^2}" : e;
}

// The sum of the per-axis terms of F's symbolic coefficient: `xyz` is a pattern such as
// "E_@ d_@" with @ standing for the axis.
std::string axis_sum(const Shape& sh, const std::string& pattern) {
    auto term = [&](char axis) {
        std::string t = pattern;
        for (auto pos = t.find('@'); pos != std::string::npos; pos = t.find('@')) t[pos] = axis;
        return t;
    };
    std::string s = over(term('x'), sh.x) + " + " + over(term('y'), sh.y);
    if (sh.z) s += (sh.z_negative ? " - " : " + ") + over(term('z'), sh.z);
    return s;
}

std::string F_tex(const Shape& sh) {
    std::string s = axis_sum(sh, "@^2");
    if (sh.minus_z) s += " - z";
    if (sh.rhs) s += std::string(" - ") + sh.rhs;
    return s;
}

// "x^2/4" (text) or "\frac{x^2}{4}" (LaTeX) for the coordinate over a parameter's square.
std::string coord_term(const char* coord, double param, bool latex) {
    const double sq = param * param;
    const std::string c = std::string(coord) + (latex ? "^2" : "²");
    if (sq == 1) return c;
    return latex ? "\\frac{" + c + "}{" + tex(sq) + "}" : c + "/" + num(sq);
}

double param_value(const Quadric& s, const char* name) {
    switch (name[0]) {
        case 'r':
            return s.r;
        case 'a':
            return s.a;
        case 'b':
            return s.b;
        case 'c':
            return s.c;
        case 'p':
            return s.p;
        case 'q':
            return s.q;
    }
    return 1;
}

double max_abs(dvec3 v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

std::string root_name(const QuadraticRoots& r, int i) {
    return r.count == 1 ? "t" : (i == 0 ? "t₁" : "t₂");
}

void check_point(dvec3 v, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            throw InputError(field + "[" + std::to_string(i) + "]",
                             "must be a finite number (got " + given(v[i]) + ")");
}

}  // namespace

std::string quadric_equation(const Quadric& s, bool latex) {
    const Shape sh = shape_of(s.kind);
    if (s.kind == QuadricKind::Sphere)
        return latex ? "x^2 + y^2 + z^2 = " + tex(s.r * s.r) : "x² + y² + z² = " + num(s.r * s.r);
    std::string lhs = coord_term("x", param_value(s, sh.x), latex) + " + " +
                      coord_term("y", param_value(s, sh.y), latex);
    if (sh.z) lhs += (sh.z_negative ? " − " : " + ") + coord_term("z", param_value(s, sh.z), latex);
    if (latex)
        for (auto pos = lhs.find("−"); pos != std::string::npos; pos = lhs.find("−"))
            lhs.replace(pos, std::string("−").size(), "-");
    const std::string rhs = sh.minus_z ? "z" : (sh.rhs ? "1" : "0");
    return lhs + " = " + rhs;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& RayQuadric::spec() {
    static const Spec spec{
        "ray-quadric",
        "Ray-quadric intersection",
        "Ray Tracing",
        {
            "E_m ← M⁻¹(E − T);  d_m ← M⁻¹ d              ▷ the ray in model space",
            "a ← F₂(d_m);  b ← ∇-term(E_m, d_m);  c ← F(E_m)  ▷ F(E_m + t d_m) = a t² + b t + c",
            "if a = 0: solve b t + c = 0 (none if b = 0)",
            "Δ ← b² − 4ac;  if Δ < 0: miss",
            "q ← −(b + sign(b)√Δ)/2;  t₁, t₂ ← q/a, c/q    ▷ no cancellation",
            "t ← the smallest root > ε with zmin ≤ z ≤ zmax;  none: miss",
            "P ← E + t d",
            "n ← normalize((M⁻¹)ᵀ ∇F(E_m + t d_m))",
        },
        {
            {"no-transform", "the quadric sits in its canonical place: model space is world space"},
            {"to-model", "the ray carried into model space by the inverse transform"},
            {"coefficients", "E + t d substituted into F: the quadratic's a, b, c"},
            {"two-roots", "Δ > 0: the line crosses the surface twice"},
            {"tangent", "Δ = 0: the line touches the surface, one double root"},
            {"no-roots", "Δ < 0: no real root, the line misses the surface"},
            {"linear", "a = 0: the t² term vanishes, one root of b t + c = 0"},
            {"no-solution", "a = b = 0, c ≠ 0: F is a nonzero constant along the line: no hit"},
            {"in-surface", "a = b = c = 0: the whole line lies in the surface: no isolated hit"},
            {"roots", "the real roots, computed without cancellation"},
            {"nearest", "the nearest root in front of the eye and inside the slab is the hit"},
            {"miss", "every root is behind the eye or cut away by the slab"},
            {"hit-point", "the hit point E + t d"},
            {"normal", "the gradient of F, carried back by the inverse transpose and normalised"},
            {"apex", "the gradient vanishes (the cone's apex): the normal is undefined"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"coefficients", {"b", "c"}},
                    {"two-roots", {"discriminant"}},
                    {"nearest", {"t"}},
                    {"hit-point", {"P"}},
                    {"normal", {"n"}},
                },
            .mistakes =
                {
                    {"normal", "n", "copy:grad_F", "forgot to normalise the gradient"},
                    {"coefficients", "c", "negate", "took c = r² − |E − C|²: its sign flipped"},
                    {"coefficients", "b", "negate", "took the sign of b wrong"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void RayQuadric::validate(const Input& in) {
    validate_quadric(in.quadric, "quadric");
    check_point(in.origin, "origin");
    check_point(in.direction, "direction");
    if (in.direction == dvec3(0.0))
        throw InputError("direction", "must not be the zero vector: a ray needs a direction");
    // Squares of the model-space ray must neither overflow nor underflow.
    const PreparedQuadric p = prepare(in.quadric);
    const RayQuadratic q = ray_quadratic(p, in.origin, in.direction);
    const double d = max_abs(q.direction), o = max_abs(q.origin);
    if (!(d >= 1e-100 && d <= 1e100))
        throw InputError("direction",
                         "is too small or too large for double precision in model "
                         "space (largest component " +
                             given(d) + ")");
    if (!(o <= 1e100))
        throw InputError("origin",
                         "is too far away for double precision in model space (" + given(o) + ")");
    if (!std::isfinite(q.a) || !std::isfinite(q.b) || !std::isfinite(q.c) ||
        !std::isfinite(q.b * q.b - 4 * q.a * q.c))
        throw InputError("origin",
                         "and direction give a quadratic that overflows (a = " + given(q.a) +
                             ", b = " + given(q.b) + ", c = " + given(q.c) + ")");
}

RayQuadric::State RayQuadric::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

RayQuadric::State RayQuadric::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {

// ∇F at the hit, model space, and carried to the world by (M⁻¹)ᵀ (not normalised).
dvec3 model_gradient(const RayQuadric::State& s) {
    return gradient(s.prepared.f, s.model_point);
}
dvec3 world_gradient(const RayQuadric::State& s) {
    const dvec3 g = model_gradient(s);
    return s.prepared.transformed ? g * s.prepared.linear_inv : g;
}

}  // namespace

void RayQuadric::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::ToModel:  // Transform the ray into model space
            s.prepared = prepare(s.in->quadric);
            s.phase = Phase::Coefficients;
            return;
        case Phase::Coefficients:  // Substitute the ray: the quadratic's coefficients
            s.quad = ray_quadratic(s.prepared, s.in->origin, s.in->direction);
            s.phase = Phase::Discriminant;
            return;
        case Phase::Discriminant:  // Compute the quadratic discriminant (or the linear case)
            s.roots = solve_quadratic(s.quad);
            s.phase = s.roots.count > 0 ? Phase::Roots : Phase::Done;
            return;
        case Phase::Roots:  // The roots (already solved; this step shows them)
            s.hit.roots = s.roots.t;
            s.hit.root_count = s.roots.count;
            s.phase = Phase::Nearest;
            return;
        case Phase::Nearest: {  // The nearest root in front of the eye, inside the slab
            bool found = false;
            for (int i = 0; i < s.roots.count; ++i) {
                const double t = s.roots.t[i];
                const double z = s.quad.origin.z + t * s.quad.direction.z;
                if (found) {
                    s.verdict[i] = Verdict::Farther;
                } else if (!(t > kRayEpsilon)) {
                    s.verdict[i] = Verdict::Behind;
                } else if (z < s.prepared.zmin || z > s.prepared.zmax) {
                    s.verdict[i] = Verdict::OutsideSlab;
                } else {
                    s.verdict[i] = Verdict::Chosen;
                    s.hit.t = t;
                    found = true;
                }
            }
            s.hit.hit = found;
            s.phase = found ? Phase::HitPoint : Phase::Done;
            return;
        }
        case Phase::HitPoint:  // The hit point
            s.hit.point = s.in->origin + s.hit.t * s.in->direction;
            s.model_point = s.quad.origin + s.hit.t * s.quad.direction;
            s.phase = Phase::Normal;
            return;
        case Phase::Normal:  // The normal from the gradient, back to world space
            s.hit.normal = unit(world_gradient(s));
            s.hit.has_normal = s.hit.normal != dvec3(0.0);
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

void RayQuadric::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::vector<std::vector<double>> rows3(const glm::dmat3& m) {
    return {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}};
}

std::string matrix_tex(const glm::dmat3& m) {
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " & " : "") + tex(m[c][r], 4);
        t += r < 2 ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

std::string column_tex(dvec3 v) {
    return "\\begin{bmatrix} " + tex(v.x) + " \\\\ " + tex(v.y) + " \\\\ " + tex(v.z) +
           " \\end{bmatrix}";
}

// "2", "(−3)": a number after an operator.
std::string operand(double v) {
    return v < 0 ? "(" + num(v) + ")" : num(v);
}
std::string tex_operand(double v) {
    return v < 0 ? "(" + tex(v) + ")" : tex(v);
}

std::string quadratic_text(const RayQuadratic& q) {
    return num(q.a) + "·t² + " + operand(q.b) + "·t + " + operand(q.c) + " = 0";
}
std::string quadratic_tex(const RayQuadratic& q) {
    return tex(q.a) + " t^2 + " + tex_operand(q.b) + " t + " + tex_operand(q.c) + " = 0";
}

void narrate_model(const RayQuadric::State& s, StepInfo& info) {
    const Quadric& qd = s.in->quadric;
    const std::string surface =
        std::string(quadric_kind_name(qd.kind)) + " " + quadric_equation(qd, false);
    if (!s.prepared.transformed) {
        info.event = "no-transform";
        info.line = kLineModel;
        info.narration = "The " + surface +
                         " has no model transform, so model space is world space: E_m = E = " +
                         num(s.in->origin) + ", d_m = d = " + num(s.in->direction) + ".";
        info.math = "E_m = E = " + tex(s.in->origin) + ",\\quad d_m = d = " + tex(s.in->direction);
        return;
    }
    const dvec3 om = s.prepared.linear_inv * (s.in->origin - s.prepared.translation);
    const dvec3 dm = s.prepared.linear_inv * s.in->direction;
    info.event = "to-model";
    info.line = kLineModel;
    info.narration = "The " + surface + " is placed by M; solve in its model space instead: " +
                     "E_m = M⁻¹(E − T) = " + num(om) + " and d_m = M⁻¹d = " + num(dm) +
                     " (a direction is not translated). t means the same in both spaces.";
    info.math = "M^{-1} = " + matrix_tex(s.prepared.linear_inv) + ",\\quad E_m = M^{-1}(" +
                tex(s.in->origin) + " - " + tex(s.prepared.translation) + ") = " + tex(om) +
                ",\\quad d_m = M^{-1}" + tex(s.in->direction) + " = " + tex(dm);
}

void narrate_coefficients(const RayQuadric::State& s, StepInfo& info) {
    const Shape sh = shape_of(s.in->quadric.kind);
    const RayQuadratic& q = s.quad;
    std::string a_sym = axis_sum(sh, "d_@^2");
    std::string b_sym = "2\\left(" + axis_sum(sh, "E_@ d_@") + "\\right)";
    if (sh.minus_z) b_sym += " - d_z";
    std::string c_sym = axis_sum(sh, "E_@^2");
    if (sh.minus_z) c_sym += " - E_z";
    if (sh.rhs) c_sym += std::string(" - ") + sh.rhs;
    info.event = "coefficients";
    info.line = kLineCoefficients;
    info.narration = "Substitute E_m + t·d_m into F: a = " + num(q.a) +
                     " (the t² terms), b = " + num(q.b) + ", c = F(E_m) = " + num(q.c) + ", so " +
                     quadratic_text(q) +
                     (q.c < 0    ? ". c < 0: the eye is inside the surface (F < 0)."
                      : q.c == 0 ? ". c = 0: the eye is on the surface."
                                 : ".");
    info.math = "F = " + F_tex(sh) + ";\\quad a = " + a_sym + " = " + tex(q.a) +
                ",\\quad b = " + b_sym + " = " + tex(q.b) + ",\\quad c = " + c_sym + " = " +
                tex(q.c) + ";\\quad " + quadratic_tex(q);
}

void narrate_discriminant(const RayQuadric::State& s, StepInfo& info) {
    const RayQuadratic& q = s.quad;
    const QuadraticRoots& r = s.roots;
    const std::string disc = "Δ = b² − 4ac = " + operand(q.b) + "² − 4·" + operand(q.a) + "·" +
                             operand(q.c) + " = " + num(r.discriminant);
    const std::string disc_tex = "\\Delta = b^2 - 4ac = " + tex_operand(q.b) + "^2 - 4 \\cdot " +
                                 tex_operand(q.a) + " \\cdot " + tex_operand(q.c) + " = " +
                                 tex(r.discriminant);
    switch (r.kind) {
        case QuadraticCase::TwoRoots:
            info.event = "two-roots";
            info.line = kLineDiscriminant;
            info.narration = disc + " > 0: the line crosses the surface twice.";
            info.math = disc_tex + " > 0";
            return;
        case QuadraticCase::Tangent:
            info.event = "tangent";
            info.line = kLineDiscriminant;
            info.narration = disc + ": the line touches the surface (a double root).";
            info.math =
                disc_tex + (r.discriminant == 0 && q.b * q.b != 4 * q.a * q.c ? " \\approx 0" : "");
            return;
        case QuadraticCase::NoRoots:
            info.event = "no-roots";
            info.line = kLineDiscriminant;
            info.narration = disc + " < 0: no real root, the ray misses the " +
                             std::string(quadric_kind_name(s.in->quadric.kind)) + ".";
            info.math = disc_tex + " < 0";
            return;
        case QuadraticCase::Linear:
            info.event = "linear";
            info.line = kLineLinear;
            info.narration = "a = " + num(q.a) +
                             ": the t² terms cancel (the ray runs parallel to a line of the "
                             "surface's asymptotic directions, e.g. its axis), leaving the "
                             "linear equation " +
                             num(q.b) + "·t + " + operand(q.c) + " = 0.";
            info.math = "a = 0:\\quad " + tex(q.b) + " t + " + tex_operand(q.c) + " = 0";
            return;
        case QuadraticCase::NoSolution:
            info.event = "no-solution";
            info.line = kLineLinear;
            info.narration = "a = b = 0 but c = " + num(q.c) +
                             " ≠ 0: F keeps the same nonzero value all along the line, which "
                             "never meets the surface.";
            info.math = "a = b = 0,\\quad c = " + tex(q.c) + " \\ne 0";
            return;
        case QuadraticCase::InSurface:
            info.event = "in-surface";
            info.line = kLineLinear;
            info.narration =
                "a = b = c = 0: every t solves, the whole line lies in the surface "
                "(along a ruling). There is no isolated hit to shade: a miss.";
            info.math = "a = b = c = 0";
            return;
    }
}

void narrate_roots(const RayQuadric::State& s, StepInfo& info) {
    const RayQuadratic& q = s.quad;
    const QuadraticRoots& r = s.roots;
    info.event = "roots";
    if (r.kind == QuadraticCase::Linear) {
        info.line = kLineLinear;
        info.narration =
            "t = −c/b = −" + operand(q.c) + "/" + operand(q.b) + " = " + num(r.t[0]) + ".";
        info.math =
            "t = -\\frac{c}{b} = -\\frac{" + tex(q.c) + "}{" + tex(q.b) + "} = " + tex(r.t[0]);
        return;
    }
    info.line = kLineRoots;
    if (r.kind == QuadraticCase::Tangent) {
        info.narration = "The double root t = −b/(2a) = " + num(r.t[0]) + ".";
        info.math = "t = -\\frac{b}{2a} = -\\frac{" + tex(q.b) + "}{2 \\cdot " + tex_operand(q.a) +
                    "} = " + tex(r.t[0]);
        return;
    }
    const double h = -0.5 * (q.b + std::copysign(std::sqrt(r.discriminant), q.b));
    info.narration = "q = −(b + sign(b)·√Δ)/2 = " + num(h) +
                     " (adding numbers of one sign, so "
                     "nothing cancels); the roots q/a and c/q are t₁ = " +
                     num(r.t[0]) + " and t₂ = " + num(r.t[1]) + ".";
    info.math = "q = -\\frac{b + \\operatorname{sign}(b)\\sqrt{\\Delta}}{2} = " + tex(h) +
                ",\\quad \\frac{q}{a} = " + tex(h / q.a) +
                ",\\quad \\frac{c}{q} = " + tex(q.c / h) + ";\\quad t_1 = " + tex(r.t[0]) +
                ",\\ t_2 = " + tex(r.t[1]);
}

void narrate_nearest(const RayQuadric::State& s, StepInfo& info) {
    const QuadraticRoots& r = s.roots;
    std::string why;
    for (int i = 0; i < r.count; ++i) {
        const double z = s.quad.origin.z + r.t[i] * s.quad.direction.z;
        std::string w = root_name(r, i) + " = " + num(r.t[i]);
        switch (s.verdict[i]) {
            case Verdict::Behind:
                w += " is not > ε (behind or at the eye)";
                break;
            case Verdict::OutsideSlab:
                w += " hits at model z = " + num(z) + ", outside the slab " +
                     (std::isfinite(s.prepared.zmin) ? num(s.prepared.zmin) + " ≤ z" : "z") +
                     (std::isfinite(s.prepared.zmax) ? " ≤ " + num(s.prepared.zmax) : "");
                break;
            case Verdict::Chosen:
                w += " is the nearest hit";
                break;
            case Verdict::Farther:
                w += " is farther";
                break;
            case Verdict::Pending:
                break;
        }
        why += (i ? "; " : "") + w;
    }
    if (s.hit.hit) {
        info.event = "nearest";
        info.narration = why + ": t = " + num(s.hit.t) + ".";
        info.math = "t = " + tex(s.hit.t);
    } else {
        info.event = "miss";
        info.narration = why + ": nothing in front of the eye, the ray misses.";
        info.math = "\\text{no } t > \\varepsilon";
    }
    info.line = kLineNearest;
}

void narrate_point(const RayQuadric::State& s, StepInfo& info) {
    const dvec3 E = s.in->origin, d = s.in->direction, P = s.hit.point;
    info.event = "hit-point";
    info.line = kLinePoint;
    info.narration =
        "P = E + t·d = " + num(E) + " + " + num(s.hit.t) + "·" + num(d) + " = " + num(P) +
        (s.prepared.transformed ? " (in model space " + num(s.model_point) + ")" : "") +
        "; F there is " + num(eval_F(s.prepared.f, s.model_point), 3) + ".";
    info.math = "P = " + tex(E) + " + " + tex(s.hit.t) + " \\cdot " + tex(d) + " = " + tex(P);
}

void narrate_normal(const RayQuadric::State& s, StepInfo& info) {
    const Shape sh = shape_of(s.in->quadric.kind);
    std::string grad_sym =
        "\\nabla F = \\left(" + over("2x", sh.x) + ", " + over("2y", sh.y) + ", ";
    if (sh.z)
        grad_sym += std::string(sh.z_negative ? "-" : "") + over("2z", sh.z);
    else
        grad_sym += sh.minus_z ? "-1" : "0";
    grad_sym += "\\right)";
    const dvec3 grad = model_gradient(s), world_grad = world_gradient(s);
    const std::string at = "∇F(" + num(s.model_point) + ") = " + num(grad);
    if (!s.hit.has_normal) {
        info.event = "apex";
        info.line = kLineNormal;
        info.narration = at +
                         ": the gradient vanishes at the cone's apex, where the surface "
                         "has no tangent plane, so there is no normal.";
        info.math = grad_sym + " = " + tex(grad) + " = \\mathbf{0}";
        return;
    }
    info.event = "normal";
    info.line = kLineNormal;
    if (s.prepared.transformed) {
        info.narration =
            at + "; back to world space by the inverse transpose, (M⁻¹)ᵀ∇F = " + num(world_grad) +
            " (M itself would tilt it off the surface under "
            "non-uniform scale or shear); normalised n = " +
            num(s.hit.normal) + ".";
        info.math = grad_sym + " = " + tex(grad) + ",\\quad (M^{-1})^T \\nabla F = " +
                    matrix_tex(glm::transpose(s.prepared.linear_inv)) + column_tex(grad) + " = " +
                    tex(world_grad) + ",\\quad n = " + tex(s.hit.normal);
    } else {
        info.narration = at + ", normalised n = ∇F/|∇F| = " + num(s.hit.normal) + ".";
        info.math = grad_sym + " = " + tex(grad) +
                    ",\\quad n = \\frac{\\nabla F}{|\\nabla F|} = " + tex(s.hit.normal);
    }
}

void fill_vars(const RayQuadric::State& s, StepInfo& info) {
    info.vars = {{"E", vec(s.in->origin)}, {"d", vec(s.in->direction)}};
    if (s.prepared.transformed) info.vars.push_back({"M_inv", rows3(s.prepared.linear_inv)});
    if (s.last >= Phase::Coefficients) {
        info.vars.push_back({"E_m", vec(s.quad.origin)});
        info.vars.push_back({"d_m", vec(s.quad.direction)});
        info.vars.push_back({"a", s.quad.a});
        info.vars.push_back({"b", s.quad.b});
        info.vars.push_back({"c", s.quad.c});
    }
    if (s.last >= Phase::Discriminant && s.roots.kind != QuadraticCase::Linear &&
        s.roots.kind != QuadraticCase::NoSolution && s.roots.kind != QuadraticCase::InSurface)
        info.vars.push_back({"discriminant", s.roots.discriminant});
    if (s.last >= Phase::Roots) {
        std::vector<double> roots(s.roots.t.begin(), s.roots.t.begin() + s.roots.count);
        info.vars.push_back({"roots", roots});
    }
    if (s.last >= Phase::Nearest && s.hit.hit) info.vars.push_back({"t", s.hit.t});
    if (s.last >= Phase::HitPoint) info.vars.push_back({"P", vec(s.hit.point)});
    if (s.last >= Phase::Normal) {
        info.vars.push_back({"grad_F", vec(model_gradient(s))});
        if (s.hit.has_normal) info.vars.push_back({"n", vec(s.hit.normal)});
    }
}

}  // namespace

void RayQuadric::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::ToModel:
            narrate_model(s, info);
            break;
        case Phase::Coefficients:
            narrate_coefficients(s, info);
            break;
        case Phase::Discriminant:
            narrate_discriminant(s, info);
            break;
        case Phase::Roots:
            narrate_roots(s, info);
            break;
        case Phase::Nearest:
            narrate_nearest(s, info);
            break;
        case Phase::HitPoint:
            narrate_point(s, info);
            break;
        case Phase::Normal:
        case Phase::Done:
            narrate_normal(s, info);
            break;
    }
    fill_vars(s, info);
}

}  // namespace cg
