// Sections: [spec] [start] [advance] [narrate] [step and result] [draw].
#include "curves/de_casteljau.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using curves::point_name;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineInit = 1,
    kLineLevels,
    kLinePoints,
    kLineLerp,
    kLinePoint,
    kLineTangent,
    kLineSubdivide,
};

// A point with as many coordinates as the input has.
std::string pt(glm::dvec3 p, int dim) {
    return dim == 3 ? num(p) : num(curves::xy(p));
}
std::string pt_tex(glm::dvec3 p, int dim) {
    return dim == 3 ? tex(p) : tex(curves::xy(p));
}
std::vector<double> coords(glm::dvec3 p, int dim) {
    return dim == 3 ? vec(p) : std::vector<double>{p.x, p.y};
}
std::vector<std::vector<double>> coords(const std::vector<glm::dvec3>& ps, int dim) {
    std::vector<std::vector<double>> m;
    for (const glm::dvec3& p : ps) m.push_back(coords(p, dim));
    return m;
}

// "P_1^2" for LaTeX; level 0 is written P_i, as the course does.
std::string name_tex(int i, int k) {
    return "P_{" + std::to_string(i) + "}" + (k > 0 ? "^{" + std::to_string(k) + "}" : "");
}
std::string name_text(int i, int k) {
    return k > 0 ? point_name(i, k) : point_name(i);
}

DeCasteljau::Result view(const DeCasteljau::State& s) {
    DeCasteljau::Result r;
    r.dim = s.dim, r.n = s.n, r.t = s.t, r.point = s.point, r.tangent = s.tangent;
    r.levels = s.levels;
    return r;
}

glm::dvec3 at(const DeCasteljau::State& s, int k, int i) {
    return s.levels[DeCasteljau::offset(s.n, k) + static_cast<std::size_t>(i)];
}

std::string extrapolation_note(const DeCasteljau::State& s) {
    if (s.t >= 0 && s.t <= 1) return "";
    return "t = " + num(s.t) +
           " lies outside [0, 1], so this extrapolates: the new points lie on "
           "the extensions of the segments, not between their ends. ";
}

// The points of level k as one sentence: all of them when few, else the first two and the last.
std::string level_text(const DeCasteljau::State& s, int k) {
    const int count = s.n + 1 - k;
    std::string out;
    for (int i = 0; i < count; ++i) {
        if (count > 4 && i == 2) {
            out += ", …";
            i = count - 2;
            continue;
        }
        out += (i ? ", " : "") + name_text(i, k) + " = " + pt(at(s, k, i), s.dim);
    }
    return out;
}

// P_i^k = (1 − t) P_i^{k−1} + t P_{i+1}^{k−1} with the numbers, for each point of level k
// (only the values when the level is long).
std::string level_tex(const DeCasteljau::State& s, int k) {
    const int count = s.n + 1 - k;
    std::string out;
    for (int i = 0; i < count; ++i) {
        out += i ? ",\\quad " : "";
        out += name_tex(i, k) + " = ";
        if (count <= 4)
            out += tex(1 - s.t) + "\\," + pt_tex(at(s, k - 1, i), s.dim) + " + " + tex(s.t) +
                   "\\," + pt_tex(at(s, k - 1, i + 1), s.dim) + " = ";
        out += pt_tex(at(s, k, i), s.dim);
    }
    return out;
}

}  // namespace

// --- [spec] -------------------------------------------------------------------------------------

const Spec& DeCasteljau::spec() {
    static const Spec spec{
        "de-casteljau",
        "De Casteljau's algorithm: evaluating and splitting a Bézier curve",
        "Splines",
        {
            "P_i^0 ← P_i  for i = 0 .. n",
            "for k = 1 .. n:",
            "    for i = 0 .. n − k:",
            "        P_i^k ← (1 − t) P_i^{k−1} + t P_{i+1}^{k−1}",
            "P(t) ← P_0^n",
            "P′(t) ← n (P_1^{n−1} − P_0^{n−1})",
            "left ← [P_0^0, P_0^1, …, P_0^n],  right ← [P_0^n, P_1^{n−1}, …, P_n^0]",
        },
        {
            {"level",
             "one level of the triangle: each point t of the way along a segment of the level "
             "before"},
            {"point", "the last level has one point: the curve point P(t)"},
            {"tangent", "the last segment gives the tangent P′(t) = n (P_1^{n−1} − P_0^{n−1})"},
            {"subdivide",
             "the triangle's two edges are the control polygons of the curve's halves"},
        },
        {{"/t", "t", 0, 1}},
        {
            .predict = {
                {"level", {}},
                {"point", {"P(t)"}},
                {"tangent", {"P′(t)"}},
                {"subdivide", {"left", "right"}},
            },
            .mistakes = {
                {"tangent", "P′(t)", "negate", "took the last difference the wrong way round"},
                {"subdivide", "right", "reverse",
                 "listed the right half's control points backwards"},
            },
        },
    };
    return spec;
}

std::vector<glm::dvec3> DeCasteljau::Result::level(int k) const {
    std::vector<glm::dvec3> out;
    for (int i = 0; i <= n - k; ++i) out.push_back(at(k, i));
    return out;
}

std::vector<glm::dvec3> DeCasteljau::Result::left() const {
    std::vector<glm::dvec3> out;
    for (int k = 0; k <= n; ++k) out.push_back(at(k, 0));
    return out;
}

std::vector<glm::dvec3> DeCasteljau::Result::right() const {
    std::vector<glm::dvec3> out;
    for (int k = n; k >= 0; --k) out.push_back(at(k, n - k));
    return out;
}

// --- [start] ------------------------------------------------------------------------------------

void DeCasteljau::validate(const Input& in) {
    curves::validate_points(in.control_points, in.dim, "control_points", 2);
    curves::validate_t(in.t, in.extrapolate);
}

DeCasteljau::State DeCasteljau::start(const Input& in) {
    validate(in);
    return begin(in);
}

DeCasteljau::State DeCasteljau::begin(const Input& in) {
    State s;
    s.dim = in.dim;
    s.n = static_cast<int>(in.control_points.size()) - 1;
    s.t = in.t;
    s.extrapolate = in.extrapolate;
    s.phase = s.n >= 2 ? Phase::Level : Phase::Point;
    s.levels.resize(offset(s.n, s.n) + 1);
    std::copy(in.control_points.begin(), in.control_points.end(), s.levels.begin());
    return s;
}

// --- [advance] ----------------------------------------------------------------------------------

// The algorithm proper: one step of the math. Kept apart from the narration below so that
// running to completion (no StepInfo) costs about what the plain evaluate() does.
void DeCasteljau::advance(State& s) {
    const double t = s.t, u = 1 - t;
    switch (s.phase) {
        case Phase::Level: {  // Interpolate each neighbouring pair of the level before
            const int k = ++s.k;
            glm::dvec3* prev = s.levels.data() + offset(s.n, k - 1);
            glm::dvec3* next = s.levels.data() + offset(s.n, k);
            for (int i = 0; i <= s.n - k; ++i) next[i] = u * prev[i] + t * prev[i + 1];
            if (k + 1 == s.n) s.phase = Phase::Point;
            return;
        }
        case Phase::Point: {  // The last level: one point, on the curve
            const int k = s.k = s.n;
            const glm::dvec3* prev = s.levels.data() + offset(s.n, k - 1);
            s.point = s.levels[offset(s.n, k)] = u * prev[0] + t * prev[1];
            s.phase = Phase::Tangent;
            return;
        }
        case Phase::Tangent: {  // The last segment is tangent to the curve
            const glm::dvec3* last = s.levels.data() + offset(s.n, s.n - 1);
            s.tangent = static_cast<double>(s.n) * (last[1] - last[0]);
            s.phase = Phase::Subdivide;
            return;
        }
        case Phase::Subdivide:  // The triangle's edges: two control polygons (read off in result)
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// --- [narrate] ----------------------------------------------------------------------------------

// What the step just taken means, told with its numbers. `s` is the state after the step.
void DeCasteljau::narrate(const State& s, StepInfo& info) {
    const Result r = view(s);
    info.vars = {{"t", s.t}, {"n", static_cast<long long>(s.n)}};
    if (s.phase == Phase::Level || (s.phase == Phase::Point && s.k < s.n)) {
        // A level 1 .. n − 1 was just computed.
        const int k = s.k;
        info.event = "level";
        info.line = kLineLerp;
        info.narration = (k == 1 ? extrapolation_note(s) : "") + "Level " + std::to_string(k) +
                         ": each point lies " + num(s.t) + " of the way from one point of level " +
                         std::to_string(k - 1) + " to the next: " + level_text(s, k) + ".";
        info.math = level_tex(s, k);
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"level " + std::to_string(k), coords(r.level(k), s.dim)});
    } else if (s.phase == Phase::Tangent) {
        const int n = s.n;
        const glm::dvec3 a = at(s, n - 1, 0), b = at(s, n - 1, 1);
        info.event = "point";
        info.line = kLinePoint;
        info.narration = (n == 1 ? extrapolation_note(s) : "") + "The last level has one point, " +
                         name_text(0, n) + " = " + num(1 - s.t) + "·" + pt(a, s.dim) + " + " +
                         num(s.t) + "·" + pt(b, s.dim) + " = " + pt(s.point, s.dim) +
                         ": the curve point P(" + num(s.t) + ").";
        info.math = "P(" + tex(s.t) + ") = " + name_tex(0, n) + " = " + tex(1 - s.t) + "\\," +
                    pt_tex(a, s.dim) + " + " + tex(s.t) + "\\," + pt_tex(b, s.dim) + " = " +
                    pt_tex(s.point, s.dim);
        info.vars.push_back({"k", static_cast<long long>(n)});
        info.vars.push_back({"P(t)", coords(s.point, s.dim)});
    } else if (s.phase == Phase::Subdivide) {
        const int n = s.n;
        const glm::dvec3 a = at(s, n - 1, 0), b = at(s, n - 1, 1);
        info.event = "tangent";
        info.line = kLineTangent;
        info.narration = "The last segment, " + name_text(0, n - 1) + " → " + name_text(1, n - 1) +
                         ", touches the curve at P(t); the derivative is " + std::to_string(n) +
                         " times it: P′(" + num(s.t) + ") = " + std::to_string(n) + "·(" +
                         pt(b, s.dim) + " − " + pt(a, s.dim) + ") = " + pt(s.tangent, s.dim) + ".";
        info.math = "P'(" + tex(s.t) + ") = " + std::to_string(n) + "\\left(" + name_tex(1, n - 1) +
                    " - " + name_tex(0, n - 1) + "\\right) = " + std::to_string(n) + "\\left(" +
                    pt_tex(b, s.dim) + " - " + pt_tex(a, s.dim) +
                    "\\right) = " + pt_tex(s.tangent, s.dim);
        info.vars.push_back({"P(t)", coords(s.point, s.dim)});
        info.vars.push_back({"P′(t)", coords(s.tangent, s.dim)});
    } else {
        const std::vector<glm::dvec3> left = r.left(), right = r.right();
        auto list = [&](const std::vector<glm::dvec3>& ps, bool as_tex) {
            std::string out;
            for (std::size_t i = 0; i < ps.size(); ++i)
                out += (i ? ", " : "") + (as_tex ? pt_tex(ps[i], s.dim) : pt(ps[i], s.dim));
            return out;
        };
        info.event = "subdivide";
        info.line = kLineSubdivide;
        info.narration = "Splitting at t = " + num(s.t) +
                         ": the first point of every level gives the "
                         "left half's control polygon [" +
                         list(left, false) + "], the last point of every level the right half's [" +
                         list(right, false) + "].";
        info.math = "\\text{left} = [" + list(left, true) + "],\\quad \\text{right} = [" +
                    list(right, true) + "]";
        info.vars.push_back({"P(t)", coords(s.point, s.dim)});
        info.vars.push_back({"P′(t)", coords(s.tangent, s.dim)});
        info.vars.push_back({"left", coords(left, s.dim)});
        info.vars.push_back({"right", coords(right, s.dim)});
    }
}

// --- [step and result] --------------------------------------------------------------------------

void DeCasteljau::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

DeCasteljau::Result DeCasteljau::result(const State& s) {
    return view(s);
}

DeCasteljau::Result DeCasteljau::evaluate(const Input& in) {
    Result r;
    const int n = static_cast<int>(in.control_points.size()) - 1;
    const double t = in.t, u = 1 - t;
    r.dim = in.dim, r.n = n, r.t = t;
    r.levels.resize(offset(n, n) + 1);
    glm::dvec3* p = r.levels.data();
    std::copy(in.control_points.begin(), in.control_points.end(), p);
    for (int k = 1; k <= n; ++k) {
        glm::dvec3* prev = p + offset(n, k - 1);
        glm::dvec3* next = p + offset(n, k);
        for (int i = 0; i <= n - k; ++i) next[i] = u * prev[i] + t * prev[i + 1];
    }
    const glm::dvec3* last = p + offset(n, n - 1);
    r.point = p[offset(n, n)];
    r.tangent = static_cast<double>(n) * (last[1] - last[0]);
    return r;
}

// --- [draw] -------------------------------------------------------------------------------------

namespace {

// The curve from t0 to t1 as a chain of 3D segments (a 3D picture has no polylines).
void curve3(std::span<const glm::dvec3> control, double t0, double t1, Style style, Scene& scene) {
    constexpr int kSamples = 80;
    glm::dvec3 prev = curves::bezier_point(control, t0);
    for (int i = 1; i <= kSamples; ++i) {
        const glm::dvec3 p = curves::bezier_point(control, t0 + (t1 - t0) * i / kSamples);
        scene.segments3.push_back({prev, p, "", style, false});
        prev = p;
    }
}

void chain3(const std::vector<glm::dvec3>& points, Style style, Scene& scene) {
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        scene.segments3.push_back({points[i], points[i + 1], "", style, false});
}

}  // namespace

// 3D control points: the same construction on the 3D canvas (orbit it to see the levels'
// planes); the handles are 2D-only, so points are edited by typing.
void DeCasteljau::draw3(const State& s, Scene& scene) {
    const int n = s.n;
    const std::span<const glm::dvec3> control{s.levels.data(), static_cast<std::size_t>(n + 1)};
    const bool finished = s.phase == Phase::Done;
    const bool label_all = n <= 4;
    curve3(control, 0, 1, {Role::Construction, 3.0f}, scene);
    if (s.t < 0 || s.t > 1)
        curve3(control, std::min(s.t, 1.0), std::max(s.t, 0.0), {Role::Construction, 2.0f, true},
               scene);
    chain3({control.begin(), control.end()}, {Role::Subject, 1.5f}, scene);
    for (int i = 0; i <= n; ++i)
        scene.points3.push_back({control[static_cast<std::size_t>(i)], point_name(i), {Role::Subject}, 4.5f});
    const int last_level = std::min(s.k, n - 1);
    for (int k = 1; k <= last_level; ++k) {
        const bool newest = k == last_level && !finished && s.phase != Phase::Subdivide;
        const std::uint32_t rgba = curves::shade(k);
        std::vector<glm::dvec3> pts;
        for (int i = 0; i <= n - k; ++i) pts.push_back(at(s, k, i));
        chain3(pts, {Role::Neutral, newest ? 2.5f : 1.5f, false, rgba}, scene);
        for (int i = 0; i <= n - k; ++i)
            scene.points3.push_back({pts[static_cast<std::size_t>(i)],
                                     (label_all || newest) && !finished ? point_name(i, k) : "",
                                     {Role::Neutral, 1.5f, false, rgba},
                                     newest ? 5.0f : 4.0f});
    }
    if (s.k == n) {
        if (s.phase == Phase::Subdivide)
            scene.segments3.push_back({s.point, s.point + s.tangent / static_cast<double>(n),
                                       "P′(t)/" + std::to_string(n), {Role::Active, 3.0f}, true});
        scene.points3.push_back({s.point, "P(" + num(s.t, 4) + ")", {Role::Kept}, 6.5f});
    }
    if (finished) {
        const Result r = view(s);
        chain3(r.left(), {Role::Entering, 3.0f}, scene);
        chain3(r.right(), {Role::Leaving, 3.0f}, scene);
    }
}

void DeCasteljau::draw(const State& s, Scene& scene) {
    if (s.dim == 3) return draw3(s, scene);
    const int n = s.n;
    const std::span<const glm::dvec3> control{s.levels.data(), static_cast<std::size_t>(n + 1)};
    const bool finished = s.phase == Phase::Done;
    const bool label_all = n <= 4;

    // The whole curve, faintly, underneath; its continuation too when extrapolating.
    scene.polygons.push_back(
        {curves::bezier_polyline(control, 0, 1), {Role::Construction, 3.0f}, false, false});
    if (s.t < 0 || s.t > 1)
        scene.polygons.push_back(
            {curves::bezier_polyline(control, std::min(s.t, 1.0), std::max(s.t, 0.0)),
             {Role::Construction, 2.0f, true},
             false,
             false});

    // Level 0: the control polygon.
    std::vector<glm::dvec2> polygon;
    for (const glm::dvec3& p : control) polygon.push_back(curves::xy(p));
    scene.polygons.push_back({polygon, {Role::Subject, 1.5f}, false, false});
    for (int i = 0; i <= n; ++i)
        scene.points.push_back(
            {polygon[static_cast<std::size_t>(i)], point_name(i), {Role::Subject}, 4.5f});

    // Levels 1 .. k, each in its own shade; the newest one bolder.
    const int last_level = std::min(s.k, n - 1);
    for (int k = 1; k <= last_level; ++k) {
        const bool newest = k == last_level && !finished && s.phase != Phase::Subdivide;
        const std::uint32_t rgba = curves::shade(k);
        std::vector<glm::dvec2> pts;
        for (int i = 0; i <= n - k; ++i) pts.push_back(curves::xy(at(s, k, i)));
        if (pts.size() > 1)
            scene.polygons.push_back(
                {pts, {Role::Neutral, newest ? 2.5f : 1.5f, false, rgba}, false, false});
        for (int i = 0; i <= n - k; ++i)
            scene.points.push_back({pts[static_cast<std::size_t>(i)],
                                    (label_all || newest) && !finished ? point_name(i, k) : "",
                                    {Role::Neutral, 1.5f, false, rgba},
                                    newest ? 5.0f : 4.0f});
    }

    if (s.k == n) {  // the curve point, then the tangent along the last segment
        if (s.phase == Phase::Subdivide) {  // (the last step leaves the edges to the halves)
            const glm::dvec2 p = curves::xy(s.point),
                             d = curves::xy(s.tangent) / static_cast<double>(n);
            scene.segments.push_back(
                {p, p + d, "P′(t)/" + std::to_string(n), {Role::Active, 3.0f}, true});
        }
        scene.points.push_back({curves::xy(s.point), "P(" + num(s.t, 4) + ")", {Role::Kept}, 6.5f});
    }

    if (finished) {  // the two halves' control polygons, over the triangle's edges
        // The halves of the curve itself, tinted: each is the Bézier curve of its polygon.
        // (Left covers [0, t] and right [t, 1], also when t is outside [0, 1].)
        scene.polygons.push_back({curves::bezier_polyline(control, 0, s.t, 50),
                                  {Role::Neutral, 3.0f, false, 0x009e9470},
                                  false,
                                  false});
        scene.polygons.push_back({curves::bezier_polyline(control, s.t, 1, 50),
                                  {Role::Neutral, 3.0f, false, 0xd0189c70},
                                  false,
                                  false});
        const Result r = view(s);
        std::vector<glm::dvec2> left, right;
        for (const glm::dvec3& p : r.left()) left.push_back(curves::xy(p));
        for (const glm::dvec3& p : r.right()) right.push_back(curves::xy(p));
        scene.polygons.push_back({left, {Role::Entering, 3.0f}, false, false});
        scene.polygons.push_back({right, {Role::Leaving, 3.0f}, false, false});
        for (std::size_t i = 1; i + 1 < left.size(); ++i)
            scene.points.push_back(
                {left[i], i == left.size() / 2 ? "left" : "", {Role::Entering}, 4.5f});
        for (std::size_t i = 1; i + 1 < right.size(); ++i)
            scene.points.push_back(
                {right[i], i == right.size() / 2 ? "right" : "", {Role::Leaving}, 4.5f});
    }

    for (int i = 0; i <= n; ++i) {
        const std::string base = "/control_points/" + std::to_string(i) + "/";
        scene.handles.push_back(
            {polygon[static_cast<std::size_t>(i)], point_name(i), base + "0", base + "1"});
    }
}

}  // namespace cg
