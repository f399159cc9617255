// Sections: [distances] [spec] [validate] [advance] [narrate] [result and compute]
// (the picture is in sphere_tracing_draw.cpp)
#include "modelling/sphere_tracing.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = SphereTracing::Input;
using Shape = SphereTracing::Shape;
using Kind = SphereTracing::Kind;
using Combine = SphereTracing::Combine;
using Outcome = SphereTracing::Outcome;
using Phase = SphereTracing::Phase;
using State = SphereTracing::State;

enum Line {
    kLineStart = 1,
    kLinePoint,
    kLineDistance,
    kLineHit,
    kLineAdvance,
    kLineEscape,
    kLineSteps
};

}  // namespace

// ---- [distances] ----------------------------------------------------------------------------

// Sphere: |p − c| − r. Box (half extents b): with q = |p − c| − b per axis, the distance outside
// is |max(q, 0)| and inside (all q < 0) it is max(q.x, q.y, q.z), the nearest face. Torus
// (axis y): the distance to the tube's centre circle, √((√(x² + z²) − R)² + y²), minus r.
double SphereTracing::shape_distance(const Shape& s, glm::dvec3 p) {
    const glm::dvec3 q = p - s.centre;
    switch (s.kind) {
        case Kind::Sphere:
            return glm::length(q) - s.size.x;
        case Kind::Box: {
            const glm::dvec3 e = glm::abs(q) - s.size;
            const double outside = glm::length(glm::max(e, glm::dvec3(0.0)));
            const double inside = std::min(std::max(e.x, std::max(e.y, e.z)), 0.0);
            return outside + inside;
        }
        case Kind::Torus: {
            const double ring = std::sqrt(q.x * q.x + q.z * q.z) - s.size.x;
            return std::sqrt(ring * ring + q.y * q.y) - s.size.y;
        }
    }
    return 0;
}

double SphereTracing::smooth_min(double a, double b, double k) {
    const double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return b + h * (a - b) - k * h * (1.0 - h);
}

double SphereTracing::distance(const Input& in, glm::dvec3 p) {
    double d = shape_distance(in.shapes[0], p);
    for (std::size_t i = 1; i < in.shapes.size(); ++i) {
        const double e = shape_distance(in.shapes[i], p);
        switch (in.combine) {
            case Combine::Union:
                d = std::min(d, e);
                break;
            case Combine::Intersection:
                d = std::max(d, e);
                break;
            case Combine::Difference:
                d = std::max(d, -e);
                break;
            case Combine::SmoothUnion:
                d = smooth_min(d, e, in.k);
                break;
        }
    }
    return d;
}

const char* SphereTracing::kind_name(Kind k) {
    switch (k) {
        case Kind::Sphere:
            return "sphere";
        case Kind::Box:
            return "box";
        case Kind::Torus:
            return "torus";
    }
    return "?";
}

const char* SphereTracing::combine_name(Combine c) {
    switch (c) {
        case Combine::Union:
            return "union";
        case Combine::Intersection:
            return "intersection";
        case Combine::Difference:
            return "difference";
        case Combine::SmoothUnion:
            return "smooth-union";
    }
    return "?";
}

const char* SphereTracing::outcome_name(Outcome o) {
    switch (o) {
        case Outcome::Hit:
            return "hit";
        case Outcome::Escaped:
            return "escaped";
        case Outcome::OutOfSteps:
            return "out-of-steps";
    }
    return "?";
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& SphereTracing::spec() {
    static const Spec spec{
        "sphere-tracing",
        "Sphere tracing: marching a ray through a signed distance field",
        "Modelling",
        {
            "d̂ ← direction / |direction|;  t ← 0;  k ← 0",
            "repeat:  p_k ← o + t·d̂",
            "  d_k ← f(p_k)   ▷ the distance bound: min (union), max (intersection), "
            "max(a, −b) (difference), smin_k (smooth union)",
            "  if d_k < ε: return hit at t, p_k   ▷ within ε of the surface (or inside)",
            "  t ← t + d_k;  k ← k + 1   ▷ the ball of radius d_k around p_k holds no surface",
            "  if t > max_distance: return miss   ▷ the ray escaped",
            "  if k = max_steps: return miss   ▷ out of steps (a grazing ray creeps)",
        },
        {
            {"march", "one sample: p_k and its distance d_k ≥ ε, then t advances by d_k"},
            {"hit", "a sample within ε of the surface (d_k < ε): the ray hits at t"},
            {"escaped", "t went past max_distance: the ray misses"},
            {"out-of-steps", "max_steps samples without getting within ε: counted as a miss"},
        },
        {},  // no sliders
        {
            .predict = {{"march", {"d_k", "t"}}, {"hit", {"t"}}},
            .mistakes =
                {
                    {"march", "t", "keep",
                     "forgot t ← t + d_k: the ray samples the same point over and over"},
                    {"march", "d_k", "negate",
                     "took the signed distance with the wrong sign (inside read as outside)"},
                    {"hit", "", "event:escaped",
                     "tested d_k > ε instead of d_k < ε: a hit read as a miss"},
                },
            .variants = {{"union", "/combine", "\"union\""},
                         {"smooth union", "/combine", "\"smooth-union\""}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

std::string shape_field(std::size_t i, const char* name) {
    return "shapes[" + std::to_string(i) + "]." + name;
}

void check_point(const std::string& field, glm::dvec3 p) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(p[a]) || std::abs(p[a]) > SphereTracing::kMaxCoordinate)
            throw InputError(
                field, "must be finite numbers of magnitude at most 1e6 (got " + given(p) + ")");
}

void check_length(const std::string& field, double v) {
    if (!std::isfinite(v) || v <= 0 || v > SphereTracing::kMaxCoordinate)
        throw InputError(field, "must be a length above 0 and at most 1e6 (got " + given(v) + ")");
}

}  // namespace

void SphereTracing::validate(const Input& in) {
    if (in.shapes.empty()) throw InputError("shapes", "must list at least one shape");
    if (in.shapes.size() > std::size_t(kMaxShapes))
        throw InputError("shapes", "at most " + std::to_string(kMaxShapes) + " shapes (got " +
                                       std::to_string(in.shapes.size()) + ")");
    for (std::size_t i = 0; i < in.shapes.size(); ++i) {
        const Shape& s = in.shapes[i];
        check_point(shape_field(i, "centre"), s.centre);
        switch (s.kind) {
            case Kind::Sphere:
                check_length(shape_field(i, "radius"), s.size.x);
                break;
            case Kind::Box:
                for (int a = 0; a < 3; ++a) check_length(shape_field(i, "half_size"), s.size[a]);
                break;
            case Kind::Torus:
                check_length(shape_field(i, "major_radius"), s.size.x);
                check_length(shape_field(i, "minor_radius"), s.size.y);
                if (s.size.y >= s.size.x)
                    throw InputError(shape_field(i, "minor_radius"),
                                     "must be below the major radius (a ring torus; got r = " +
                                         given(s.size.y) + ", R = " + given(s.size.x) + ")");
                break;
        }
    }
    if (in.combine == Combine::SmoothUnion) check_length("k", in.k);
    check_point("origin", in.origin);
    check_point("direction", in.direction);
    if (in.direction == glm::dvec3(0.0))
        throw InputError("direction", "must not be the zero vector (a ray needs a direction)");
    if (!std::isfinite(in.epsilon) || in.epsilon <= 0 || in.epsilon > 1)
        throw InputError("epsilon", "must be above 0 and at most 1 (got " + given(in.epsilon) + ")");
    if (!std::isfinite(in.max_distance) || in.max_distance <= 0 || in.max_distance > 1e9)
        throw InputError("max_distance",
                         "must be above 0 and at most 1e9 (got " + given(in.max_distance) + ")");
    if (in.max_steps < 1 || in.max_steps > kMaxSteps)
        throw InputError("max_steps", "must be 1 to " + std::to_string(kMaxSteps) + " (got " +
                                          std::to_string(in.max_steps) + ")");
}

SphereTracing::State SphereTracing::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

SphereTracing::State SphereTracing::begin(Shared<Input> shared) {
    State s;
    s.unit = unit(shared->direction);
    s.in = std::move(shared);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void SphereTracing::advance(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::March: {
            s.last = Phase::March;
            s.t_prev = s.t;
            s.d = distance(in, in.origin + s.t * s.unit);
            s.ts.push_back(s.t);
            s.ds.push_back(s.d);
            ++s.k;
            if (s.d < in.epsilon) {
                s.outcome = Outcome::Hit;
                s.phase = Phase::Done;
                return;
            }
            s.t += s.d;
            if (s.t > in.max_distance) {
                s.outcome = Outcome::Escaped;
                s.phase = Phase::Verdict;
            } else if (s.k == in.max_steps) {
                s.outcome = Outcome::OutOfSteps;
                s.phase = Phase::Verdict;
            }
            return;
        }
        case Phase::Verdict:
            s.last = Phase::Verdict;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

// The shape nearest p (smallest |distance|), for the narration.
std::string nearest(const Input& in, glm::dvec3 p) {
    std::size_t best = 0;
    double bd = 0;
    for (std::size_t i = 0; i < in.shapes.size(); ++i) {
        const double d = std::abs(SphereTracing::shape_distance(in.shapes[i], p));
        if (i == 0 || d < bd) {
            best = i;
            bd = d;
        }
    }
    return std::string(SphereTracing::kind_name(in.shapes[best].kind)) + " " +
           std::to_string(best) + " (" + num(SphereTracing::shape_distance(in.shapes[best], p)) +
           " away)";
}

void narrate_sample(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const int k = s.k - 1;
    const glm::dvec3 p = in.origin + s.t_prev * s.unit;
    const std::string ks = std::to_string(k);
    const std::string head = "Sample " + ks + ": p_" + ks + " = o + " + num(s.t_prev) +
                             "·d̂ = " + num(p) + "; the scene's distance bound there is d_" + ks +
                             " = " + num(s.d) +
                             (in.shapes.size() > 1 ? " (nearest: " + nearest(in, p) + ")" : "");
    info.vars = {{"k", (long long)k}, {"p_k", vec(p)}, {"d_k", s.d}};
    if (s.outcome == Outcome::Hit && s.phase == Phase::Done) {
        info.event = "hit";
        info.line = kLineHit;
        info.narration =
            head +
            (s.d < 0 ? (k == 0 ? ", below 0: the ray starts inside the surface, so it hits at once"
                               : ", below 0: the point is inside")
                     : ", below ε = " + num(in.epsilon) + ": within ε of the surface") +
            " — a hit at t = " + num(s.t_prev) + " after " + std::to_string(s.k) + " sample" +
            (s.k == 1 ? "" : "s") + ".";
        info.math = "d_{" + ks + "} = " + tex(s.d) + " < \\varepsilon = " + tex(in.epsilon);
        info.vars.push_back({"t", s.t_prev});
        info.vars.push_back({"hit", true});
        return;
    }
    info.event = "march";
    info.line = kLineAdvance;
    info.narration = head + " ≥ ε = " + num(in.epsilon) + ", so the ball of radius " + num(s.d) +
                     " around p_" + ks + " holds no surface: step across it, t = " + num(s.t_prev) +
                     " + " + num(s.d) + " = " + num(s.t) + ".";
    info.math = "t_{" + std::to_string(k + 1) + "} = " + tex(s.t_prev) + " + " + tex(s.d) + " = " +
                tex(s.t);
    info.vars.push_back({"t", s.t});
}

void narrate_verdict(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.vars = {{"k", (long long)s.k}, {"t", s.t}, {"hit", false}};
    if (s.outcome == Outcome::Escaped) {
        info.event = "escaped";
        info.line = kLineEscape;
        info.narration = "t = " + num(s.t) + " is past max_distance = " + num(in.max_distance) +
                         ": nothing lies ahead within reach — a miss after " + std::to_string(s.k) +
                         " sample" + (s.k == 1 ? "" : "s") + ".";
        info.math = "t = " + tex(s.t) + " > " + tex(in.max_distance);
        return;
    }
    info.event = "out-of-steps";
    info.line = kLineSteps;
    info.narration = std::to_string(s.k) +
                     " samples (max_steps) without getting within ε = " + num(in.epsilon) +
                     "; the last distance was " + num(s.d) +
                     ". Counted as a miss: a ray grazing a surface creeps along it with ever "
                     "smaller steps.";
    info.math = "k = " + std::to_string(s.k) + " = k_{\\max}";
}

}  // namespace

void SphereTracing::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    if (s.last == Phase::March)
        narrate_sample(s, info);
    else
        narrate_verdict(s, info);
}

void SphereTracing::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

SphereTracing::Result SphereTracing::result(const State& s) {
    Result r;
    r.outcome = s.outcome;
    r.t = s.outcome == Outcome::Hit ? s.t_prev : s.t;
    r.point = s.in->origin + r.t * s.unit;
    r.samples = s.k;
    r.ts = s.ts;
    r.ds = s.ds;
    return r;
}

SphereTracing::Result SphereTracing::compute(const Input& in) {
    Result r;
    const glm::dvec3 u = unit(in.direction);
    double t = 0;
    r.outcome = Outcome::OutOfSteps;
    for (int k = 0; k < in.max_steps; ++k) {
        const double d = distance(in, in.origin + t * u);
        r.ts.push_back(t);
        r.ds.push_back(d);
        if (d < in.epsilon) {
            r.outcome = Outcome::Hit;
            break;
        }
        t += d;
        if (t > in.max_distance) {
            r.outcome = Outcome::Escaped;
            break;
        }
    }
    r.samples = int(r.ts.size());
    r.t = t;
    r.point = in.origin + t * u;
    return r;
}

}  // namespace cg
