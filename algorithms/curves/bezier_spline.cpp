// Sections: [spec] [joints] [start] [advance] [narrate] [step and result] [draw].
#include "curves/bezier_spline.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <span>

#include "core/format.hpp"
#include "curves/bezier.hpp"

namespace cg {

namespace {

using curves::point_name;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineTangents = 1,
    kLineIntervals,
    kLineSegment,
    kLineJoints,
    kLineC0,
    kLineG1,
    kLineC1,
    kLineC2,
    kLineSummary,
};

constexpr std::size_t kMaxSegments = 1000;

// A point as the narration writes it: (x, y) in 2D, (x, y, z) in 3D.
std::string pt(glm::dvec3 p, int dim) {
    return dim == 3 ? num(p) : num(curves::xy(p));
}
std::string pt_tex(glm::dvec3 p, int dim) {
    return dim == 3 ? tex(p) : tex(curves::xy(p));
}
std::vector<double> coords(glm::dvec3 p, int dim) {
    return dim == 3 ? vec(p) : std::vector<double>{p.x, p.y};
}

int rank(const BezierSpline::Joint& j) {
    return j.c2 ? 4 : j.c1 ? 3 : j.g1 ? 2 : j.c0 ? 1 : 0;
}

std::vector<std::vector<double>> rows_of(const BezierSpline::Segment& seg, int dim) {
    std::vector<std::vector<double>> m;
    for (glm::dvec3 p : seg) m.push_back(coords(p, dim));
    return m;
}

std::string list_text(const BezierSpline::Segment& seg, int dim) {
    std::string out;
    for (glm::dvec3 p : seg) out += (out.empty() ? "" : ", ") + pt(p, dim);
    return "[" + out + "]";
}
std::string list_tex(const BezierSpline::Segment& seg, int dim) {
    std::string out;
    for (glm::dvec3 p : seg) out += (out.empty() ? "" : ",\\; ") + pt_tex(p, dim);
    return "[" + out + "]";
}

void check_points(const std::vector<glm::dvec3>& points, int dim, const std::string& field) {
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = points[i][c];
            const std::string at = field + "[" + std::to_string(i) + "][" + std::to_string(c) + "]";
            if (c == 2 && dim == 2) {  // a 2D point is stored with z = 0
                if (v != 0) throw InputError(at, "must be 0 for a 2D point (got " + given(v) + ")");
                continue;
            }
            if (!std::isfinite(v))
                throw InputError(at, "must be a finite number (got " + given(v) + ")");
            if (std::fabs(v) > curves::kMaxCoordinate)
                throw InputError(at, "must be within ±1e100 (got " + given(v) + ")");
            if (v != 0 && std::fabs(v) < 1e-100)
                throw InputError(at, "must be 0 or at least 1e-100 in size (got " + given(v) + ")");
        }
}

double largest(const std::vector<glm::dvec3>& points, double scale = 0) {
    for (glm::dvec3 p : points)
        scale = std::max({scale, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    return scale;
}

// How a joint is written in the picture: "C1 (not C2)", "G1, β = 2".
std::string joint_caption(const BezierSpline::Joint& j) {
    if (j.c2) return "C2";
    if (j.c1) return "C1, not C2";
    if (j.g1) return "G1, β = " + num(*j.beta, 4);
    if (j.c0) return "C0 only";
    return "broken";
}

}  // namespace

// --- [spec] -------------------------------------------------------------------------------------

const Spec& BezierSpline::spec() {
    static const Spec spec{
        "bezier-spline",
        "Piecewise cubic Bézier curves: Hermite, Catmull-Rom and continuity",
        "Splines",
        {
            "Catmull-Rom: v_i ← (P_{i+1} − P_{i−1}) / 2;  ends: v_0 ← P_1 − P_0,  v_N ← P_N − "
            "P_{N−1}  (closed: no ends, indices cyclic)",
            "Hermite or Catmull-Rom: for each interval [P_i, P_{i+1}] (closed: also [P_N, P_0]):",
            "    segment i ← [P_i,  P_i + v_i/3,  P_{i+1} − v_{i+1}/3,  P_{i+1}]",
            "for each joint of [P_0 .. P_3] and [Q_0 .. Q_3]:",
            "    C0:  P_3 = Q_0 ?",
            "    G1:  P_3 − P_2 = β (Q_1 − Q_0),  β > 0 ?",
            "    C1:  P_3 − P_2 = Q_1 − Q_0 ?",
            "    C2:  (P_3 − P_2) − (P_2 − P_1) = (Q_2 − Q_1) − (Q_1 − Q_0) ?",
            "the spline is as smooth as its weakest joint",
        },
        {
            {"tangent", "Catmull-Rom makes up the derivative v_i at a point from its neighbours"},
            {"segment", "one Hermite interval turned into a cubic Bézier segment"},
            {"joint-c2", "the joint is C2: equal first and second derivatives"},
            {"joint-c1", "the joint is C1 (equal derivatives) but not C2"},
            {"joint-g1", "the joint is G1 (same tangent direction, β ≠ 1) but not C1"},
            {"joint-c0", "the pieces meet, but with a corner: C0 only"},
            {"joint-broken", "the pieces do not even meet"},
            {"summary", "the whole spline's continuity: that of its weakest joint"},
        },
        {},  // no sliders
        {
            .predict = {
                {"tangent", {"v_i"}},
                {"segment", {"segment"}},
                {"joint-c1", {"Q_1 − Q_0"}},
                {"joint-g1", {"β"}},
                {"joint-c2", {"second difference P", "second difference Q"}},
            },
            .mistakes = {
                {"joint-g1", "", "event:joint-c1",
                 "called the joint C1 though the tangents differ by β"},
                {"joint-c2", "", "event:joint-c1", "compared only the first differences"},
                {"joint-g1", "Q_1 − Q_0", "negate",
                 "took Q_0 − Q_1 for the next segment's tangent"},
            },
        },
    };
    return spec;
}

// --- [joints] -----------------------------------------------------------------------------------

BezierSpline::Segment BezierSpline::hermite_segment(glm::dvec3 p0, glm::dvec3 v0, glm::dvec3 p1,
                                                    glm::dvec3 v1) {
    return {p0, p0 + v0 / 3.0, p1 - v1 / 3.0, p1};
}

std::size_t BezierSpline::segment_count(const Input& in) {
    if (in.mode == Mode::Segments) return in.segments.size();
    return in.closed ? in.points.size() : in.points.size() - 1;
}

BezierSpline::Joint BezierSpline::classify(const Segment& a, const Segment& b, double tol) {
    Joint j;
    const glm::dvec3 out = a[3] - a[2], in = b[1] - b[0];
    j.c0 = glm::length(a[3] - b[0]) <= tol;
    if (!j.c0) return j;
    j.c1 = glm::length(out - in) <= tol;
    const bool nonzero = glm::length(out) > tol && glm::length(in) > tol;
    if (nonzero) {
        const double beta = glm::dot(out, in) / glm::dot(in, in);
        if (beta > 0 && glm::length(out - beta * in) <= tol) j.beta = j.c1 ? 1.0 : beta;
    }
    j.g1 = j.c1 || j.beta.has_value();
    if (j.c1) {
        const glm::dvec3 second_a = out - (a[2] - a[1]), second_b = (b[2] - b[1]) - in;
        j.c2 = glm::length(second_a - second_b) <= tol;
    }
    return j;
}

std::string BezierSpline::level(const Joint& j) {
    static constexpr const char* kNames[] = {"broken", "C0", "G1", "C1", "C2"};
    return kNames[rank(j)];
}

// --- [start] ------------------------------------------------------------------------------------

void BezierSpline::validate(const Input& in) {
    if (in.dim != 2 && in.dim != 3)
        throw InputError("",
                         "points must be 2D or 3D (got dimension " + std::to_string(in.dim) + ")");
    if (in.closed && in.mode != Mode::CatmullRom)
        throw InputError(in.mode == Mode::Hermite ? "hermite.closed" : "closed",
                         "applies to catmull_rom only: segments and Hermite data are joined as "
                         "given");
    switch (in.mode) {
        case Mode::Segments:
            if (in.segments.empty())
                throw InputError("segments", "needs at least 1 segment (got 0)");
            if (in.segments.size() > kMaxSegments)
                throw InputError("segments", "takes at most 1000 segments (got " +
                                                 std::to_string(in.segments.size()) + ")");
            for (std::size_t i = 0; i < in.segments.size(); ++i)
                check_points({in.segments[i].begin(), in.segments[i].end()}, in.dim,
                             "segments[" + std::to_string(i) + "]");
            return;
        case Mode::Hermite:
        case Mode::CatmullRom: {
            const std::string base = in.mode == Mode::Hermite ? "hermite" : "catmull_rom";
            if (in.points.size() < 2)
                throw InputError(base + ".points", "needs at least 2 points (got " +
                                                       std::to_string(in.points.size()) + ")");
            if (in.points.size() > kMaxSegments + 1)
                throw InputError(base + ".points", "takes at most 1001 points (got " +
                                                       std::to_string(in.points.size()) + ")");
            check_points(in.points, in.dim, base + ".points");
            if (in.closed) {
                if (in.points.size() < 3)
                    throw InputError("catmull_rom.points",
                                     "a closed loop needs at least 3 points (got " +
                                         std::to_string(in.points.size()) + ")");
                if (in.points.size() > kMaxSegments)
                    throw InputError("catmull_rom.points",
                                     "a closed loop takes at most 1000 points (got " +
                                         std::to_string(in.points.size()) + ")");
                if (in.points.front() == in.points.back())
                    throw InputError(
                        "catmull_rom.points[" + std::to_string(in.points.size() - 1) + "]",
                        "repeats the first point: a closed loop joins the last point back to "
                        "the first by itself, so leave the repeat out");
            }
            if (in.mode == Mode::Hermite) {
                if (in.tangents.size() != in.points.size())
                    throw InputError("hermite.tangents", "needs one vector per point (" +
                                                             std::to_string(in.points.size()) +
                                                             "), got " +
                                                             std::to_string(in.tangents.size()));
                check_points(in.tangents, in.dim, "hermite.tangents");
            }
            return;
        }
    }
}

BezierSpline::State BezierSpline::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    double scale = largest(in.points, largest(in.tangents));
    for (const Segment& seg : in.segments) scale = largest({seg.begin(), seg.end()}, scale);
    s.tolerance = 1e-9 * scale;
    switch (in.mode) {
        case Mode::Segments:
            s.segments = in.segments;
            s.phase = in.segments.size() > 1 ? Phase::Joint : Phase::Summary;
            break;
        case Mode::Hermite:
            s.tangents = in.tangents;
            s.phase = Phase::Convert;
            break;
        case Mode::CatmullRom:
            s.phase = Phase::Tangent;
            break;
    }
    return s;
}

// --- [advance] ----------------------------------------------------------------------------------

// The algorithm proper: one step of the math.
void BezierSpline::advance(State& s) {
    const int i = s.taken == s.phase ? s.index + 1 : 0;  // the first of a new phase is number 0
    s.taken = s.phase;
    s.index = i;
    const auto& p = s.in.points;
    const int last = static_cast<int>(p.size()) - 1;
    const std::size_t n = p.size();
    switch (s.phase) {
        case Phase::Tangent: {  // Catmull-Rom: a derivative from the neighbours
            const std::size_t k = static_cast<std::size_t>(i);
            if (s.in.closed)  // no ends: the neighbours wrap around
                s.tangents.push_back((p[(k + 1) % n] - p[(k + n - 1) % n]) / 2.0);
            else if (i == 0)
                s.tangents.push_back(p[1] - p[0]);
            else if (i == last)
                s.tangents.push_back(p[k] - p[k - 1]);
            else
                s.tangents.push_back((p[k + 1] - p[k - 1]) / 2.0);
            if (i == last) s.phase = Phase::Convert;
            return;
        }
        case Phase::Convert: {  // Hermite: one interval becomes one Bézier segment
            const std::size_t k = static_cast<std::size_t>(i), k1 = (k + 1) % n;
            s.segments.push_back(hermite_segment(p[k], s.tangents[k], p[k1], s.tangents[k1]));
            if (s.segments.size() == segment_count(s.in))
                s.phase = joint_count(s.in) > 0 ? Phase::Joint : Phase::Summary;
            return;
        }
        case Phase::Joint: {  // Classify one joint (closed: the last is segment N into 0)
            const std::size_t k = static_cast<std::size_t>(i);
            s.joints.push_back(
                classify(s.segments[k], s.segments[(k + 1) % s.segments.size()], s.tolerance));
            if (s.joints.size() == joint_count(s.in)) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:  // The weakest joint decides
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// --- [narrate] ----------------------------------------------------------------------------------

// What the step just taken means, told with its numbers. `s` is the state after the step.
void BezierSpline::narrate(const State& s, StepInfo& info) {
    const int i = s.index;
    const std::size_t k = static_cast<std::size_t>(i);
    const auto& p = s.in.points;
    const int last = static_cast<int>(p.size()) - 1;
    const int d = s.in.dim;
    switch (s.taken) {
        case Phase::Tangent: {
            const glm::dvec3 v = s.tangents[k];
            const std::string vi = "v" + curves::subscript(i), vt = "v_{" + std::to_string(i) + "}";
            info.event = "tangent";
            info.line = kLineTangents;
            if (s.in.closed) {  // the neighbours wrap around: P_{−1} = P_N, P_{N+1} = P_0
                const int a = i == last ? 0 : i + 1, b = i == 0 ? last : i - 1;
                const std::size_t ka = static_cast<std::size_t>(a),
                                  kb = static_cast<std::size_t>(b);
                info.narration =
                    vi + " = (" + point_name(a) + " − " + point_name(b) + ")/2 = (" + pt(p[ka], d) +
                    " − " + pt(p[kb], d) + ")/2 = " + pt(v, d) +
                    (i == 0 || i == last ? ": the loop has no ends, so the neighbours wrap around."
                                         : ": parallel to the chord through the two neighbours.");
                info.math = vt + " = \\frac{P_{" + std::to_string(a) + "} - P_{" +
                            std::to_string(b) + "}}{2} = \\frac{" + pt_tex(p[ka], d) + " - " +
                            pt_tex(p[kb], d) + "}{2} = " + pt_tex(v, d);
            } else if (i == 0 || i == last) {
                const int a = i == 0 ? 1 : i, b = i == 0 ? 0 : i - 1;
                info.narration =
                    vi + " = " + point_name(a) + " − " + point_name(b) + " = " +
                    pt(p[static_cast<std::size_t>(a)], d) + " − " +
                    pt(p[static_cast<std::size_t>(b)], d) + " = " + pt(v, d) +
                    ": at an end there is only one neighbour, so a one-sided difference.";
                info.math = vt + " = P_{" + std::to_string(a) + "} - P_{" + std::to_string(b) +
                            "} = " + pt_tex(p[static_cast<std::size_t>(a)], d) + " - " +
                            pt_tex(p[static_cast<std::size_t>(b)], d) + " = " + pt_tex(v, d);
            } else {
                info.narration = vi + " = (" + point_name(i + 1) + " − " + point_name(i - 1) +
                                 ")/2 = (" + pt(p[k + 1], d) + " − " + pt(p[k - 1], d) +
                                 ")/2 = " + pt(v, d) +
                                 ": parallel to the chord through the two neighbours.";
                info.math = vt + " = \\frac{P_{" + std::to_string(i + 1) + "} - P_{" +
                            std::to_string(i - 1) + "}}{2} = \\frac{" + pt_tex(p[k + 1], d) +
                            " - " + pt_tex(p[k - 1], d) + "}{2} = " + pt_tex(v, d);
            }
            info.vars = {
                {"i", static_cast<long long>(i)}, {"P_i", coords(p[k], d)}, {"v_i", coords(v, d)}};
            return;
        }
        case Phase::Convert: {
            const Segment& seg = s.segments[k];
            const int next = (i + 1) % static_cast<int>(p.size());  // closed: the last goes to P_0
            const std::size_t k1 = static_cast<std::size_t>(next);
            const std::string a = std::to_string(i), b = std::to_string(next);
            info.event = "segment";
            info.line = kLineSegment;
            info.narration = "Segment " + a + ", from " + point_name(i) + " to " +
                             point_name(next) + ": [" + point_name(i) + ", " + point_name(i) +
                             " + v" + curves::subscript(i) + "/3, " + point_name(next) + " − v" +
                             curves::subscript(next) + "/3, " + point_name(next) +
                             "] = " + list_text(seg, d) +
                             (next == 0 ? ": the segment that closes the loop." : ".");
            info.math = "[P_{" + a + "},\\; P_{" + a + "} + \\tfrac{v_{" + a + "}}{3},\\; P_{" + b +
                        "} - \\tfrac{v_{" + b + "}}{3},\\; P_{" + b + "}] = " + list_tex(seg, d);
            info.vars = {{"i", static_cast<long long>(i)},
                         {"v_i", coords(s.tangents[k], d)},
                         {"v_i+1", coords(s.tangents[k1], d)},
                         {"segment", rows_of(seg, d)}};
            return;
        }
        case Phase::Joint: {
            const std::size_t kb = (k + 1) % s.segments.size();  // closed: the seam, N into 0
            const Segment& a = s.segments[k];
            const Segment& b = s.segments[kb];
            const Joint& j = s.joints[k];
            const glm::dvec3 out = a[3] - a[2], in = b[1] - b[0];
            const glm::dvec3 second_a = out - (a[2] - a[1]), second_b = (b[2] - b[1]) - in;
            std::string text = "Joint " + std::to_string(i + 1) + " (segment " + std::to_string(i) +
                               " into segment " + std::to_string(kb) +
                               (kb == 0 ? ", where the loop closes" : "") + "): ";
            std::string math;
            info.vars = {{"joint", static_cast<long long>(i + 1)},
                         {"P_3", coords(a[3], d)},
                         {"Q_0", coords(b[0], d)}};
            if (!j.c0) {
                info.event = "joint-broken";
                info.line = kLineC0;
                text += "P₃ = " + pt(a[3], d) + " but Q₀ = " + pt(b[0], d) +
                        ": the pieces do not meet, not even C0.";
                math = "P_3 = " + pt_tex(a[3], d) + " \\ne Q_0 = " + pt_tex(b[0], d);
            } else {
                text += "P₃ = Q₀ = " + pt(a[3], d) + " (C0). P₃ − P₂ = " + pt(out, d) +
                        ", Q₁ − Q₀ = " + pt(in, d);
                math = "P_3 = Q_0,\\quad P_3 - P_2 = " + pt_tex(out, d) +
                       ",\\quad Q_1 - Q_0 = " + pt_tex(in, d);
                info.vars.push_back({"P_3 − P_2", coords(out, d)});
                info.vars.push_back({"Q_1 − Q_0", coords(in, d)});
                if (!j.g1) {
                    info.event = "joint-c0";
                    info.line = kLineG1;
                    text +=
                        glm::length(out) <= s.tolerance || glm::length(in) <= s.tolerance
                            ? ": one of them is zero, so there is no common direction — C0 only."
                            : ": different directions, a corner — C0 only.";
                    math += ",\\quad \\nexists\\, \\beta > 0";
                } else if (!j.c1) {
                    info.event = "joint-g1";
                    info.line = kLineC1;
                    text +=
                        ": the same direction with β = " + num(*j.beta) + " ≠ 1, so G1 but not C1.";
                    math += ",\\quad \\beta = " + tex(*j.beta) + " \\ne 1";
                    info.vars.push_back({"β", *j.beta});
                } else {
                    text += ": equal, so C1. Second differences: (P₃ − P₂) − (P₂ − P₁) = " +
                            pt(second_a, d) + ", (Q₂ − Q₁) − (Q₁ − Q₀) = " + pt(second_b, d);
                    math += ",\\quad (P_3 - P_2) - (P_2 - P_1) = " + pt_tex(second_a, d) +
                            (j.c2 ? " = " : " \\ne ") +
                            "(Q_2 - Q_1) - (Q_1 - Q_0) = " + pt_tex(second_b, d);
                    info.vars.push_back({"second difference P", coords(second_a, d)});
                    info.vars.push_back({"second difference Q", coords(second_b, d)});
                    info.line = kLineC2;
                    if (j.c2) {
                        info.event = "joint-c2";
                        text += ": equal too, so C2.";
                    } else {
                        info.event = "joint-c1";
                        text += ": they differ, so C1 but not C2.";
                    }
                }
            }
            info.narration = text;
            info.math = math;
            info.vars.push_back({"continuity", level(j)});
            return;
        }
        case Phase::Summary: {
            info.event = "summary";
            info.line = kLineSummary;
            const std::size_t n = s.segments.size();
            if (s.joints.empty()) {
                info.narration =
                    "One segment, so no joints to check: a single cubic is smooth everywhere "
                    "inside.";
                info.math = "";
            } else {
                std::size_t weakest = 0;
                std::string levels;
                for (std::size_t j = 0; j < s.joints.size(); ++j) {
                    levels += (j ? ", " : "") + level(s.joints[j]);
                    if (rank(s.joints[j]) < rank(s.joints[weakest])) weakest = j;
                }
                const std::string w = level(s.joints[weakest]);
                info.narration =
                    std::to_string(n) + " segments" + (s.in.closed ? " in a closed loop" : "") +
                    ", " + std::to_string(s.joints.size()) +
                    (s.joints.size() == 1 ? " joint: " : " joints: ") + levels + ". " +
                    (w == "broken"
                         ? "The spline falls apart at joint " + std::to_string(weakest + 1) + "."
                         : "The spline is " + w + ": as smooth as its weakest joint (joint " +
                               std::to_string(weakest + 1) + ").");
                info.math = "\\text{" + levels + "}";
            }
            info.vars = {{"segments", static_cast<long long>(n)},
                         {"joints", static_cast<long long>(s.joints.size())}};
            return;
        }
        case Phase::Done:
            return;
    }
}

// --- [step and result] --------------------------------------------------------------------------

void BezierSpline::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

BezierSpline::Result BezierSpline::result(const State& s) {
    Result r;
    r.dim = s.in.dim;
    r.segments = s.segments;
    r.joints = s.joints;
    if (s.in.mode != Mode::Segments) r.tangents = s.tangents;
    return r;
}

// --- [draw] -------------------------------------------------------------------------------------

namespace {

// One drawing vocabulary for both canvases: 2D primitives (z dropped) for a 2D spline, exactly
// as before, and 3D ones on the 3D canvas for a 3D spline.
struct Canvas {
    Scene& scene;
    int dim;
    void line(const std::vector<glm::dvec3>& pts, Style style, bool closed = false) const {
        if (dim == 2) {
            std::vector<glm::dvec2> v;
            v.reserve(pts.size());
            for (const glm::dvec3& p : pts) v.push_back(curves::xy(p));
            scene.polygons.push_back({std::move(v), style, closed, false});
            return;
        }
        for (std::size_t i = 0; i + 1 < pts.size(); ++i)
            scene.segments3.push_back({pts[i], pts[i + 1], "", style, false});
        if (closed && pts.size() > 2)
            scene.segments3.push_back({pts.back(), pts.front(), "", style, false});
    }
    void curve(const BezierSpline::Segment& seg, Style style, int samples = 60) const {
        const std::span<const glm::dvec3> control{seg.data(), seg.size()};
        if (dim == 2) {
            scene.polygons.push_back(
                {curves::bezier_polyline(control, 0, 1, samples), style, false, false});
            return;
        }
        glm::dvec3 prev = seg[0];
        for (int i = 1; i <= samples; ++i) {
            const glm::dvec3 q = curves::bezier_point(control, double(i) / samples);
            scene.segments3.push_back({prev, q, "", style, false});
            prev = q;
        }
    }
    void segment(glm::dvec3 a, glm::dvec3 b, const std::string& label, Style style,
                 bool arrow) const {
        if (dim == 2)
            scene.segments.push_back({curves::xy(a), curves::xy(b), label, style, arrow});
        else
            scene.segments3.push_back({a, b, label, style, arrow});
    }
    void point(glm::dvec3 p, const std::string& label, Style style, float radius) const {
        if (dim == 2)
            scene.points.push_back({curves::xy(p), label, style, radius});
        else
            scene.points3.push_back({p, label, style, radius});
    }
    void label(glm::dvec3 p, const std::string& text, Style style) const {
        if (dim == 2)
            scene.labels.push_back({curves::xy(p), text, style});
        else
            scene.labels3.push_back({p, text, style});
    }
};

}  // namespace

void BezierSpline::draw(const State& s, Scene& scene) {
    const Canvas canvas{scene, s.in.dim};
    const auto& p = s.in.points;
    const std::size_t n = p.size();
    const bool from_points = s.in.mode != Mode::Segments;
    const bool at_joint = s.taken == Phase::Joint && s.phase != Phase::Done;
    const bool at_segment = s.taken == Phase::Convert;
    const bool at_tangent = s.taken == Phase::Tangent;

    // From points: the polyline through them (closed: a loop), and the spline to come, faint.
    if (from_points) {
        canvas.line(p, {Role::Construction, 1.0f, true}, s.in.closed);
        std::vector<glm::dvec3> v = s.in.tangents;
        if (s.in.mode == Mode::CatmullRom)
            for (std::size_t k = 0; k < n; ++k)
                v.push_back(s.in.closed  ? (p[(k + 1) % n] - p[(k + n - 1) % n]) / 2.0
                            : k == 0     ? p[1] - p[0]
                            : k + 1 == n ? p[k] - p[k - 1]
                                         : (p[k + 1] - p[k - 1]) / 2.0);
        for (std::size_t k = s.segments.size(); k < segment_count(s.in); ++k)
            canvas.curve(hermite_segment(p[k], v[k], p[(k + 1) % n], v[(k + 1) % n]),
                         {Role::Construction, 2.0f});
    }

    // Each segment: its control polygon (dashed) and its curve, alternating two shades.
    for (std::size_t k = 0; k < s.segments.size(); ++k) {
        const Segment& seg = s.segments[k];
        const bool newest = at_segment && k == static_cast<std::size_t>(s.index);
        canvas.line({seg.begin(), seg.end()},
                    {newest ? Role::Active : Role::Construction, newest ? 2.0f : 1.2f, !newest});
        canvas.curve(seg, {Role::Neutral, 3.0f, false, curves::shade(k % 2 ? 4 : 1)});
        for (int c = 1; c < 3; ++c)
            canvas.point(seg[static_cast<std::size_t>(c)], newest ? point_name(c, -1, "B") : "",
                         {newest ? Role::Active : Role::Construction}, 3.5f);
        if (!from_points)
            for (int c : {0, 3})
                canvas.point(seg[static_cast<std::size_t>(c)], "", {Role::Subject}, 4.0f);
    }

    // The joint under test: the two end vectors and the A-frame.
    if (at_joint) {
        const std::size_t ka = static_cast<std::size_t>(s.index);
        const Segment& a = s.segments[ka];
        const Segment& b = s.segments[(ka + 1) % s.segments.size()];
        const Joint& j = s.joints[ka];
        canvas.segment(a[2], a[3], "P₃ − P₂", {Role::Entering, 2.5f}, true);
        canvas.segment(b[0], b[1], "Q₁ − Q₀", {Role::Leaving, 2.5f}, true);
        if (j.c1) {
            const glm::dvec3 apex_a = 2.0 * a[2] - a[1], apex_b = 2.0 * b[1] - b[2];
            canvas.segment(a[1], apex_a, "", {Role::Entering, 1.2f, true}, false);
            canvas.segment(b[2], apex_b, "", {Role::Leaving, 1.2f, true}, false);
            canvas.point(apex_a, j.c2 ? "A-frame apex" : "2P₂ − P₁", {Role::Entering}, 4.0f);
            if (!j.c2) canvas.point(apex_b, "2Q₁ − Q₂", {Role::Leaving}, 4.0f);
        }
        const Role role = j.c1 ? Role::Kept : j.c0 ? Role::Active : Role::Discarded;
        canvas.point(a[3], (j.c0 ? "P₃ = Q₀: " : "P₃: ") + joint_caption(j), {role}, 6.0f);
        if (!j.c0) canvas.point(b[0], "Q₀", {role}, 6.0f);
        for (int c = 0; c < 3 && !from_points; ++c) {  // (from points: P_i already name the data)
            canvas.label(a[static_cast<std::size_t>(c)], point_name(c), {Role::Entering});
            canvas.label(b[static_cast<std::size_t>(c) + 1], point_name(c + 1, -1, "Q"),
                         {Role::Leaving});
        }
    } else if (s.phase == Phase::Done) {
        for (std::size_t k = 0; k < s.joints.size(); ++k) {
            const Joint& j = s.joints[k];
            canvas.point(s.segments[k][3], joint_caption(j),
                         {j.c1   ? Role::Kept
                          : j.c0 ? Role::Active
                                 : Role::Discarded},
                         5.5f);
        }
    }

    // Catmull-Rom's derivative at the point just handled: the chord it copies, and v_i/3.
    if (at_tangent) {
        const std::size_t k = static_cast<std::size_t>(s.index);
        const std::size_t a = s.in.closed ? (k + n - 1) % n : k == 0 ? 0 : k - 1;
        const std::size_t b = s.in.closed ? (k + 1) % n : std::min(k + 1, n - 1);
        canvas.segment(p[a], p[b], "", {Role::Active, 1.5f, true}, false);
    }
    const bool building = s.taken == Phase::Tangent || s.taken == Phase::Convert ||
                          (s.taken == Phase::Done && s.in.mode == Mode::Hermite);
    if (from_points && building)
        for (std::size_t k = 0; k < s.tangents.size(); ++k) {
            const bool newest = at_tangent && k == static_cast<std::size_t>(s.index);
            canvas.segment(p[k], p[k] + s.tangents[k] / 3.0,
                           newest ? "v" + curves::subscript(static_cast<int>(k)) + "/3" : "",
                           {newest ? Role::Active : Role::Entering, newest ? 2.5f : 1.5f}, true);
        }

    // The data points, and their handles in 2D (a 3D point is edited by typing).
    if (from_points) {
        const std::string base =
            s.in.mode == Mode::Hermite ? "/hermite/points/" : "/catmull_rom/points/";
        for (std::size_t k = 0; k < n; ++k) {
            canvas.point(p[k], point_name(static_cast<int>(k)), {Role::Subject}, 5.0f);
            if (s.in.dim == 2)
                scene.handles.push_back({curves::xy(p[k]), point_name(static_cast<int>(k)),
                                         base + std::to_string(k) + "/0",
                                         base + std::to_string(k) + "/1"});
        }
    } else if (s.in.dim == 2) {
        for (std::size_t k = 0; k < s.in.segments.size(); ++k)
            for (std::size_t c = 0; c < 4; ++c) {
                const std::string base =
                    "/segments/" + std::to_string(k) + "/" + std::to_string(c) + "/";
                scene.handles.push_back(
                    {curves::xy(s.in.segments[k][c]),
                     "segment " + std::to_string(k) + ", " + point_name(static_cast<int>(c)),
                     base + "0", base + "1"});
            }
    }
}

}  // namespace cg
