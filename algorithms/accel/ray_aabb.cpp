// Sections: [helpers] [spec] [validate] [slab and intersect] [step] [narrate]
// (the picture: ray_aabb_draw.cpp)
#include "accel/ray_aabb.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Case = RayAabb::Case;
using Phase = RayAabb::Phase;
using Verdict = RayAabb::Verdict;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineInit = 1,
    kLineFor,
    kLineParallel,
    kLinePlanes,
    kLineSwap,
    kLineUpdate,
    kLineEarlyOut,
    kLineBehind,
    kLineHit,
};

const char* const kAxis[3] = {"x", "y", "z"};

// A t as the narration writes it: a number, or −∞ / +∞.
std::string tn(double t) {
    if (std::isinf(t)) return t > 0 ? "+∞" : "−∞";
    return num(t);
}
std::string tt(double t) {
    if (std::isinf(t)) return t > 0 ? "+\\infty" : "-\\infty";
    return tex(t);
}
// ... and as a variable: a number, or the strings "inf" / "-inf" as in the result's JSON.
Value tv(double t) {
    if (std::isinf(t)) return std::string(t > 0 ? "inf" : "-inf");
    return t;
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

// A number after a minus sign: negative ones in parentheses, "0 − (−2)".
std::string sub(double x) {
    return x < 0 ? "(" + num(x) + ")" : num(x);
}
std::string subtex(double x) {
    return x < 0 ? "(" + tex(x) + ")" : tex(x);
}

std::string at(const char* name, int i) {
    return std::string(name) + "[" + std::to_string(i) + "]";
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& RayAabb::spec() {
    static const Spec spec{
        "ray-aabb",
        "Ray against an axis-aligned box: the slab test",
        "Bounding Boxes and Spatial Subdivision",
        {
            "t_min ← −∞;  t_max ← +∞                 ▷ the ray P(t) = E + t d, t ≥ 0",
            "for each axis i = x, y, z:",
            "  if d_i = 0: slab ← (−∞, +∞) if min_i ≤ E_i ≤ max_i, else empty (+∞, −∞)",
            "  else: t_near ← (min_i − E_i)/d_i;  t_far ← (max_i − E_i)/d_i",
            "    if d_i < 0: swap(t_near, t_far)      ▷ the max plane comes first",
            "  t_min ← max(t_min, t_near);  t_max ← min(t_max, t_far)",
            "  if t_min > t_max: return miss          ▷ early-out: the slabs do not overlap",
            "if t_max < 0: return miss                ▷ the box is behind the origin",
            "return hit, in the box for t ∈ [max(t_min, 0), t_max]   ▷ t_min ≤ 0: E inside",
        },
        {
            {"slab", "d_i > 0: the two planes' t, the min plane first; then t_min, t_max"},
            {"slab-swapped", "d_i < 0: the max plane comes first, so the two t are swapped"},
            {"parallel-inside", "d_i = 0 and E between the planes: the slab is (−∞, +∞)"},
            {"parallel-outside", "d_i = 0 and E outside the planes: the slab is empty, a miss"},
            {"hit", "t_min ≤ t_max and t_min ≥ 0: the ray enters at t_min, leaves at t_max"},
            {"inside", "t_min ≤ 0 ≤ t_max: the origin is in the box; the ray leaves at t_max"},
            {"miss-disjoint", "t_min > t_max: no t is in every slab (the early-out)"},
            {"miss-behind", "t_max < 0: the line meets the box behind the origin only"},
        },
        {},  // no sliders
        {
            .predict = {
                {"slab", {"t_near", "t_far"}},
                {"slab-swapped", {"t_near", "t_far"}},
                {"hit", {"t_hit"}},
            },
            .mistakes = {
                {"slab", "t_min", "other:t_near", "updated t_min with min instead of max"},
                {"slab", "t_max", "other:t_far", "updated t_max with max instead of min"},
                {"hit", "t_hit", "copy:t_max", "took the exit t_max as the hit"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void RayAabb::validate(const Input& in) {
    for (int i = 0; i < 3; ++i) {
        check_finite(in.min[i], at("box.min", i));
        check_finite(in.max[i], at("box.max", i));
        check_finite(in.origin[i], at("origin", i));
        check_finite(in.direction[i], at("direction", i));
    }
    for (int i = 0; i < 3; ++i)
        if (in.min[i] > in.max[i])
            throw InputError(at("box.max", i),
                             "is less than box.min[" + std::to_string(i) + "] (" + given(in.max[i]) +
                                 " < " + given(in.min[i]) +
                                 "): the box is empty; it needs min ≤ max on every axis (a flat "
                                 "box, min = max, is allowed)");
    if (in.direction == dvec3(0.0))
        throw InputError("direction",
                         "must not be the zero vector (0, 0, 0): a ray needs a direction");
    // Every t must be a double: a tiny direction component against a huge distance would give
    // a t past 1.8e308, which IEEE arithmetic would round to ±∞ and the verdict could not order.
    for (int i = 0; i < 3; ++i) {
        const double d = in.direction[i];
        if (d == 0) continue;
        const double a = in.min[i] - in.origin[i], b = in.max[i] - in.origin[i];
        if (!std::isfinite(a) || !std::isfinite(b))
            throw InputError(at("origin", i),
                             "is too far from the box: the distance to its planes overflows a "
                             "double (beyond 1.8e308)");
        if (!std::isfinite(a / d) || !std::isfinite(b / d))
            throw InputError(at("direction", i),
                             "is too small against the distance to the box: t = (plane − E)/d "
                             "overflows a double (beyond 1.8e308); scale the direction up");
    }
}

RayAabb::State RayAabb::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// ---- [slab and intersect] -------------------------------------------------------------------

RayAabb::Slab RayAabb::slab(double min, double max, double origin, double direction) {
    Slab sl;
    if (direction == 0) {  // parallel: never divide (0/0 when E is on a face)
        const bool in_slab = min <= origin && origin <= max;
        sl.kind = in_slab ? Case::ParallelInside : Case::ParallelOutside;
        sl.t_near = in_slab ? -kInf : kInf;
        sl.t_far = in_slab ? kInf : -kInf;
        return sl;
    }
    // + 0.0 turns a −0 (E on a plane, d < 0) into 0, so the JSON never shows "-0.0".
    double t0 = (min - origin) / direction + 0.0, t1 = (max - origin) / direction + 0.0;
    sl.kind = Case::Crossing;
    if (direction < 0) std::swap(t0, t1), sl.kind = Case::Swapped;
    sl.t_near = t0, sl.t_far = t1;
    return sl;
}

namespace {

// t_min ≤ t_max: the verdict, and the surface point met.
void decide(RayAabb::Result& r) {
    if (r.t_min > r.t_max) {
        r.verdict = Verdict::Disjoint;
    } else if (r.t_max < 0) {
        r.verdict = Verdict::Behind;
    } else {
        r.verdict = r.t_min <= 0 ? Verdict::Inside : Verdict::Hit;
        r.hit = true;
        r.t_hit = r.t_min >= 0 ? r.t_min : r.t_max;
    }
}

}  // namespace

[[gnu::flatten]] RayAabb::Result RayAabb::intersect(const Input& in) {
    Result r;
    for (int i = 0; i < 3; ++i) {
        const Slab sl = slab(in.min[i], in.max[i], in.origin[i], in.direction[i]);
        r.axes[i] = sl;
        r.count = i + 1;
        r.t_min = std::max(r.t_min, sl.t_near);
        r.t_max = std::min(r.t_max, sl.t_far);
        if (r.t_min > r.t_max) break;
    }
    decide(r);
    return r;
}

// ---- [step] ---------------------------------------------------------------------------------

void RayAabb::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;  // a finished machine stays finished
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Axis: {  // One slab: its two planes (or the parallel case), then t_min/t_max
            const int i = s.axis;
            const Slab sl = slab(s.in.min[i], s.in.max[i], s.in.origin[i], s.in.direction[i]);
            s.r.axes[i] = sl;
            s.r.count = i + 1;
            s.r.t_min = std::max(s.r.t_min, sl.t_near);
            s.r.t_max = std::min(s.r.t_max, sl.t_far);
            ++s.axis;
            if (s.r.t_min > s.r.t_max || s.axis == 3) s.phase = Phase::Verdict;
            break;
        }
        case Phase::Verdict:
            decide(s.r);
            s.phase = Phase::Done;
            break;
        case Phase::Done:
            return;
    }
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = RayAabb::State;

void narrate_axis(const State& s, StepInfo& info) {
    const int i = s.axis - 1;
    const std::string a = kAxis[i];
    const RayAabb::Slab& sl = s.r.axes[i];
    const double mn = s.in.min[i], mx = s.in.max[i], e = s.in.origin[i], d = s.in.direction[i];
    const RayAabb::Result& r = s.r;
    std::string text = "Axis " + a + ": ";
    switch (sl.kind) {
        case Case::Crossing:
            info.event = "slab";
            info.line = kLinePlanes;
            text += "d_" + a + " = " + num(d) + " > 0, so the ray crosses the plane " + a +
                    " = min_" + a + " = " + num(mn) + " first, at t_near = (" + num(mn) + " − " +
                    sub(e) + ")/" + num(d) + " = " + tn(sl.t_near) + ", and the plane " + a +
                    " = max_" + a + " = " + num(mx) + " at t_far = (" + num(mx) + " − " + sub(e) +
                    ")/" + num(d) + " = " + tn(sl.t_far) + ".";
            info.math = "t_{near} = \\frac{" + tex(mn) + " - " + subtex(e) + "}{" + tex(d) +
                        "} = " + tt(sl.t_near) + ",\\; t_{far} = \\frac{" + tex(mx) + " - " +
                        subtex(e) + "}{" + tex(d) + "} = " + tt(sl.t_far);
            break;
        case Case::Swapped:
            info.event = "slab-swapped";
            info.line = kLineSwap;
            text += "d_" + a + " = " + num(d) + " < 0: the ray runs toward −" + a +
                    " and meets the plane " + a + " = max_" + a + " = " + num(mx) +
                    " first. (min_" + a + " − E_" + a + ")/d_" + a + " = (" + num(mn) + " − " +
                    sub(e) + ")/" + num(d) + " = " + tn(sl.t_far) + " and (max_" + a + " − E_" + a +
                    ")/d_" + a + " = (" + num(mx) + " − " + sub(e) + ")/" + num(d) + " = " +
                    tn(sl.t_near) + " are swapped: t_near = " + tn(sl.t_near) +
                    ", t_far = " + tn(sl.t_far) + ".";
            info.math = "t_{near} = \\frac{" + tex(mx) + " - " + subtex(e) + "}{" + tex(d) +
                        "} = " + tt(sl.t_near) + ",\\; t_{far} = \\frac{" + tex(mn) + " - " +
                        subtex(e) + "}{" + tex(d) + "} = " + tt(sl.t_far) + "\\quad(d_" + a +
                        " < 0\\text{: swapped})";
            break;
        case Case::ParallelInside:
            info.event = "parallel-inside";
            info.line = kLineParallel;
            text += "d_" + a + " = 0: the ray is parallel to the " + a + " slab, and E_" + a +
                    " = " + num(e) + " is between min_" + a + " = " + num(mn) + " and max_" + a +
                    " = " + num(mx) +
                    (e == mn || e == mx ? " (on a face: the box is closed, so that counts)" : "") +
                    ", so the ray is in this slab for every t: (t_near, t_far) = (−∞, +∞). No "
                    "division is made: (min − E)/0 would be ±∞" +
                    (e == mn || e == mx ? ", and here it would be 0/0, which has no value" : "") +
                    ".";
            info.math = "d_" + a + " = 0,\\; " + tex(mn) + " \\le E_" + a + " = " + tex(e) +
                        " \\le " + tex(mx) + ":\\; (t_{near}, t_{far}) = (-\\infty, +\\infty)";
            break;
        case Case::ParallelOutside:
            info.event = "parallel-outside";
            info.line = kLineParallel;
            text +=
                "d_" + a + " = 0: the ray is parallel to the " + a + " slab, and E_" + a + " = " +
                num(e) + " is " +
                (e < mn ? "below min_" + a + " = " + num(mn) : "above max_" + a + " = " + num(mx)) +
                ", so the ray is never in this slab: it is empty, written (t_near, t_far) = "
                "(+∞, −∞) so that the max and min below need no special case.";
            info.math = "d_" + a + " = 0,\\; E_" + a + " = " + tex(e) + " \\notin [" + tex(mn) +
                        ", " + tex(mx) + "]:\\; (t_{near}, t_{far}) = (+\\infty, -\\infty)";
            break;
    }
    text += " Running: t_min = " + tn(r.t_min) + ", t_max = " + tn(r.t_max) + ".";
    info.math += ";\\quad t_{min} = " + tt(r.t_min) + ",\\; t_{max} = " + tt(r.t_max);
    if (r.t_min > r.t_max) {
        info.line = kLineEarlyOut;
        text += " Now t_min > t_max: no t is in all the slabs so far, so the ray misses the box";
        text += s.axis < 3 ? std::string(" — the early-out: the ") +
                                 (s.axis == 1 ? "y and z slabs are" : "z slab is") + " not needed."
                           : ".";
    }
    info.narration = std::move(text);
}

void narrate_verdict(const State& s, StepInfo& info) {
    const RayAabb::Result& r = s.r;
    const dvec3 E = s.in.origin, d = s.in.direction;
    auto point = [&](double t) { return num(E + t * d); };
    switch (r.verdict) {
        case Verdict::Disjoint: {
            info.event = "miss-disjoint";
            info.line = kLineEarlyOut;
            const RayAabb::Slab& last = r.axes[r.count - 1];
            info.narration =
                "A miss: t_min = " + tn(r.t_min) + " > t_max = " + tn(r.t_max) +
                (last.kind == Case::ParallelOutside
                     ? std::string(": the ray is parallel to the ") + kAxis[r.count - 1] +
                           " slab and outside it."
                     : ": the ray leaves one slab before it enters another, so it is never in "
                       "all three at once.") +
                (r.count < 3 ? " The remaining axes were skipped (the early-out)." : "");
            info.math =
                "t_{min} = " + tt(r.t_min) + " > t_{max} = " + tt(r.t_max) + ":\\ \\text{miss}";
            return;
        }
        case Verdict::Behind:
            info.event = "miss-behind";
            info.line = kLineBehind;
            info.narration = "A miss: t_min = " + tn(r.t_min) + " ≤ t_max = " + tn(r.t_max) +
                             ", so the line through E meets the box, but t_max < 0: only behind "
                             "the origin. The ray is the half-line t ≥ 0, and the box is behind "
                             "it.";
            info.math = "t_{max} = " + tt(r.t_max) + " < 0:\\ \\text{miss (behind)}";
            return;
        case Verdict::Hit:
            info.event = "hit";
            info.line = kLineHit;
            info.narration =
                r.t_min == r.t_max
                    ? "A hit, but only a touch: t_min = t_max = " + tn(r.t_min) +
                          ", so the ray grazes an edge or a corner of the box at " +
                          point(r.t_min) + "."
                    : "A hit: t_min = " + tn(r.t_min) + " ≤ t_max = " + tn(r.t_max) +
                          " and t_min ≥ 0. The ray enters the box at t_min, the point " +
                          point(r.t_min) + ", and leaves it at t_max, the point " + point(r.t_max) +
                          "; t_hit = t_min = " + tn(r.t_hit) + ".";
            info.math = "0 \\le t_{min} = " + tt(r.t_min) + " \\le t_{max} = " + tt(r.t_max) +
                        ":\\ \\text{hit at } t = " + tt(r.t_hit);
            return;
        case Verdict::Inside:
            info.event = "inside";
            info.line = kLineHit;
            if (r.t_max == 0)
                info.narration = "A hit, only at t = 0: t_min = " + tn(r.t_min) +
                                 " ≤ 0 = t_max, so E = " + num(E) +
                                 " is on the box's surface and the ray leaves at once.";
            else if (r.t_min == 0)
                info.narration = "A hit at t = 0: t_min = 0 ≤ t_max = " + tn(r.t_max) +
                                 ", so E = " + num(E) +
                                 " is on the box's surface and the ray goes in there, leaving "
                                 "at t_max, the point " +
                                 point(r.t_max) + ". t_hit = 0.";
            else
                info.narration = "A hit from inside: t_min = " + tn(r.t_min) +
                                 " < 0 ≤ t_max = " + tn(r.t_max) + ", so the origin E = " + num(E) +
                                 " is inside the box (t_min is behind it, where the line came "
                                 "in). The ray meets the box's surface on the way out, at t_max, "
                                 "the point " +
                                 point(r.t_max) + ": t_hit = t_max = " + tn(r.t_hit) +
                                 "; t_min and t_max are both reported.";
            info.math = "t_{min} = " + tt(r.t_min) + " \\le 0 \\le t_{max} = " + tt(r.t_max) +
                        ":\\ \\text{inside, } t_{hit} = " + tt(r.t_hit);
            return;
        case Verdict::None:
            return;
    }
}

void fill_vars(const State& s, StepInfo& info) {
    const RayAabb::Result& r = s.r;
    info.vars = {{"E", vec(s.in.origin)},
                 {"d", vec(s.in.direction)},
                 {"min", vec(s.in.min)},
                 {"max", vec(s.in.max)}};
    if (s.last == Phase::Axis) {
        const RayAabb::Slab& sl = r.axes[s.axis - 1];
        info.vars.push_back({"axis", std::string(kAxis[s.axis - 1])});
        info.vars.push_back({"t_near", tv(sl.t_near)});
        info.vars.push_back({"t_far", tv(sl.t_far)});
    }
    info.vars.push_back({"t_min", tv(r.t_min)});
    info.vars.push_back({"t_max", tv(r.t_max)});
    if (s.last == Phase::Verdict) {
        info.vars.push_back({"hit", r.hit});
        if (r.hit) info.vars.push_back({"t_hit", r.t_hit});
    }
}

}  // namespace

void RayAabb::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    if (s.last == Phase::Axis)
        narrate_axis(s, info);
    else
        narrate_verdict(s, info);
    fill_vars(s, info);
}

}  // namespace cg
