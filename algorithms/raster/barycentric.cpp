// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and compute] [draw]
#include "raster/barycentric.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "raster/orient2d.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using glm::ivec3;
using Input = Barycentric::Input;
using PointResult = Barycentric::PointResult;
using Phase = Barycentric::Phase;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineArea = 1,
    kLineForEach,
    kLineProject,
    kLineAreas,
    kLineRatios,
    kLineInside,
};

const char* const kVertex[3] = {"A", "B", "C"};
const char* const kWeight[3] = {"α", "β", "γ"};
const char* const kWeightTex[3] = {"\\alpha", "\\beta", "\\gamma"};
const char* const kSubArea[3] = {"A_a", "A_b", "A_c"};
// The sub-triangle whose area gives weight i: P takes the place of vertex i.
const char* const kSubTriangle[3] = {"(P, B, C)", "(A, P, C)", "(A, B, P)"};
// The edge opposite vertex i: weight i is 0 on it.
const char* const kEdge[3] = {"BC", "CA", "AB"};

dvec2 xy(const dvec3& p) {
    return {p.x, p.y};
}

// (b − a) × (p − a): twice the signed area of (a, b, p), the formula orient2d's filter uses.
double cross2(const dvec3& a, const dvec3& b, const dvec3& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

int sign(double x) {
    return (x > 0) - (x < 0);
}

// (b − a) × (p − a) to within about an ulp, for when the plain formula's rounding gave the
// wrong sign: the six products of raw coordinates (as in orient2d_exact), each split exactly
// with fma, added into a non-overlapping expansion (Shewchuk's grow-expansion), whose
// components are then summed smallest first.
[[gnu::noinline]] double accurate_cross2(const dvec3& a, const dvec3& b, const dvec3& p) {
    const double f[6][2] = {{b.x, p.y},  {-b.x, a.y}, {-a.x, p.y},
                            {-b.y, p.x}, {b.y, a.x},  {a.y, p.x}};
    double e[12];
    int n = 0;
    for (int k = 0; k < 12; ++k) {
        const double hi = f[k / 2][0] * f[k / 2][1];
        // even k: the product; odd k: its rounding error
        double q = k % 2 == 0 ? hi : std::fma(f[k / 2][0], f[k / 2][1], -hi);
        int m = 0;
        for (int i = 0; i < n; ++i) {
            double sum, err;
            orient2d_detail::two_sum(q, e[i], sum, err);
            if (err != 0) e[m++] = err;
            q = sum;
        }
        if (q != 0) e[m++] = q;
        n = m;
    }
    double total = 0;
    for (int i = 0; i < n; ++i) total += e[i];
    return total;
}

// What every point needs of the triangle: its area and orientation (2D) or normal (3D).
struct Setup {
    double area = 0;
    dvec3 normal{0}, unit_normal{0};
    int orient = 0;
};

Setup setup(const Input& in) {
    const auto& t = in.triangle;
    Setup s;
    if (in.dim == 2) {
        s.area = cross2(t[0], t[1], t[2]) / 2;
        s.orient = orient2d(xy(t[0]), xy(t[1]), xy(t[2]));
        s.normal = {0, 0, 2 * s.area};
        s.unit_normal = {0, 0, double(s.orient)};
    } else {
        s.normal = glm::cross(t[1] - t[0], t[2] - t[0]);
        const double length = std::hypot(s.normal.x, s.normal.y, s.normal.z);  // no overflow
        s.area = length / 2;
        s.unit_normal = s.normal / length;
        s.orient = 1;
    }
    return s;
}

// 3D: the signed distance of P from the plane along n̂, and its projection P′ onto it.
void project(const Input& in, const Setup& t, const dvec3& p, PointResult& r) {
    r.distance = glm::dot(p - in.triangle[0], t.unit_normal);
    r.projected = p - r.distance * t.unit_normal;
}

// The three signed sub-areas of r.projected, and their signs measured towards the inside
// (+1: on the triangle's side of that edge, 0: on the edge's line, −1: beyond it). 2D signs
// are exact (orient2d) and a sub-area whose exact sign is 0 is exactly 0; 3D signs use the
// tolerance on the weights (|w| ≤ 1e-12 is 0).
void sub_areas(const Input& in, const Setup& t, PointResult& r, ivec3& signs) {
    const auto& v = in.triangle;
    const dvec3 p = r.projected;
    if (in.dim == 2) {
        const dvec3 a{cross2(v[1], v[2], p), cross2(v[2], v[0], p), cross2(v[0], v[1], p)};
        const int exact[3] = {orient2d(xy(v[1]), xy(v[2]), xy(p)),
                              orient2d(xy(v[2]), xy(v[0]), xy(p)),
                              orient2d(xy(v[0]), xy(v[1]), xy(p))};
        const dvec3* ends[3][2] = {{&v[1], &v[2]}, {&v[2], &v[0]}, {&v[0], &v[1]}};
        for (int i = 0; i < 3; ++i) {
            double twice = a[i];
            if (exact[i] == 0)
                twice = 0;
            else if (sign(twice) != exact[i])  // rounding flipped it: recompute accurately
                twice = accurate_cross2(*ends[i][0], *ends[i][1], p);
            r.areas[i] = twice / 2;
            signs[i] = exact[i] * t.orient;
        }
    } else {
        const dvec3& n = t.unit_normal;
        r.areas = {glm::dot(glm::cross(v[2] - v[1], p - v[1]), n) / 2,
                   glm::dot(glm::cross(v[0] - v[2], p - v[2]), n) / 2,
                   glm::dot(glm::cross(v[1] - v[0], p - v[0]), n) / 2};
        for (int i = 0; i < 3; ++i) {
            const double w = r.areas[i] / t.area;
            signs[i] = std::fabs(w) <= Barycentric::kEdgeTolerance3 ? 0 : sign(w);
        }
    }
}

void ratios(const Setup& t, PointResult& r) {
    r.weights = r.areas / t.area;
}

void classify(const ivec3& signs, PointResult& r) {
    r.inside = signs[0] >= 0 && signs[1] >= 0 && signs[2] >= 0;
    r.on_edge = r.inside && (signs[0] == 0 || signs[1] == 0 || signs[2] == 0);
}

// A point as the input has it: (x, y) in 2D, (x, y, z) in 3D.
std::string pt(int dim, const dvec3& p, int digits = 6) {
    return dim == 2 ? num(xy(p), digits) : num(p, digits);
}
std::vector<double> pt_vec(int dim, const dvec3& p) {
    return dim == 2 ? vec(xy(p)) : vec(p);
}

std::string coordinate_name(const std::string& base, std::size_t k, int c) {
    return base + "[" + std::to_string(k) + "][" + std::to_string(c) + "]";
}

void check_coordinate(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
    if (std::fabs(v) > Barycentric::kMaxCoordinate)
        throw InputError(field, "must lie within ±1e100 (got " + given(v) +
                                    "): products of coordinates must not overflow");
    if (v != 0 && std::fabs(v) < Barycentric::kMinCoordinate)
        throw InputError(field, "must be 0 or at least 1e-100 in size (got " + given(v) +
                                    "): products of coordinates must not underflow");
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Barycentric::spec() {
    static const Spec spec{
        "barycentric",
        "Barycentric coordinates",
        "Polygons",
        {
            "area ← area(A, B, C)   ▷ 2D: ½ (B − A) × (C − A), signed;  3D: n ← (B − A) × (C − A), "
            "area ← |n|/2",
            "for each point P:",
            "    (3D) N ← n/|n|;  d ← (P − A) · N;  P′ ← P − d N     ▷ onto the plane",
            "    A_a ← area(P, B, C),  A_b ← area(A, P, C),  A_c ← area(A, B, P)   ▷ signed",
            "    α ← A_a / area,  β ← A_b / area,  γ ← A_c / area   ▷ α + β + γ = 1, P = αA + βB "
            "+ γC",
            "    inside ← α, β, γ ≥ 0;  on_edge ← inside and some weight = 0",
        },
        {
            {"area", "the whole triangle's area: 2D signed (its orientation), 3D from the normal"},
            {"project", "3D: the point's distance from the plane, and its projection P′ onto it"},
            {"areas", "the three signed sub-areas, P in place of A, B and C in turn"},
            {"ratios", "the weights: each sub-area over the whole area; they sum to 1"},
            {"inside", "all three weights > 0: the point is strictly inside"},
            {"on-edge", "all weights ≥ 0 and one (or two, at a vertex) is 0: on the boundary"},
            {"outside", "a weight < 0: the point is beyond the edge opposite that vertex"},
        },
        {},  // no sliders
        {
            .predict = {
                {"area", {"area"}},
                {"areas", {"A_a", "A_b"}},
                {"ratios", {"alpha", "beta"}},
                {"inside", {}},
                {"on-edge", {}},
                {"outside", {}},
            },
            .mistakes = {
                {"areas", "A_a", "negate",
                 "went round the sub-triangle clockwise: its area flipped sign"},
                {"ratios", "alpha", "swap:beta", "paired the areas with the wrong vertices"},
                {"outside", "", "event:inside",
                 "missed the negative weight and called the point inside"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Barycentric::validate(const Input& in) {
    if (in.dim != 2 && in.dim != 3)
        throw InputError("triangle", "must have 2D or 3D vertices (got dimension " +
                                         std::to_string(in.dim) + ")");
    for (std::size_t k = 0; k < 3; ++k)
        for (int c = 0; c < in.dim; ++c)
            check_coordinate(in.triangle[k][c], coordinate_name("triangle", k, c));
    if (in.points.empty())
        throw InputError("points", "must list at least one point [x, y] or [x, y, z]");
    if (in.points.size() > kMaxPoints)
        throw InputError("points", "must list at most " + std::to_string(kMaxPoints) +
                                       " points (got " + std::to_string(in.points.size()) + ")");
    for (std::size_t k = 0; k < in.points.size(); ++k)
        for (int c = 0; c < in.dim; ++c)
            check_coordinate(in.points[k][c], coordinate_name("points", k, c));

    const auto& v = in.triangle;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (v[i] == v[j])
            throw InputError("triangle", std::string("is degenerate: ") + kVertex[std::min(i, j)] +
                                             " and " + kVertex[std::max(i, j)] +
                                             " are the same point, so the triangle has no area "
                                             "and barycentric coordinates are not defined");
    }
    const Setup t = setup(in);
    if (in.dim == 2 ? t.orient == 0 : t.area == 0)
        throw InputError("triangle",
                         "is degenerate: A, B and C lie on one line (its area is 0), so "
                         "barycentric coordinates are not defined");
    double longest = 0;  // the longest edge, squared
    for (int i = 0; i < 3; ++i) {
        const dvec3 e = v[(i + 1) % 3] - v[i];
        longest = std::max(longest, glm::dot(e, e));
    }
    if (2 * std::fabs(t.area) < kMinShape * longest)
        throw InputError("triangle",
                         "is degenerate: A, B and C lie (nearly) on one line — its height is " +
                             given(2 * std::fabs(t.area) / std::sqrt(longest), 4) +
                             ", below 1e-9 of its longest edge (" + given(std::sqrt(longest), 4) +
                             "), so the weights would be ratios of nearly vanishing areas");
}

Barycentric::State Barycentric::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Barycentric::advance(State& s) {
    const Input& in = *s.in;
    const Phase first = in.dim == 3 ? Phase::Project : Phase::Areas;  // a point's first step
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Area: {  // The whole triangle
            const Setup t = setup(in);
            s.area = t.area;
            s.normal = t.normal;
            s.unit_normal = t.unit_normal;
            s.orient = t.orient;
            s.results.reserve(in.points.size());
            s.phase = first;
            return;
        }
        case Phase::Project:  // 3D: onto the plane
            ++s.k;
            s.cur = {};
            project(in, {s.area, s.normal, s.unit_normal, s.orient}, in.points[s.k], s.cur);
            s.phase = Phase::Areas;
            return;
        case Phase::Areas:  // The three signed sub-areas
            if (in.dim == 2) {
                ++s.k;
                s.cur = {};
                s.cur.projected = in.points[s.k];
            }
            sub_areas(in, {s.area, s.normal, s.unit_normal, s.orient}, s.cur, s.signs);
            s.phase = Phase::Ratios;
            return;
        case Phase::Ratios:  // The weights
            ratios({s.area, s.normal, s.unit_normal, s.orient}, s.cur);
            s.phase = Phase::Inside;
            return;
        case Phase::Inside:  // The inside test
            classify(s.signs, s.cur);
            s.results.push_back(s.cur);
            s.phase = s.k + 1 < std::ssize(in.points) ? first : Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = Barycentric::State;

void narrate_area(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& v = in.triangle;
    info.event = "area";
    info.line = kLineArea;
    const std::string points =
        "A = " + pt(in.dim, v[0]) + ", B = " + pt(in.dim, v[1]) + ", C = " + pt(in.dim, v[2]);
    if (in.dim == 2) {
        const dvec3 ab = v[1] - v[0], ac = v[2] - v[0];
        info.narration =
            points + ": area = ½ (B − A) × (C − A) = ½ ((" + num(ab.x) + ")(" + num(ac.y) +
            ") − (" + num(ab.y) + ")(" + num(ac.x) + ")) = " + num(s.area) +
            (s.orient > 0
                 ? " > 0: A, B, C turn counter-clockwise."
                 : " < 0: A, B, C turn clockwise; the sub-areas are signed the same way, so "
                   "the ratios come out the same.");
        info.math = "\\text{area} = \\tfrac{1}{2}\\,(B - A) \\times (C - A) = \\tfrac{1}{2}((" +
                    tex(ab.x) + ")(" + tex(ac.y) + ") - (" + tex(ab.y) + ")(" + tex(ac.x) +
                    ")) = " + tex(s.area);
    } else {
        info.narration = points + ": n = (B − A) × (C − A) = " + num(v[1] - v[0]) + " × " +
                         num(v[2] - v[0]) + " = " + num(s.normal) + ", |n| = " + num(2 * s.area) +
                         ", so area = |n|/2 = " + num(s.area) +
                         " and the unit normal N = n/|n| = " + num(s.unit_normal, 4) + ".";
        info.math = "n = (B - A) \\times (C - A) = " + tex(s.normal) +
                    ",\\; \\text{area} = \\tfrac{|n|}{2} = " + tex(s.area) +
                    ",\\; N = " + tex(s.unit_normal, 4);
    }
}

void narrate_project(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const dvec3 p = in.points[s.k];
    info.event = "project";
    info.line = kLineProject;
    const std::string name = "P" + std::to_string(s.k) + " = " + num(p);
    if (s.cur.distance == 0)
        info.narration = name + ": d = (P − A) · N = 0, it lies in the triangle's plane: P′ = P.";
    else
        info.narration = name + ": d = (P − A) · N = " + num(s.cur.distance) + ", so it is " +
                         num(std::fabs(s.cur.distance)) + " off the plane (" +
                         (s.cur.distance > 0 ? "on the side n points to" : "behind it") +
                         "). Its projection P′ = P − d N = " + num(s.cur.projected) +
                         " is what the weights describe.";
    info.math = "d = (P - A) \\cdot N = " + tex(s.cur.distance) +
                ",\\; P' = P - d\\,N = " + tex(s.cur.projected);
}

void narrate_areas(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "areas";
    info.line = kLineAreas;
    const std::string p = in.dim == 2 ? "P" + std::to_string(s.k) + " = " + pt(2, s.cur.projected)
                                      : "P′ = " + num(s.cur.projected);
    std::string text = p + ": ";
    for (int i = 0; i < 3; ++i)
        text += std::string(i ? ", " : "") + kSubArea[i] + " = area" + kSubTriangle[i] + " = " +
                num(s.cur.areas[i]);
    const double sum = s.cur.areas[0] + s.cur.areas[1] + s.cur.areas[2];
    text += " (sum " + num(sum) + ", the whole area).";
    std::string beyond;
    for (int i = 0; i < 3; ++i)
        if (s.signs[i] < 0) beyond += std::string(beyond.empty() ? "" : ", ") + kEdge[i];
    if (!beyond.empty())
        text +=
            " A sub-area with the opposite sign to the whole: P is beyond the edge " + beyond + ".";
    info.narration = text;
    info.math = "A_a = " + tex(s.cur.areas[0]) + ",\\; A_b = " + tex(s.cur.areas[1]) +
                ",\\; A_c = " + tex(s.cur.areas[2]) + ",\\; A_a + A_b + A_c = " + tex(sum);
}

void narrate_ratios(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& v = in.triangle;
    info.event = "ratios";
    info.line = kLineRatios;
    std::string text;
    for (int i = 0; i < 3; ++i)
        text += std::string(i ? ", " : "") + kWeight[i] + " = " + kSubArea[i] +
                " / area = " + num(s.cur.areas[i]) + " / " + num(s.area) + " = " +
                num(s.cur.weights[i]);
    const dvec3& w = s.cur.weights;
    const dvec3 back = w[0] * v[0] + w[1] * v[1] + w[2] * v[2];
    text += ". α + β + γ = " + num(w[0] + w[1] + w[2]) +
            ", and αA + βB + γC = " + pt(in.dim, back) + (in.dim == 2 ? " = P." : " = P′.");
    info.narration = text;
    info.math =
        std::string("(\\alpha, \\beta, \\gamma) = \\frac{(A_a, A_b, A_c)}{\\text{area}} = ") +
        tex(w) + ",\\; \\alpha + \\beta + \\gamma = " + tex(w[0] + w[1] + w[2]);
}

void narrate_inside(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const PointResult& r = s.cur;
    info.line = kLineInside;
    const std::string p = "P" + std::to_string(s.k);
    const std::string rule = in.dim == 2 ? "" : " (3D: a weight within 1e-12 of 0 counts as 0)";
    int zeros = 0, zero = -1, other = -1;
    for (int i = 0; i < 3; ++i)
        if (s.signs[i] == 0) ++zeros, (zero < 0 ? zero : other) = i;
    if (!r.inside) {
        info.event = "outside";
        std::string which;
        for (int i = 0; i < 3; ++i)
            if (s.signs[i] < 0)
                which += std::string(which.empty() ? "" : " and ") + kWeight[i] +
                         " < 0 (on the far side of " + kEdge[i] + " from " + kVertex[i] + ")";
        info.narration = which + ": " + p + " is outside the triangle." + rule;
        info.math = "\\text{inside} = \\text{false}";
    } else if (zeros == 0) {
        info.event = "inside";
        info.narration = "α, β, γ are all > 0: " + p + " is strictly inside the triangle." + rule;
        info.math = "\\alpha, \\beta, \\gamma > 0 \\Rightarrow \\text{inside}";
    } else {
        info.event = "on-edge";
        if (zeros == 2) {
            const int vertex = 3 - zero - other;
            info.narration = std::string(kWeight[zero]) + " = " + kWeight[other] + " = 0 and " +
                             kWeight[vertex] + " = 1: " + p + " is the vertex " + kVertex[vertex] +
                             ", on two edges. inside = true (the boundary counts), on_edge = "
                             "true." +
                             rule;
        } else {
            info.narration = std::string(kWeight[zero]) + " = 0 and the others ≥ 0: " + p +
                             " lies on the edge " + kEdge[zero] +
                             ". inside = true (the boundary counts), on_edge = true." + rule;
        }
        info.math = std::string(kWeightTex[zero]) + " = 0 \\Rightarrow \\text{on the edge}";
    }
}

void fill_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.vars = {{"area", s.area}};
    if (in.dim == 3) {
        info.vars.push_back({"n", vec(s.normal)});
        info.vars.push_back({"N", vec(s.unit_normal)});
    }
    if (s.last == Phase::Area) return;
    info.vars.push_back({"k", static_cast<long long>(s.k)});
    info.vars.push_back({"P", pt_vec(in.dim, in.points[s.k])});
    if (in.dim == 3) {
        info.vars.push_back({"d", s.cur.distance});
        info.vars.push_back({"P'", vec(s.cur.projected)});
    }
    if (s.last >= Phase::Areas) {
        info.vars.push_back({"A_a", s.cur.areas[0]});
        info.vars.push_back({"A_b", s.cur.areas[1]});
        info.vars.push_back({"A_c", s.cur.areas[2]});
    }
    if (s.last >= Phase::Ratios) {
        info.vars.push_back({"alpha", s.cur.weights[0]});
        info.vars.push_back({"beta", s.cur.weights[1]});
        info.vars.push_back({"gamma", s.cur.weights[2]});
    }
    if (s.last >= Phase::Inside) {
        info.vars.push_back({"inside", s.cur.inside});
        info.vars.push_back({"on_edge", s.cur.on_edge});
    }
}

}  // namespace

void Barycentric::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Area:
            narrate_area(s, info);
            break;
        case Phase::Project:
            narrate_project(s, info);
            break;
        case Phase::Areas:
            narrate_areas(s, info);
            break;
        case Phase::Ratios:
            narrate_ratios(s, info);
            break;
        case Phase::Inside:
        case Phase::Done:
            narrate_inside(s, info);
            break;
    }
    fill_vars(s, info);
}

void Barycentric::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

Barycentric::Result Barycentric::result(const State& s) {
    return {s.in->dim, s.area, s.normal, s.results};
}

Barycentric::Result Barycentric::result(State&& s) {
    return {s.in->dim, s.area, s.normal, std::move(s.results)};
}

Barycentric::Result Barycentric::compute(const Input& in) {
    const Setup t = setup(in);
    Result r{in.dim, t.area, t.normal, {}};
    r.results.reserve(in.points.size());
    for (const dvec3& p : in.points) {
        PointResult pr;
        ivec3 signs{0};
        if (in.dim == 3)
            project(in, t, p, pr);
        else
            pr.projected = p;
        sub_areas(in, t, pr, signs);
        ratios(t, pr);
        classify(signs, pr);
        r.results.push_back(pr);
    }
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

namespace {

// The sub-triangle opposite vertex i takes vertex i's colour: red for A, green for B, blue
// for C (translucent fills; their labels say the area and, once known, the weight).
constexpr std::uint32_t kFill[3] = {0xe0505070u, 0x40b04070u, 0x4070e070u};
constexpr std::uint32_t kInk[3] = {0xb02020ffu, 0x207a20ffu, 0x2050b0ffu};

std::array<dvec3, 3> sub_triangle(const std::array<dvec3, 3>& v, int i, const dvec3& p) {
    std::array<dvec3, 3> t = v;
    t[i] = p;
    return t;
}

std::string area_label(const State& s, int i) {
    std::string t = std::string(kSubArea[i]) + " = " + num(s.cur.areas[i], 4);
    if (s.last >= Phase::Ratios)
        t += ", " + std::string(kWeight[i]) + " = " + num(s.cur.weights[i], 4);
    return t;
}

void draw_2d(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const auto& v = in.triangle;
    const bool working = s.k >= 0 && s.last >= Phase::Areas && s.last != Phase::Done;
    if (working)
        for (int i = 0; i < 3; ++i) {
            const auto t = sub_triangle(v, i, s.cur.projected);
            // A negative sub-area (P beyond that edge) overlaps the others: outlined, dashed.
            const bool negative = s.signs[i] < 0;
            scene.polygons.push_back(
                {{xy(t[0]), xy(t[1]), xy(t[2])},
                 {Role::Neutral, negative ? 2.0f : 1.0f, negative, negative ? kInk[i] : kFill[i]},
                 true,
                 !negative});
            const dvec3 centre = (t[0] + t[1] + t[2]) / 3.0;
            scene.labels.push_back(
                {xy(centre), area_label(s, i), {Role::Neutral, 1.0f, false, kInk[i]}});
        }
    std::vector<dvec2> outline = {xy(v[0]), xy(v[1]), xy(v[2])};
    scene.polygons.push_back({outline, {Role::Subject, 2.5f}, true, false});
    const dvec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
    if (!working)
        scene.labels.push_back(
            {xy(centroid),
             s.phase == Phase::Area ? "triangle A, B, C" : "area = " + num(s.area, 4),
             {Role::Neutral}});
    for (int i = 0; i < 3; ++i)
        scene.points.push_back({xy(v[i]),
                                std::string(kVertex[i]) + " " + pt(2, v[i], 4),
                                {Role::Neutral, 2.0f, false, kInk[i]},
                                5.0f});

    for (std::size_t k = 0; k < in.points.size(); ++k) {
        const dvec2 p = xy(in.points[k]);
        const bool current = working && int(k) == s.k;
        std::string label = "P" + std::to_string(k);
        Role role = Role::Subject;
        if (k < s.results.size()) {
            const PointResult& r = s.results[k];
            role = !r.inside ? Role::Discarded : r.on_edge ? Role::Active : Role::Kept;
            label += " " + num(r.weights, 3);
        } else if (current) {
            role = Role::Active;
            label += " = " + pt(2, in.points[k], 4);
        }
        scene.points.push_back({p, label, {role}, current || k < s.results.size() ? 6.0f : 4.0f});
    }
    for (int i = 0; i < 3; ++i) {
        const std::string I = std::to_string(i);
        scene.handles.push_back(
            {xy(v[i]), kVertex[i], "/triangle/" + I + "/0", "/triangle/" + I + "/1"});
    }
    for (std::size_t k = 0; k < in.points.size(); ++k) {
        const std::string K = std::to_string(k);
        scene.handles.push_back(
            {xy(in.points[k]), "P" + K, "/points/" + K + "/0", "/points/" + K + "/1"});
    }
}

void draw_3d(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const auto& v = in.triangle;
    const bool working = s.k >= 0 && s.last != Phase::Done && s.last != Phase::Area;
    const bool areas = working && s.last >= Phase::Areas;
    scene.faces3.push_back(
        {{v[0], v[1], v[2]}, {Role::Subject, 2.0f}, areas ? 0.08f : 0.25f, true, true});
    if (areas)
        for (int i = 0; i < 3; ++i) {
            const auto t = sub_triangle(v, i, s.cur.projected);
            scene.faces3.push_back({{t[0], t[1], t[2]},
                                    {Role::Neutral, 1.0f, s.signs[i] < 0, kFill[i] | 0xffu},
                                    s.signs[i] < 0 ? 0.15f : 0.45f,
                                    true,
                                    true});
            scene.labels3.push_back({(t[0] + t[1] + t[2]) / 3.0,
                                     area_label(s, i),
                                     {Role::Neutral, 1.0f, false, kInk[i]}});
        }
    const dvec3 centroid = (v[0] + v[1] + v[2]) / 3.0;
    // Seen nearly face-on (orthographic, 25° off the triangle's normal, from the side the
    // default camera is on), so the sub-triangles' areas compare as they are and a point's
    // drop d onto the plane still shows; framed on the triangle and the points.
    const dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
    if (glm::length(n) > 0) {
        dvec3 u = glm::normalize(n);
        if (glm::dot(u, dvec3(0.54, 0.34, 0.77)) < 0) u = -u;
        dvec3 up = dvec3(0, 1, 0) - glm::dot(dvec3(0, 1, 0), u) * u;
        if (glm::length(up) < 1e-6) up = dvec3(0, 0, -1) - glm::dot(dvec3(0, 0, -1), u) * u;
        up = glm::normalize(up);
        const dvec3 from = std::cos(0.44) * u - std::sin(0.44) * up;  // 25° below the normal
        scene.view3 = {-from, up, true};
    }
    dvec3 lo = v[0], hi = v[0];
    for (const dvec3& q : v) lo = glm::min(lo, q), hi = glm::max(hi, q);
    for (const dvec3& q : in.points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    add_focus(scene, lo, hi);
    if (s.phase != Phase::Area) {
        double size = 0;
        for (int i = 0; i < 3; ++i) size = std::max(size, glm::length(v[i] - centroid));
        scene.segments3.push_back({centroid,
                                   centroid + 0.5 * size * s.unit_normal,
                                   "N = n/|n|",
                                   {Role::Construction, 2.0f},
                                   true,
                                   0,
                                   -1});
        if (!areas)
            scene.labels3.push_back({centroid, "area = " + num(s.area, 4), {Role::Neutral}});
    }
    for (int i = 0; i < 3; ++i)
        scene.points3.push_back({v[i], kVertex[i], {Role::Neutral, 2.0f, false, kInk[i]}, 5.0f});
    for (std::size_t k = 0; k < in.points.size(); ++k) {
        const dvec3 p = in.points[k];
        const bool current = working && int(k) == s.k;
        std::string label = "P" + std::to_string(k);
        Role role = Role::Subject;
        if (k < s.results.size()) {
            const PointResult& r = s.results[k];
            role = !r.inside ? Role::Discarded : r.on_edge ? Role::Active : Role::Kept;
        } else if (current) {
            role = Role::Active;
        }
        scene.points3.push_back({p, label, {role}, current ? 6.0f : 4.0f});
        // (A drop of rounding noise, d printed as 0, is no drop.)
        if (current && std::fabs(s.cur.distance) > 1e-12 * std::max(1.0, glm::length(hi - lo))) {
            scene.segments3.push_back({p,
                                       s.cur.projected,
                                       "d = " + num(s.cur.distance, 4),
                                       {Role::Construction, 1.5f, true},
                                       false});
            scene.points3.push_back({s.cur.projected, "P′", {Role::Active}, 5.0f, 1});
        }
    }
}

}  // namespace

void Barycentric::draw(const State& s, Scene& scene) {
    if (s.in->dim == 2)
        draw_2d(s, scene);
    else
        draw_3d(s, scene);
}

}  // namespace cg
