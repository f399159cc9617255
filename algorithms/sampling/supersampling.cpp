// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and supersample] [draw]
#include "sampling/supersampling.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Phase = Supersampling::Phase;
using sampling::Filter;
using sampling::Pattern;
using sampling::RegionKind;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLinePattern = 1,
    kLineValue,
    kLineWeight,
    kLineEstimate,
    kLineExact,
    kLineError,
};

double orient(dvec2 a, dvec2 b, dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool on_segment(dvec2 a, dvec2 b, dvec2 p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Whether closed segments ab and cd share a point.
bool segments_meet(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
                 o4 = orient(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return true;
    return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
           (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

void check_coordinate(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + num(v) + ")");
    if (std::fabs(v) > Supersampling::kMaxCoordinate)
        throw InputError(field, "must be within ±10⁶ pixels (got " + num(v) + ")");
}

std::string filter_formula(Filter f) {
    switch (f) {
        case Filter::Box:
            return "w = 1";
        case Filter::Tent:
            return "w = (1 − |dx|)(1 − |dy|)";
        case Filter::Gaussian:
            return "w = exp(−(dx² + dy²)/(2·0.5²))";
    }
    return "";
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Supersampling::spec() {
    static const Spec spec{
        "supersampling",
        "Anti-aliasing a pixel: supersampling and area sampling",
        "Ray Tracing",
        {
            "(x_k, y_k) ← pattern(N, seed) in pixel (i, j)   ▷ regular, random, jittered, poisson",
            "for each sample k:  v_k ← f(x_k, y_k)            ▷ 1 inside the scene, 0 outside",
            "    w_k ← filter(x_k − c_x, y_k − c_y);  Σw += w_k,  Σwv += w_k v_k",
            "estimate ← Σ w_k v_k / Σ w_k",
            "exact ← ∫∫ w f / ∫∫ w over the pixel   ▷ area sampling: the covered polygon",
            "error ← estimate − exact",
        },
        {
            {"pattern", "the sample positions in the pixel, and how the pattern made them"},
            {"inside", "a sample inside the scene: value 1, and its weight"},
            {"outside", "a sample outside the scene: value 0, and its weight"},
            {"estimate", "the filtered average of the samples, Σ w v / Σ w"},
            {"exact", "area sampling: the covered part of the pixel, its weighted area, the error"},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Supersampling::validate(const Input& in) {
    if (in.samples < 1 || in.samples > kMaxSamples)
        throw InputError("samples", "must be between 1 and " + std::to_string(kMaxSamples) +
                                        " (got " + std::to_string(in.samples) + ")");
    if (sampling::is_grid(in.pattern) && sampling::grid_side(in.samples) == 0)
        throw InputError("samples",
                         std::string("must be a square number n × n (1, 4, 9, 16, …) for "
                                     "the ") +
                             sampling::pattern_id(in.pattern) + " pattern (got " +
                             std::to_string(in.samples) + ")");
    if (!std::isfinite(in.radius) || in.radius < 0 || in.radius > 2)
        throw InputError("radius", "must be between 0 and 2 pixels (got " + num(in.radius) + ")");
    check_coordinate(in.i, "pixel[0]");
    check_coordinate(in.j, "pixel[1]");
    const sampling::Region& r = in.scene;
    if (r.kind == RegionKind::Edge) {
        check_coordinate(r.point.x, "scene.point[0]");
        check_coordinate(r.point.y, "scene.point[1]");
        if (!std::isfinite(r.angle_deg))
            throw InputError("scene.angle",
                             "must be a finite number (got " + num(r.angle_deg) + ")");
        return;
    }
    const auto& p = r.points;
    const std::size_t n = p.size();
    if (n < 3 || n > std::size_t(kMaxPolygon))
        throw InputError("scene.points", "must have between 3 and " + std::to_string(kMaxPolygon) +
                                             " vertices (got " + std::to_string(n) + ")");
    for (std::size_t k = 0; k < n; ++k) {
        check_coordinate(p[k].x, "scene.points[" + std::to_string(k) + "][0]");
        check_coordinate(p[k].y, "scene.points[" + std::to_string(k) + "][1]");
    }
    for (std::size_t k = 0; k < n; ++k)
        if (p[k] == p[(k + 1) % n])
            throw InputError("scene.points[" + std::to_string((k + 1) % n) + "]",
                             "repeats the vertex before it: the polygon has a zero-length edge");
    if (sampling::signed_area(p) == 0)
        throw InputError("scene.points",
                         "has zero area (all vertices on one line): it covers nothing");
    // Simple: edges that are not neighbours share no point; neighbours share only their vertex.
    for (std::size_t a = 0; a < n; ++a) {
        const dvec2 a0 = p[a], a1 = p[(a + 1) % n];
        for (std::size_t b = a + 1; b < n; ++b) {
            const dvec2 b0 = p[b], b1 = p[(b + 1) % n];
            const bool next = b == a + 1, wrap = a == 0 && b == n - 1;
            bool bad;
            if (next)  // share a1 = b0: bad if b1 lies on a back along it (a fold)
                bad = orient(a0, a1, b1) == 0 && glm::dot(a0 - a1, b1 - a1) > 0;
            else if (wrap)  // share a0 = b1
                bad = orient(b0, b1, a1) == 0 && glm::dot(b0 - b1, a1 - b1) > 0;
            else
                bad = segments_meet(a0, a1, b0, b1);
            if (bad)
                throw InputError("scene.points", "must be a simple polygon: edges " +
                                                     std::to_string(a) + " and " +
                                                     std::to_string(b) + " cross or touch");
        }
    }
}

double Supersampling::radius_of(const Input& in) {
    if (in.pattern != Pattern::Poisson) return 0;
    return in.radius > 0 ? in.radius : sampling::default_radius(in.samples);
}

Supersampling::State Supersampling::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.radius = radius_of(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {

Supersampling::Sample take(const Supersampling::Input& in, const sampling::PatternPoint& q) {
    Supersampling::Sample smp;
    smp.p = dvec2(in.i, in.j) + q.p;
    smp.value = sampling::region_value(in.scene, smp.p);
    smp.weight = sampling::weight(in.filter, q.p - dvec2(0.5));
    return smp;
}

}  // namespace

void Supersampling::advance(State& s) {
    const Input& in = *s.in;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Pattern:  // The positions
            s.points = sampling::generate(in.pattern, in.samples, in.seed, s.radius);
            s.samples.reserve(s.points.size());
            s.phase = Phase::Sample;
            return;
        case Phase::Sample: {  // One sample: its value and weight
            ++s.k;
            const Sample smp = take(in, s.points[s.k]);
            s.sum_w += smp.weight;
            s.sum_wv += smp.weight * smp.value;
            s.samples.push_back(smp);
            if (s.k + 1 == int(s.points.size())) s.phase = Phase::Estimate;
            return;
        }
        case Phase::Estimate:
            s.estimate = s.sum_wv / s.sum_w;
            s.phase = Phase::Exact;
            return;
        case Phase::Exact:  // Area sampling: the covered polygon
            s.covered = sampling::covered_polygon(in.scene, in.i, in.j);
            s.covered_integral =
                sampling::weighted_area(in.filter, s.covered, {in.i + 0.5, in.j + 0.5});
            s.exact = std::clamp(s.covered_integral / sampling::pixel_weight_integral(in.filter),
                                 0.0, 1.0);
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = Supersampling::State;

std::string pattern_text(const State& s) {
    const Supersampling::Input& in = *s.in;
    const int n = sampling::grid_side(in.samples);
    const std::string N = std::to_string(in.samples);
    switch (in.pattern) {
        case Pattern::Regular:
            return N + " samples on a regular " + std::to_string(n) + " × " + std::to_string(n) +
                   " grid: the centres of the cells, x = i + (a + ½)/" + std::to_string(n) +
                   ", y = j + (b + ½)/" + std::to_string(n) +
                   " (no randomness: the seed is unused)";
        case Pattern::Random:
            return N +
                   " random samples, each (x, y) = (i + ξx, j + ξy) with ξ uniform in [0, 1) "
                   "from seed " +
                   std::to_string(in.seed);
        case Pattern::Jittered:
            return N + " jittered samples: the pixel cut into " + std::to_string(n) + " × " +
                   std::to_string(n) + " cells, one uniform point in each, x = i + (a + ξx)/" +
                   std::to_string(n) + ", y = j + (b + ξy)/" + std::to_string(n) + " (seed " +
                   std::to_string(in.seed) + ")";
        case Pattern::Poisson: {
            int darts = 0;
            for (const auto& q : s.points) darts += q.darts;
            std::string t =
                "Poisson-disc samples by dart throwing (seed " + std::to_string(in.seed) +
                "): uniform darts, each kept only if at "
                "least r = " +
                num(s.radius, 4) + " from every sample kept before; " +
                std::to_string(s.points.size()) + " kept of " + std::to_string(darts) + " darts";
            if (int(s.points.size()) < in.samples)
                t += " — only " + std::to_string(s.points.size()) + " of the " + N +
                     " wanted fit before the limit of " +
                     std::to_string(sampling::kMaxDartsPerSample) +
                     " darts per sample: r is too large for so many";
            return t;
        }
    }
    return "";
}

void narrate_pattern(const State& s, StepInfo& info) {
    const Supersampling::Input& in = *s.in;
    info.event = "pattern";
    info.line = kLinePattern;
    info.narration = "Pixel (" + std::to_string(in.i) + ", " + std::to_string(in.j) + ") covers [" +
                     std::to_string(in.i) + ", " + std::to_string(in.i + 1) + ") × [" +
                     std::to_string(in.j) + ", " + std::to_string(in.j + 1) + "). " +
                     pattern_text(s) + ". Filter: " + sampling::filter_id(in.filter) + ", " +
                     filter_formula(in.filter) + " at offset (dx, dy) from the centre.";
    info.math = "c = (" + tex(in.i + 0.5) + ", " + tex(in.j + 0.5) +
                "),\\; N = " + std::to_string(s.points.size());
}

void narrate_sample(const State& s, StepInfo& info) {
    const Supersampling::Input& in = *s.in;
    const auto& q = s.points[s.k];
    const Supersampling::Sample& smp = s.samples[s.k];
    const int n = sampling::grid_side(in.samples);
    const std::string I = std::to_string(in.i), J = std::to_string(in.j);
    std::string where;
    switch (in.pattern) {
        case Pattern::Regular:
            where = "cell (" + std::to_string(q.cell_a) + ", " + std::to_string(q.cell_b) +
                    "): x = " + I + " + (" + std::to_string(q.cell_a) + " + ½)/" +
                    std::to_string(n) + ", y = " + J + " + (" + std::to_string(q.cell_b) +
                    " + ½)/" + std::to_string(n);
            break;
        case Pattern::Jittered:
            where = "cell (" + std::to_string(q.cell_a) + ", " + std::to_string(q.cell_b) +
                    "), ξ = " + num(q.xi, 4) + ": x = " + I + " + (" + std::to_string(q.cell_a) +
                    " + " + num(q.xi.x, 4) + ")/" + std::to_string(n) + ", y = " + J + " + (" +
                    std::to_string(q.cell_b) + " + " + num(q.xi.y, 4) + ")/" + std::to_string(n);
            break;
        case Pattern::Random:
            where = "ξ = " + num(q.xi, 4) + ": x = " + I + " + ξx, y = " + J + " + ξy";
            break;
        case Pattern::Poisson:
            where = q.darts == 1 ? "the first dart landed at least r from every kept sample"
                                 : std::to_string(q.darts - 1) +
                                       (q.darts == 2 ? " dart fell" : " darts fell") +
                                       " closer than r to a kept sample, then this one landed";
            break;
    }
    const dvec2 d = smp.p - dvec2(in.i + 0.5, in.j + 0.5);
    info.event = smp.value > 0 ? "inside" : "outside";
    info.line = kLineValue;
    info.narration =
        "Sample " + std::to_string(s.k + 1) + " of " + std::to_string(s.points.size()) + " at " +
        num(smp.p, 4) + " (" + where +
        "): " + (smp.value > 0 ? "inside the scene, v = 1" : "outside, v = 0") + "; offset (" +
        num(d.x, 4) + ", " + num(d.y, 4) + ") from the centre, " +
        (in.filter == Filter::Box ? std::string("box weight w = 1")
                                  : filter_formula(in.filter) + " = " + num(smp.weight, 4)) +
        ". Σw = " + num(s.sum_w, 6) + ", Σwv = " + num(s.sum_wv, 6) + ".";
    info.math = "v_{" + std::to_string(s.k + 1) + "} = " + tex(smp.value) + ",\\; w_{" +
                std::to_string(s.k + 1) + "} = " + tex(smp.weight, 4) +
                ",\\; \\Sigma w = " + tex(s.sum_w, 6) + ",\\; \\Sigma wv = " + tex(s.sum_wv, 6);
}

void narrate_estimate(const State& s, StepInfo& info) {
    info.event = "estimate";
    info.line = kLineEstimate;
    int in_count = 0;
    for (const auto& smp : s.samples) in_count += smp.value > 0;
    info.narration = std::to_string(in_count) + " of " + std::to_string(s.samples.size()) +
                     " samples are inside. Estimate = Σ w v / Σ w = " + num(s.sum_wv, 6) + " / " +
                     num(s.sum_w, 6) + " = " + num(s.estimate, 6) + ".";
    info.math = "\\hat I = \\frac{\\sum w_k v_k}{\\sum w_k} = \\frac{" + tex(s.sum_wv, 6) + "}{" +
                tex(s.sum_w, 6) + "} = " + tex(s.estimate, 6);
}

void narrate_exact(const State& s, StepInfo& info) {
    const Supersampling::Input& in = *s.in;
    info.event = "exact";
    info.line = kLineExact;
    const std::string what = in.scene.kind == RegionKind::Edge
                                 ? "the pixel square clipped by the edge's half-plane"
                                 : "the polygon clipped to the pixel square";
    std::string t;
    if (s.covered.empty())
        t = "Area sampling: the scene does not cover the pixel at all, so exact = 0";
    else if (in.filter == Filter::Box)
        t = "Area sampling: the covered part is " + what + ", a polygon of " +
            std::to_string(s.covered.size()) + " vertices with area " + num(s.covered_integral, 6) +
            " (shoelace): the exact box-filtered value is the covered fraction, " + num(s.exact, 6);
    else
        t = "Weighted area sampling: the covered part is " + what +
            "; ∫∫ w over it = " + num(s.covered_integral, 6) + " and over the whole pixel " +
            num(sampling::pixel_weight_integral(in.filter), 6) + ", so exact = " + num(s.exact, 6);
    info.narration = t + ". Error = estimate − exact = " + num(s.estimate, 6) + " − " +
                     num(s.exact, 6) + " = " + num(s.estimate - s.exact, 4) + ".";
    info.math = "I = \\frac{\\iint w f}{\\iint w} = " + tex(s.exact, 6) +
                ",\\; \\hat I - I = " + tex(s.estimate - s.exact, 4);
}

void fill_vars(const State& s, StepInfo& info) {
    const Supersampling::Input& in = *s.in;
    info.vars = {{"pixel", std::vector<double>{double(in.i), double(in.j)}},
                 {"N", static_cast<long long>(s.points.size())}};
    if (in.pattern == Pattern::Poisson) info.vars.push_back({"r", s.radius});
    if (s.last == Phase::Sample) {
        const auto& smp = s.samples[s.k];
        info.vars.push_back({"k", static_cast<long long>(s.k + 1)});
        info.vars.push_back({"x_k", vec(smp.p)});
        if (in.pattern != Pattern::Regular) info.vars.push_back({"xi", vec(s.points[s.k].xi)});
        info.vars.push_back({"v_k", smp.value});
        info.vars.push_back({"w_k", smp.weight});
    }
    if (s.last >= Phase::Sample) {
        info.vars.push_back({"sum_w", s.sum_w});
        info.vars.push_back({"sum_wv", s.sum_wv});
    }
    if (s.last >= Phase::Estimate) info.vars.push_back({"estimate", s.estimate});
    if (s.last >= Phase::Exact) {
        info.vars.push_back({"covered_integral", s.covered_integral});
        info.vars.push_back({"exact", s.exact});
        info.vars.push_back({"error", s.estimate - s.exact});
    }
}

}  // namespace

void Supersampling::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Pattern:
            narrate_pattern(s, info);
            break;
        case Phase::Sample:
            narrate_sample(s, info);
            break;
        case Phase::Estimate:
            narrate_estimate(s, info);
            break;
        case Phase::Exact:
        case Phase::Done:
            narrate_exact(s, info);
            break;
    }
    fill_vars(s, info);
}

void Supersampling::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and supersample] ---------------------------------------------------------------

Supersampling::Result Supersampling::result(const State& s) {
    Result r;
    r.samples = s.samples;
    r.weight_sum = s.sum_w;
    r.estimate = s.estimate;
    r.exact = s.exact;
    r.error = s.estimate - s.exact;
    r.radius = s.radius;
    r.covered = s.covered;
    return r;
}

Supersampling::Result Supersampling::supersample(const Input& in) {
    Result r;
    r.radius = radius_of(in);
    const auto points = sampling::generate(in.pattern, in.samples, in.seed, r.radius);
    r.samples.reserve(points.size());
    double sum_wv = 0;
    for (const auto& q : points) {
        const Sample smp = take(in, q);
        r.weight_sum += smp.weight;
        sum_wv += smp.weight * smp.value;
        r.samples.push_back(smp);
    }
    r.estimate = sum_wv / r.weight_sum;
    r.covered = sampling::covered_polygon(in.scene, in.i, in.j);
    r.exact = std::clamp(sampling::weighted_area(in.filter, r.covered, {in.i + 0.5, in.j + 0.5}) /
                             sampling::pixel_weight_integral(in.filter),
                         0.0, 1.0);
    r.error = r.estimate - r.exact;
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

// The pixel (blue) among its eight neighbours (grid lines), the scene (the edge's half-plane
// with the outside shaded, or the polygon), the pattern's cells, and the samples: grey before
// they are taken, then green inside and red outside, sized by weight; the current one orange
// with, for Poisson, its exclusion circle. From the exact step on, the covered polygon (green).
void Supersampling::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const double x0 = in.i, y0 = in.j;
    const Style grid{Role::Construction, 1.0f, false};
    for (int k = -1; k <= 2; ++k) {
        scene.segments.push_back({{x0 + k, y0 - 1}, {x0 + k, y0 + 2}, "", grid, false});
        scene.segments.push_back({{x0 - 1, y0 + k}, {x0 + 2, y0 + k}, "", grid, false});
    }
    scene.polygons.push_back({{{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}},
                              {Role::Window, 2.5f},
                              true,
                              false});
    scene.points.push_back({{x0 + 0.5, y0 + 0.5}, "", {Role::Window}, 2.5f});
    scene.labels.push_back({{x0 + 0.02, y0 - 0.12},
                            "pixel (" + std::to_string(in.i) + ", " + std::to_string(in.j) + ")",
                            {Role::Window}});

    const sampling::Region& r = in.scene;
    if (r.kind == RegionKind::Edge) {
        const dvec2 d = sampling::edge_direction(r.angle_deg);
        // The line's point nearest the pixel's centre: where the handle sits.
        const dvec2 c(x0 + 0.5, y0 + 0.5);
        const dvec2 foot = r.point + d * glm::dot(c - r.point, d);
        scene.half_planes.push_back({foot, {-d.y, d.x}, "edge", {Role::Subject, 2.0f}});
        scene.handles.push_back({foot, "edge", "/scene/point/0", "/scene/point/1"});
    } else {
        scene.polygons.push_back({r.points, {Role::Subject, 2.0f}, true, true});
        for (std::size_t k = 0; k < r.points.size(); ++k) {
            const std::string p = "/scene/points/" + std::to_string(k);
            scene.handles.push_back({r.points[k], "P" + std::to_string(k), p + "/0", p + "/1"});
        }
    }

    if (sampling::is_grid(in.pattern)) {
        const int n = sampling::grid_side(in.samples);
        if (n > 1 && n <= 16)
            for (int k = 1; k < n; ++k) {
                const double t = double(k) / n;
                const Style cells{Role::Construction, 1.0f, true};
                scene.segments.push_back({{x0 + t, y0}, {x0 + t, y0 + 1}, "", cells, false});
                scene.segments.push_back({{x0, y0 + t}, {x0 + 1, y0 + t}, "", cells, false});
            }
    }

    if (s.phase >= Phase::Done && !s.covered.empty())
        scene.polygons.push_back({s.covered, {Role::Kept, 2.0f}, true, true});

    const bool many = s.points.size() > 64;
    double wmax = 0;
    for (const auto& smp : s.samples) wmax = std::max(wmax, smp.weight);
    for (std::size_t k = 0; k < s.points.size(); ++k) {
        const dvec2 p = dvec2(x0, y0) + s.points[k].p;
        if (int(k) > s.k) {
            scene.points.push_back({p, "", {Role::Subject}, many ? 2.0f : 3.0f});
            continue;
        }
        const Sample& smp = s.samples[k];
        const bool current = int(k) == s.k && s.last == Phase::Sample;
        const float radius = (many ? 2.0f : 3.0f) +
                             (many ? 2.0f : 4.0f) * float(smp.weight / std::max(wmax, 1e-300));
        const Role role = current ? Role::Active : smp.value > 0 ? Role::Kept : Role::Discarded;
        scene.points.push_back({p, current ? std::to_string(k + 1) : "", {role}, radius});
    }
    if (s.last == Phase::Sample && in.pattern == Pattern::Poisson) {  // the exclusion circle
        const dvec2 c = s.samples[s.k].p;
        std::vector<dvec2> circle;
        for (int a = 0; a < 48; ++a)
            circle.push_back(c +
                             s.radius * dvec2(std::cos(a * M_PI / 24), std::sin(a * M_PI / 24)));
        scene.polygons.push_back({std::move(circle), {Role::Active, 1.0f, true}, true, false});
    }
    if (s.phase >= Phase::Exact) {
        std::string t = "estimate " + num(s.estimate, 4);
        if (s.phase == Phase::Done)
            t += ", exact " + num(s.exact, 4) + ", error " + num(s.estimate - s.exact, 3);
        scene.labels.push_back({{x0 + 0.02, y0 + 1.06}, t, {Role::Neutral}});
    }
}

}  // namespace cg
