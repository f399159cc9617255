#include "clipping/liang_barsky.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace cg {

namespace {

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineDeltas = 1,
    kLineInit,
    kLineLoop,
    kLinePQ,
    kLineParallel,
    kLineParallelReject,
    kLineEnteringTest,
    kLineEntering,
    kLineLeavingTest,
    kLineLeaving,
    kLineEmptyReject,
    kLineAccept,
};

glm::dvec2 point_at(const LiangBarsky::Input& in, double t) { return in.p0 + t * (in.p1 - in.p0); }

// p_k and q_k of edge k (1..4), as in the header comment.
void edge_pq(const LiangBarsky::State& s, int k, double& p, double& q) {
    const auto& w = s.in.window;
    switch (k) {
        case 1: p = -s.dx; q = s.in.p0.x - w.xmin; break;
        case 2: p = s.dx;  q = w.xmax - s.in.p0.x; break;
        case 3: p = -s.dy; q = s.in.p0.y - w.ymin; break;
        default: p = s.dy; q = w.ymax - s.in.p0.y; break;
    }
}

void check_finite(double v, const char* field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

std::string edge_equation(const LiangBarsky::State& s, int k) {
    const auto& w = s.in.window;
    switch (k) {
        case 1: return "x = " + num(w.xmin);
        case 2: return "x = " + num(w.xmax);
        case 3: return "y = " + num(w.ymin);
        default: return "y = " + num(w.ymax);
    }
}

// "p_1 = −dx = -4, q_1 = x0 − xmin = -1", and the same in LaTeX.
std::string pq_tex(const LiangBarsky::State& s) {
    static constexpr const char* kP[] = {"", "-dx", "dx", "-dy", "dy"};
    static constexpr const char* kQ[] = {"", "x_0 - x_{min}", "x_{max} - x_0", "y_0 - y_{min}",
                                         "y_{max} - y_0"};
    const std::string k = std::to_string(s.k);
    return "p_" + k + " = " + kP[s.k] + " = " + tex(s.p_k) + ",\\quad q_" + k + " = " + kQ[s.k] +
           " = " + tex(s.q_k);
}

std::string pq_text(const LiangBarsky::State& s) {
    static constexpr const char* kP[] = {"", "−dx", "dx", "−dy", "dy"};
    static constexpr const char* kQ[] = {"", "x0 − xmin", "xmax − x0", "y0 − ymin", "ymax − y0"};
    const std::string k = std::to_string(s.k);
    return "p_" + k + " = " + kP[s.k] + " = " + num(s.p_k) + ", q_" + k + " = " + kQ[s.k] +
           " = " + num(s.q_k);
}

void fill_vars(const LiangBarsky::State& s, StepInfo& info) {
    info.vars = {{"dx", s.dx}, {"dy", s.dy}, {"t_enter", s.t_enter}, {"t_leave", s.t_leave}};
    if (s.k > 0) {
        info.vars.push_back({"k", static_cast<long long>(s.k)});
        info.vars.push_back({"edge", std::string(LiangBarsky::kEdgeName[s.k])});
        info.vars.push_back({"p_k", s.p_k});
        info.vars.push_back({"q_k", s.q_k});
        if (s.p_k != 0) info.vars.push_back({"r_k", s.r_k});
    }
}

}  // namespace

const Spec& LiangBarsky::spec() {
    static const Spec spec{
        "liang-barsky",
        "Liang-Barsky line clipping",
        "Line Clipping",
        {
            "dx ← x1 − x0,  dy ← y1 − y0",
            "t_enter ← 0,  t_leave ← 1",
            "for k in left, right, bottom, top:",
            "    (p_k, q_k) ← edge k's test  p_k·t ≤ q_k",
            "    if p_k = 0:                       ▷ parallel to edge k",
            "        if q_k < 0: reject            ▷ and outside it",
            "    else if p_k < 0:                  ▷ entering",
            "        t_enter ← max(t_enter, q_k / p_k)",
            "    else:                             ▷ leaving",
            "        t_leave ← min(t_leave, q_k / p_k)",
            "    if t_enter > t_leave: reject",
            "Q0 ← P(t_enter),  Q1 ← P(t_leave)",
        },
        {
            {"setup", "compute dx, dy and start with t_enter = 0, t_leave = 1"},
            {"entering", "p_k < 0: the line crosses edge k from outside to inside"},
            {"leaving", "p_k > 0: the line crosses edge k from inside to outside"},
            {"parallel-inside", "p_k = 0 and q_k ≥ 0: parallel to edge k, on its inner side"},
            {"parallel-outside", "p_k = 0 and q_k < 0: parallel to edge k, outside it"},
            {"reject", "nothing of the segment is inside the window"},
            {"accept", "the visible part is P(t_enter) to P(t_leave)"},
        },
        {},  // no sliders
        {
            .predict = {{"entering", {"r_k", "t_enter"}}, {"leaving", {"r_k", "t_leave"}}},
            .mistakes = {
                {"entering", "p_k", "negate",
                 "flipped the sign of p_k: took p = +dx for the left edge"},
                {"entering", "t_enter", "other:r_k", "updated t_enter with min instead of max"},
                {"leaving", "t_leave", "other:r_k", "updated t_leave with max instead of min"},
                {"leaving", "", "event:entering", "read p_k > 0 as entering"},
            },
        },
    };
    return spec;
}

void LiangBarsky::validate(const Input& in) {
    check_finite(in.window.xmin, "window.xmin");
    check_finite(in.window.ymin, "window.ymin");
    check_finite(in.window.xmax, "window.xmax");
    check_finite(in.window.ymax, "window.ymax");
    check_finite(in.p0.x, "p0[0]");
    check_finite(in.p0.y, "p0[1]");
    check_finite(in.p1.x, "p1[0]");
    check_finite(in.p1.y, "p1[1]");
    if (in.window.xmin > in.window.xmax)
        throw InputError("window.xmin", "must not exceed window.xmax (" + given(in.window.xmin) +
                                            " > " + given(in.window.xmax) + ")");
    if (in.window.ymin > in.window.ymax)
        throw InputError("window.ymin", "must not exceed window.ymax (" + given(in.window.ymin) +
                                            " > " + given(in.window.ymax) + ")");
    // dx and the q_k are differences of inputs; keep them finite too.
    if (!std::isfinite(in.p1.x - in.p0.x) || !std::isfinite(in.p1.y - in.p0.y) ||
        !std::isfinite(in.window.xmax - in.window.xmin) ||
        !std::isfinite(in.window.ymax - in.window.ymin) ||
        !std::isfinite(in.p0.x - in.window.xmin) || !std::isfinite(in.window.xmax - in.p0.x) ||
        !std::isfinite(in.p0.y - in.window.ymin) || !std::isfinite(in.window.ymax - in.p0.y))
        throw InputError("p1", "coordinates too large: differences overflow to infinity");
}

LiangBarsky::State LiangBarsky::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// The algorithm proper: one step of the math. Kept apart from the narration below so that
// running to completion (no StepInfo) costs about what the plain clip() does.
void LiangBarsky::advance(State& s) {
    switch (s.phase) {
        case Phase::Setup:  // Compute the direction and the full parameter range
            s.dx = s.in.p1.x - s.in.p0.x;
            s.dy = s.in.p1.y - s.in.p0.y;
            s.t_enter = 0;
            s.t_leave = 1;
            s.phase = Phase::Edge;
            return;
        case Phase::Edge: {  // Test one window edge: p_k t <= q_k
            const int k = ++s.k;
            edge_pq(s, k, s.p_k, s.q_k);
            if (s.p_k == 0) {
                s.r_k = 0;
                s.verdict = s.q_k < 0 ? Verdict::ParallelOutside : Verdict::ParallelInside;
            } else {
                s.r_k = s.q_k / s.p_k;
                if (s.p_k < 0) {
                    s.verdict = Verdict::Entering;
                    s.t_before = s.t_enter;
                    s.t_enter = std::max(s.t_enter, s.r_k);
                } else {
                    s.verdict = Verdict::Leaving;
                    s.t_before = s.t_leave;
                    s.t_leave = std::min(s.t_leave, s.r_k);
                }
            }
            s.tested[std::size_t(k - 1)] = {k, s.p_k, s.q_k, s.r_k, s.verdict};
            const bool reject = s.verdict == Verdict::ParallelOutside || s.t_enter > s.t_leave;
            s.phase = reject ? Phase::Reject : (k == 4 ? Phase::Accept : Phase::Edge);
            return;
        }
        case Phase::Reject:  // Nothing is left inside
            s.visible = false;
            s.phase = Phase::Done;
            return;
        case Phase::Accept:  // The visible part lies between the two parameters
            s.visible = true;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// What the step just taken means, told with its numbers. `s` is the state after the step.
void LiangBarsky::narrate(const State& s, StepInfo& info) {
    const int k = s.k;
    if (k == 0) {
        info.event = "setup";
        info.line = kLineInit;
        info.narration = "dx = x1 − x0 = " + num(s.dx) + ", dy = y1 − y0 = " + num(s.dy) +
                         "; start with t_enter = 0 and t_leave = 1.";
        info.math = "dx = x_1 - x_0 = " + tex(s.dx) + ",\\quad dy = y_1 - y_0 = " + tex(s.dy) +
                    ",\\quad t_{enter} = 0,\\quad t_{leave} = 1";
    } else if (s.phase != Phase::Done) {  // an edge was just tested
        std::string head = "Edge " + std::to_string(k) + " (" + kEdgeName[k] + ", " +
                           edge_equation(s, k) + "): " + pq_text(s) + ". ";
        std::string rk = "r_" + std::to_string(k) + " = q/p = " + num(s.q_k) + "/" + num(s.p_k) +
                         " = " + num(s.r_k);
        const std::string K = std::to_string(k);
        const std::string rk_tex = ",\\quad r_" + K + " = \\frac{q_" + K + "}{p_" + K + "} = \\frac{" +
                                   tex(s.q_k) + "}{" + tex(s.p_k) + "} = " + tex(s.r_k);
        info.math = pq_tex(s);
        switch (s.verdict) {
            case Verdict::ParallelInside:
                info.event = "parallel-inside";
                info.line = kLineParallel;
                info.narration = head + "p = 0 and q ≥ 0: parallel to this edge and on its inner "
                                        "side, so nothing changes.";
                info.math += " \\ge 0";
                break;
            case Verdict::ParallelOutside:
                info.event = "parallel-outside";
                info.line = kLineParallelReject;
                info.narration = head + "p = 0 and q < 0: parallel to this edge and outside it.";
                info.math += " < 0";
                break;
            case Verdict::Entering:
                info.event = "entering";
                info.line = kLineEntering;
                info.narration = head + "p < 0, entering: " + rk + ", so t_enter = max(" +
                                 num(s.t_before) + ", " + num(s.r_k) + ") = " + num(s.t_enter) + ".";
                info.math += rk_tex + ",\\quad t_{enter} = \\max(" + tex(s.t_before) + ", " +
                             tex(s.r_k) + ") = " + tex(s.t_enter);
                break;
            default:
                info.event = "leaving";
                info.line = kLineLeaving;
                info.narration = head + "p > 0, leaving: " + rk + ", so t_leave = min(" +
                                 num(s.t_before) + ", " + num(s.r_k) + ") = " + num(s.t_leave) + ".";
                info.math += rk_tex + ",\\quad t_{leave} = \\min(" + tex(s.t_before) + ", " +
                             tex(s.r_k) + ") = " + tex(s.t_leave);
                break;
        }
    } else if (!s.visible) {
        info.event = "reject";
        if (s.verdict == Verdict::ParallelOutside) {
            info.line = kLineParallelReject;
            info.narration = std::string("The segment runs outside the ") + kEdgeName[k] +
                             " edge along its whole length: reject.";
            info.math = "p_" + std::to_string(k) + " = 0,\\quad q_" + std::to_string(k) + " = " +
                        tex(s.q_k) + " < 0";
        } else {
            info.line = kLineEmptyReject;
            info.narration = "t_enter = " + num(s.t_enter) + " > t_leave = " + num(s.t_leave) +
                             ": the segment misses the window, reject.";
            info.math = "t_{enter} = " + tex(s.t_enter) + " > t_{leave} = " + tex(s.t_leave);
        }
    } else {
        info.event = "accept";
        info.line = kLineAccept;
        info.narration = "Q0 = P(" + num(s.t_enter) + ") = " + num(point_at(s.in, s.t_enter)) +
                         " and Q1 = P(" + num(s.t_leave) + ") = " +
                         num(point_at(s.in, s.t_leave)) + ": this part of the segment is visible.";
        info.math = "Q_0 = P(" + tex(s.t_enter) + ") = " + tex(point_at(s.in, s.t_enter)) +
                    ",\\quad Q_1 = P(" + tex(s.t_leave) + ") = " + tex(point_at(s.in, s.t_leave));
    }
    fill_vars(s, info);
}

void LiangBarsky::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

LiangBarsky::Result LiangBarsky::result(const State& s) {
    Result r;
    r.visible = s.visible;
    r.t_enter = s.t_enter;
    r.t_leave = s.t_leave;
    if (s.visible) {
        r.q0 = point_at(s.in, s.t_enter);
        r.q1 = point_at(s.in, s.t_leave);
    }
    r.edges.assign(s.tested.begin(), s.tested.begin() + s.k);
    return r;
}

LiangBarsky::Result LiangBarsky::clip(const Input& in) {
    Result r;
    const double dx = in.p1.x - in.p0.x, dy = in.p1.y - in.p0.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {in.p0.x - in.window.xmin, in.window.xmax - in.p0.x,
                         in.p0.y - in.window.ymin, in.window.ymax - in.p0.y};
    double t0 = 0, t1 = 1;
    r.edges.reserve(4);
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            r.edges.push_back({k + 1, p[k], q[k], 0,
                               q[k] < 0 ? Verdict::ParallelOutside : Verdict::ParallelInside});
            if (q[k] < 0) {
                r.t_enter = t0, r.t_leave = t1;
                return r;
            }
            continue;
        }
        const double rk = q[k] / p[k];
        r.edges.push_back({k + 1, p[k], q[k], rk, p[k] < 0 ? Verdict::Entering : Verdict::Leaving});
        if (p[k] < 0) t0 = std::max(t0, rk);
        else t1 = std::min(t1, rk);
        if (t0 > t1) {
            r.t_enter = t0, r.t_leave = t1;
            return r;
        }
    }
    r.visible = true;
    r.t_enter = t0, r.t_leave = t1;
    r.q0 = point_at(in, t0);
    r.q1 = point_at(in, t1);
    return r;
}

bool LiangBarsky::clip_segment(const Window& w, glm::dvec2& a, glm::dvec2& b) {
    const glm::dvec2 d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x - w.xmin, w.xmax - a.x, a.y - w.ymin, w.ymax - a.y};
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            if (q[k] < 0) return false;
            continue;
        }
        const double r = q[k] / p[k];
        if (p[k] < 0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
        if (t0 > t1) return false;
    }
    const glm::dvec2 a0 = a;
    a = a0 + t0 * d, b = a0 + t1 * d;
    return true;
}

void LiangBarsky::draw(const State& s, Scene& scene) {
    const auto& w = s.in.window;
    scene.polygons.push_back(
        {{{w.xmin, w.ymin}, {w.xmax, w.ymin}, {w.xmax, w.ymax}, {w.xmin, w.ymax}},
         {Role::Window, 2.0f},
         true,
         true});

    const bool finished = s.phase == Phase::Done;
    Style subject{finished && !s.visible ? Role::Discarded : Role::Subject, 2.0f,
                  !finished || s.visible};
    scene.segments.push_back({s.in.p0, s.in.p1, "", subject, true});

    // The edge under test, as the half-plane it keeps.
    if (s.k > 0 && !finished) {
        glm::dvec2 point, inward;
        switch (s.k) {
            case 1: point = {w.xmin, 0}; inward = {1, 0}; break;
            case 2: point = {w.xmax, 0}; inward = {-1, 0}; break;
            case 3: point = {0, w.ymin}; inward = {0, 1}; break;
            default: point = {0, w.ymax}; inward = {0, -1}; break;
        }
        scene.half_planes.push_back(
            {point, inward, std::string("edge ") + std::to_string(s.k) + ": " + kEdgeName[s.k],
             {Role::Active, 2.5f}});
        if (s.p_k != 0) {
            Role role = s.verdict == Verdict::Entering ? Role::Entering : Role::Leaving;
            scene.points.push_back({point_at(s.in, s.r_k),
                                    "r_" + std::to_string(s.k) + " = " + num(s.r_k, 4),
                                    {role, 1.5f},
                                    4.0f});
        }
    }

    // The surviving parameter range [t_enter, t_leave].
    if (s.phase != Phase::Setup && s.t_enter <= s.t_leave && (!finished || s.visible)) {
        const glm::dvec2 a = point_at(s.in, s.t_enter), b = point_at(s.in, s.t_leave);
        scene.segments.push_back({a, b, "", {Role::Kept, 5.0f}, false});
        scene.points.push_back(
            {a, (finished ? "Q0, t_enter = " : "t_enter = ") + num(s.t_enter, 4), {Role::Entering}, 6.0f});
        scene.points.push_back(
            {b, (finished ? "Q1, t_leave = " : "t_leave = ") + num(s.t_leave, 4), {Role::Leaving}, 6.0f});
    }

    scene.labels.push_back({s.in.p0, "P0", {Role::Subject}});
    scene.labels.push_back({s.in.p1, "P1", {Role::Subject}});
    scene.handles.push_back({s.in.p0, "P0", "/p0/0", "/p0/1"});
    scene.handles.push_back({s.in.p1, "P1", "/p1/0", "/p1/1"});
    scene.handles.push_back({{w.xmin, w.ymin}, "window (xmin, ymin)", "/window/xmin", "/window/ymin"});
    scene.handles.push_back({{w.xmax, w.ymax}, "window (xmax, ymax)", "/window/xmax", "/window/ymax"});
}

}  // namespace cg
