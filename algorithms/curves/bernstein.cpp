// Sections: [spec] [hull] [start] [advance] [narrate] [step and result]; the picture is in
// bernstein_draw.cpp.
#include "curves/bernstein.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "curves/bezier.hpp"

namespace cg {

namespace {

using curves::point_name;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineLoop = 1,
    kLineBasis,
    kLineSum,
    kLineSign,
    kLinePoint,
    kLineHull,
    kLineAffine,
};

double ipow(double x, int k) {
    double r = 1;
    for (int j = 0; j < k; ++j) r *= x;
    return r;
}

int degree(const Bernstein::State& s) {
    return static_cast<int>(s.in.control_points.size()) - 1;
}

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// The tolerance of the geometric checks: 1e-9 of the largest coordinate (rounding only).
double tolerance(const std::vector<glm::dvec2>& points) {
    double scale = 0;
    for (glm::dvec2 p : points) scale = std::max({scale, std::fabs(p.x), std::fabs(p.y)});
    return 1e-9 * scale;
}

// Σ B_i T(P_i) and T(P(t)) agree up to rounding.
bool affine_ok(const Bernstein::State& s) {
    std::vector<glm::dvec2> all = s.transformed;
    all.push_back(s.image_of_point);
    return s.affine_error <= tolerance(all);
}

std::vector<std::vector<double>> rows_of(const std::vector<glm::dvec2>& ps) {
    std::vector<std::vector<double>> m;
    for (glm::dvec2 p : ps) m.push_back(vec(p));
    return m;
}

std::string basis_name(int i, int n) {
    return "B" + curves::subscript(i) + curves::superscript(n);
}
std::string basis_tex(int i, int n) {
    return "B_{" + std::to_string(i) + "}^{" + std::to_string(n) + "}";
}

}  // namespace

// --- [spec] -------------------------------------------------------------------------------------

const Spec& Bernstein::spec() {
    static const Spec spec{
        "bernstein",
        "Bernstein polynomials and the properties of Bézier curves",
        "Splines",
        {
            "for i = 0 .. n:",
            "    B_i ← C(n, i) (1 − t)^(n−i) t^i",
            "check Σ_i B_i = 1                  ▷ partition of unity",
            "check B_i ≥ 0 for every i          ▷ holds for t in [0, 1]",
            "P(t) ← Σ_i B_i P_i",
            "H ← convex hull of P_0 .. P_n;  is P(t) in H?",
            "if a map T is given: T(P(t)) = Σ_i B_i T(P_i)?   ▷ affine invariance",
        },
        {
            {"basis", "one Bernstein polynomial B_i^n evaluated at t"},
            {"sum", "the weights add up to 1: the point is an affine combination"},
            {"non-negative", "no weight is negative: the point is a convex combination"},
            {"negative-weight", "t is outside [0, 1], so some weights are negative"},
            {"point", "the curve point as the weighted sum of the control points"},
            {"hull", "the convex hull of the control points, and whether P(t) lies in it"},
            {"affine", "mapping the control points maps the curve: T(P(t)) = Σ B_i T(P_i)"},
        },
        {{"/t", "t", 0, 1}},
        {
            .predict = {{"basis", {"B_i"}}, {"sum", {"sum"}}, {"point", {"P(t)"}}},
            .mistakes = {
                {"basis", "basis", "reverse", "swapped t and 1 − t: the weights came out reversed"},
                {"hull", "inside hull", "not", "thought P(t) may leave the control points' hull"},
            },
        },
    };
    return spec;
}

// --- [hull] -------------------------------------------------------------------------------------

glm::dvec2 Bernstein::apply(const Rows& m, glm::dvec2 p) {
    return {m[0].x * p.x + m[0].y * p.y + m[0].z, m[1].x * p.x + m[1].y * p.y + m[1].z};
}

std::vector<glm::dvec2> Bernstein::convex_hull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(),
              [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    std::vector<glm::dvec2> hull(2 * points.size());
    std::size_t k = 0;
    // Lower chain left to right, then upper chain right to left; keep only left turns.
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);                                   // the last point repeats the first
    if (hull.size() == 1) hull.push_back(points.back());  // all collinear: just the two ends
    return hull;
}

bool Bernstein::in_hull(const std::vector<glm::dvec2>& hull, glm::dvec2 p, double tolerance) {
    if (hull.empty()) return false;
    if (hull.size() == 1) return glm::length(p - hull[0]) <= tolerance;
    if (hull.size() == 2) {  // a segment: the distance to it
        const glm::dvec2 d = hull[1] - hull[0];
        const double u = std::clamp(glm::dot(p - hull[0], d) / glm::dot(d, d), 0.0, 1.0);
        return glm::length(p - (hull[0] + u * d)) <= tolerance;
    }
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        if (cross(b - a, p - a) < -tolerance * glm::length(b - a)) return false;
    }
    return true;
}

// --- [start] ------------------------------------------------------------------------------------

void Bernstein::validate(const Input& in) {
    std::vector<glm::dvec3> points;
    for (glm::dvec2 p : in.control_points) points.push_back({p.x, p.y, 0});
    curves::validate_points(points, 2, "control_points", 2);
    curves::validate_t(in.t, in.extrapolate);
    if (in.transform) {
        const Rows& m = *in.transform;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                const double v = m[static_cast<std::size_t>(r)][c];
                const std::string field =
                    "transform[" + std::to_string(r) + "][" + std::to_string(c) + "]";
                if (!std::isfinite(v))
                    throw InputError(field, "must be a finite number (got " + given(v) + ")");
                if (std::fabs(v) > 1e100)
                    throw InputError(field, "must be within ±1e100 (got " + given(v) + ")");
            }
        if (m[2] != glm::dvec3(0, 0, 1))
            throw InputError("transform[2]",
                             "must be [0, 0, 1]: only an affine map keeps a Bézier curve (got " +
                                 given(m[2]) + ")");
    }
}

Bernstein::State Bernstein::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    s.basis.assign(in.control_points.size(), 0.0);
    return s;
}

// --- [advance] ----------------------------------------------------------------------------------

// The algorithm proper: one step of the math.
void Bernstein::advance(State& s) {
    const int n = degree(s);
    const double t = s.in.t;
    switch (s.phase) {
        case Phase::Basis: {  // One Bernstein polynomial at t
            const int i = ++s.i;
            s.basis[static_cast<std::size_t>(i)] =
                curves::binomial(n, i) * ipow(1 - t, n - i) * ipow(t, i);
            if (i == n) s.phase = Phase::Sum;
            return;
        }
        case Phase::Sum:  // The weights add up to one
            s.sum = 0;
            for (double b : s.basis) s.sum += b;
            s.phase = Phase::Sign;
            return;
        case Phase::Sign:  // ... and none is negative on [0, 1]
            s.negative = static_cast<int>(
                std::count_if(s.basis.begin(), s.basis.end(), [](double b) { return b < 0; }));
            s.phase = Phase::Point;
            return;
        case Phase::Point:  // The curve point as the weighted sum
            s.point = glm::dvec2(0);
            for (int i = 0; i <= n; ++i)
                s.point += s.basis[static_cast<std::size_t>(i)] *
                           s.in.control_points[static_cast<std::size_t>(i)];
            s.phase = Phase::Hull;
            return;
        case Phase::Hull:  // The convex hull, and whether the point lies in it
            s.hull = convex_hull(s.in.control_points);
            s.inside_hull = in_hull(s.hull, s.point, tolerance(s.in.control_points));
            s.phase = s.in.transform ? Phase::Affine : Phase::Done;
            return;
        case Phase::Affine: {  // Map the control points and compare with the mapped point
            const Rows& m = *s.in.transform;
            s.transformed.clear();
            s.transformed_point = glm::dvec2(0);
            for (int i = 0; i <= n; ++i) {
                s.transformed.push_back(apply(m, s.in.control_points[static_cast<std::size_t>(i)]));
                s.transformed_point += s.basis[static_cast<std::size_t>(i)] * s.transformed.back();
            }
            s.image_of_point = apply(m, s.point);
            s.affine_error = glm::length(s.transformed_point - s.image_of_point);
            s.phase = Phase::Done;
            return;
        }
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// --- [narrate] ----------------------------------------------------------------------------------

// What the step just taken means, told with its numbers. `s` is the state after the step.
void Bernstein::narrate(const State& s, StepInfo& info) {
    const int n = degree(s);
    const double t = s.in.t;
    info.vars = {{"t", t}, {"n", static_cast<long long>(n)}};
    const std::vector<double> so_far(s.basis.begin(), s.basis.begin() + (s.i + 1));
    if (s.phase == Phase::Basis || s.phase == Phase::Sum) {  // a basis function was just computed
        const int i = s.i;
        const double c = curves::binomial(n, i), b = s.basis[static_cast<std::size_t>(i)];
        info.event = "basis";
        info.line = kLineBasis;
        info.narration = basis_name(i, n) + "(" + num(t) + ") = C(" + std::to_string(n) + ", " +
                         std::to_string(i) + ")·(1 − t)" + curves::superscript(n - i) + "·t" +
                         curves::superscript(i) + " = " + num(c) + " · " + num(1 - t) +
                         curves::superscript(n - i) + " · " + num(t) + curves::superscript(i) +
                         " = " + num(b) + ".";
        info.math = basis_tex(i, n) + "(" + tex(t) + ") = \\binom{" + std::to_string(n) + "}{" +
                    std::to_string(i) + "}(1 - t)^{" + std::to_string(n - i) + "}\\,t^{" +
                    std::to_string(i) + "} = " + tex(c) + " \\cdot " + tex(1 - t) + "^{" +
                    std::to_string(n - i) + "} \\cdot " + tex(t) + "^{" + std::to_string(i) +
                    "} = " + tex(b);
        info.vars.push_back({"i", static_cast<long long>(i)});
        info.vars.push_back({"C(n, i)", c});
        info.vars.push_back({"B_i", b});
        info.vars.push_back({"basis", so_far});
        return;
    }
    info.vars.push_back({"basis", so_far});
    switch (s.phase) {
        case Phase::Sign: {
            std::string terms, terms_tex;
            for (int i = 0; i <= n; ++i) {
                terms += (i ? " + " : "") + num(s.basis[static_cast<std::size_t>(i)]);
                terms_tex += (i ? " + " : "") + tex(s.basis[static_cast<std::size_t>(i)]);
            }
            info.event = "sum";
            info.line = kLineSum;
            info.narration = "The weights add up to " + terms + " = " + num(s.sum, 15) +
                             ", as they must: ((1 − t) + t)" + curves::superscript(n) +
                             " = 1, so P(t) is an affine combination of the control points.";
            info.math = "\\sum_{i=0}^{" + std::to_string(n) + "} B_i^{" + std::to_string(n) +
                        "}(t) = " + terms_tex + " = " + tex(s.sum, 15);
            info.vars.push_back({"sum", s.sum});
            return;
        }
        case Phase::Point: {
            info.vars.push_back({"sum", s.sum});
            if (s.negative == 0) {
                info.event = "non-negative";
                info.line = kLineSign;
                info.narration =
                    "Every weight is ≥ 0 (t lies in [0, 1]), so P(t) is a convex "
                    "combination: it cannot leave the convex hull of the control points.";
                info.math = "B_i^{" + std::to_string(n) + "}(" + tex(t) +
                            ") \\ge 0 \\quad (i = 0, \\dots, " + std::to_string(n) + ")";
            } else {
                std::string which;
                for (int i = 0; i <= n; ++i)
                    if (s.basis[static_cast<std::size_t>(i)] < 0)
                        which += (which.empty() ? "" : ", ") + basis_name(i, n) + " = " +
                                 num(s.basis[static_cast<std::size_t>(i)]);
                info.event = "negative-weight";
                info.line = kLineSign;
                info.narration = "t = " + num(t) + " lies outside [0, 1], and " +
                                 std::to_string(s.negative) +
                                 (s.negative == 1 ? " weight is" : " weights are") + " negative (" +
                                 which + "): still an affine combination, but not a convex one.";
                info.math = "t = " + tex(t) + " \\notin [0, 1]";
            }
            info.vars.push_back({"negative weights", static_cast<long long>(s.negative)});
            return;
        }
        case Phase::Hull: {
            std::string terms, terms_tex;
            for (int i = 0; i <= n; ++i) {
                const double b = s.basis[static_cast<std::size_t>(i)];
                const glm::dvec2 p = s.in.control_points[static_cast<std::size_t>(i)];
                terms += (i ? " + " : "") + num(b) + "·" + num(p);
                terms_tex += (i ? " + " : "") + tex(b) + "\\," + tex(p);
            }
            info.event = "point";
            info.line = kLinePoint;
            info.narration = "P(" + num(t) + ") = " + terms + " = " + num(s.point) + ".";
            info.math = "P(" + tex(t) + ") = \\sum_i B_i^{" + std::to_string(n) +
                        "} P_i = " + terms_tex + " = " + tex(s.point);
            info.vars.push_back({"P(t)", vec(s.point)});
            return;
        }
        case Phase::Affine:
        case Phase::Done:
            if (s.phase == Phase::Affine || !s.in.transform) {
                std::string corners;
                for (glm::dvec2 p : s.hull) corners += (corners.empty() ? "" : ", ") + num(p);
                info.event = "hull";
                info.line = kLineHull;
                const std::string shape =
                    s.hull.size() >= 3
                        ? "a polygon with " + std::to_string(s.hull.size()) + " corners"
                    : s.hull.size() == 2 ? "a segment (the control points are collinear)"
                                         : "a single point";
                info.narration =
                    "The convex hull of the control points (Andrew's monotone chain) is " + shape +
                    ": " + corners + ". P(t) = " + num(s.point) +
                    (s.inside_hull ? " lies inside it."
                                   : " lies outside it: a negative weight pushed it out.");
                info.math = "H = [" + corners + "],\\quad P(" + tex(t) + ") = " + tex(s.point) +
                            (s.inside_hull ? " \\in H" : " \\notin H");
                info.vars.push_back({"P(t)", vec(s.point)});
                info.vars.push_back({"hull", rows_of(s.hull)});
                info.vars.push_back({"inside hull", s.inside_hull});
                return;
            }
            {
                const bool same = affine_ok(s);
                info.event = "affine";
                info.line = kLineAffine;
                info.narration =
                    "Mapping the control points first and then blending gives Σ B_i T(P_i) = " +
                    num(s.transformed_point) +
                    "; mapping the curve point gives T(P(t)) = " + num(s.image_of_point) +
                    ". They differ by " + num(s.affine_error, 3) +
                    (same ? " (rounding only): the curve of the mapped points is the mapped curve."
                          : ": not the same point.");
                info.math = "\\sum_i B_i\\,T(P_i) = " + tex(s.transformed_point) +
                            ",\\quad T(P(t)) = " + tex(s.image_of_point);
                info.vars.push_back({"T(P_i)", rows_of(s.transformed)});
                info.vars.push_back({"Σ B_i T(P_i)", vec(s.transformed_point)});
                info.vars.push_back({"T(P(t))", vec(s.image_of_point)});
                info.vars.push_back({"difference", s.affine_error});
            }
            return;
        default:
            return;
    }
}

// --- [step and result] --------------------------------------------------------------------------

void Bernstein::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

Bernstein::Result Bernstein::result(const State& s) {
    Result r;
    r.basis = s.basis;
    r.sum = s.sum;
    r.non_negative = s.negative == 0;
    r.point = s.point;
    r.hull = s.hull;
    r.inside_hull = s.inside_hull;
    if (s.in.transform) {
        r.transformed_point = s.transformed_point;
        r.image_of_point = s.image_of_point;
        r.affine_invariant = affine_ok(s);
    }
    return r;
}

}  // namespace cg
