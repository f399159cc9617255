// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and supersample] [study]
// (the convergence study: its experiment, validation and steps); the pictures are in
// supersampling_draw.cpp.
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
    kLineStudyPoint,
    kLineStudySlopes,
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
    if (!std::isfinite(v))
        throw InputError(field, "must be a finite number (got " + given(v) + ")");
    if (std::fabs(v) > Supersampling::kMaxCoordinate)
        throw InputError(field, "must be within ±10⁶ pixels (got " + given(v) + ")");
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
            "study: for each pattern, each N:  e ← √(mean over the edges of error²)",
            "slope ← least squares of log e against log N, over N ≥ 4",
        },
        {
            {"pattern", "the sample positions in the pixel, and how the pattern made them"},
            {"inside", "a sample inside the scene: value 1, and its weight"},
            {"outside", "a sample outside the scene: value 0, and its weight"},
            {"estimate", "the filtered average of the samples, Σ w v / Σ w"},
            {"exact", "area sampling: the covered part of the pixel, its weighted area, the error"},
            {"point", "a study: one pattern's RMS error at one N, over all the edges"},
            {"slopes", "a study: each pattern's slope of log error against log N"},
        },
        {},  // no sliders
        {
            .predict =
                {
                    {"inside", {}},
                    {"outside", {}},
                    {"estimate", {"estimate"}},
                    {"exact", {"error"}},
                },
            .mistakes =
                {
                    {"inside", "sum_wv", "keep", "forgot to add the covered sample's weight"},
                    {"inside", "sum_w", "keep", "forgot to add w_k to the weight sum"},
                    {"outside", "", "event:inside",
                     "counted a sample outside the shape as covered"},
                },
            .variants =
                {
                    {"regular", "/pattern", "\"regular\""},
                    {"random", "/pattern", "\"random\""},
                    {"jittered", "/pattern", "\"jittered\""},
                    {"poisson", "/pattern", "\"poisson\""},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Supersampling::validate(const Input& in) {
    if (in.is_study) return validate_study(in);
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
        throw InputError("radius", "must be between 0 and 2 pixels (got " + given(in.radius) + ")");
    check_coordinate(in.i, "pixel[0]");
    check_coordinate(in.j, "pixel[1]");
    const sampling::Region& r = in.scene;
    if (r.kind == RegionKind::Edge) {
        check_coordinate(r.point.x, "scene.point[0]");
        check_coordinate(r.point.y, "scene.point[1]");
        if (!std::isfinite(r.angle_deg))
            throw InputError("scene.angle",
                             "must be a finite number (got " + given(r.angle_deg) + ")");
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
    if (in.is_study) {
        s.phase = s.last = Phase::Point;
        std::vector<StudyPoint> measured;
        measured.reserve(in.study.patterns.size() * in.study.samples.size());
        for (Pattern p : in.study.patterns)
            for (int n : in.study.samples) measured.push_back({p, n, study_rms(in, p, n)});
        s.study.reserve(measured.size());
        s.measured = Shared<std::vector<StudyPoint>>(std::move(measured));
    }
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
        case Phase::Point:
        case Phase::Slopes:
            return advance_study(s);
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
    if (s.in->is_study) return narrate_study(s, info);
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
        case Phase::Point:
        case Phase::Slopes:
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
    r.study = s.study;
    r.slopes = s.slopes;
    r.is_study = s.in->is_study;
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

// ---- [study] --------------------------------------------------------------------------------

Supersampling::Input Supersampling::study_trial(const Input& in, Pattern pattern, int samples,
                                                int t) {
    Rng rng(50000 + static_cast<std::uint64_t>(t));
    const double angle = in.study.near_axis ? rng.uniform(-1, 1) : rng.uniform(0, 360);
    Input trial;
    trial.pattern = pattern;
    trial.samples = samples;
    trial.filter = in.filter;
    trial.scene.kind = RegionKind::Edge;
    trial.scene.point.x = rng.uniform(0, 1);
    trial.scene.point.y = rng.uniform(0, 1);
    trial.scene.angle_deg = angle;
    trial.seed = in.seed * kMaxStudyEdges + static_cast<std::uint64_t>(t);
    return trial;
}

double Supersampling::study_rms(const Input& in, Pattern pattern, int samples) {
    double sum = 0;
    for (int t = 0; t < in.study.edges; ++t) {
        const double e = supersample(study_trial(in, pattern, samples, t)).error;
        sum += e * e;
    }
    return std::sqrt(sum / in.study.edges);
}

double Supersampling::study_slope(const std::vector<StudyPoint>& points, Pattern pattern) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const StudyPoint& q : points) {
        if (q.pattern != pattern || q.samples < 4) continue;
        const double x = std::log10(double(q.samples));
        const double y = std::log10(std::max(q.rms_error, 1e-15));  // an exact 0 stays finite
        n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double d = n * sxx - sx * sx;
    return n < 2 || d <= 0 ? 0.0 : (n * sxy - sx * sy) / d;
}

Supersampling::Result Supersampling::run_study(const Input& in) {
    Result r;
    r.is_study = true;
    for (Pattern p : in.study.patterns)
        for (int n : in.study.samples) r.study.push_back({p, n, study_rms(in, p, n)});
    for (Pattern p : in.study.patterns) r.slopes.push_back({p, study_slope(r.study, p)});
    return r;
}

void Supersampling::validate_study(const Input& in) {
    const Study& st = in.study;
    if (st.patterns.empty())
        throw InputError("study.patterns", "must list at least one pattern (got none)");
    for (std::size_t a = 0; a < st.patterns.size(); ++a)
        for (std::size_t b = 0; b < a; ++b)
            if (st.patterns[a] == st.patterns[b])
                throw InputError(
                    "study.patterns[" + std::to_string(a) + "]",
                    std::string("repeats \"") + sampling::pattern_id(st.patterns[a]) + "\"");
    const std::size_t m = st.samples.size();
    if (m < 2 || m > std::size_t(kMaxStudyCounts))
        throw InputError("study.samples", "must list between 2 and " +
                                              std::to_string(kMaxStudyCounts) +
                                              " sample counts (got " + std::to_string(m) + ")");
    int large = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const int n = st.samples[k];
        const std::string field = "study.samples[" + std::to_string(k) + "]";
        if (n < 1 || n > kMaxStudySamples)
            throw InputError(field, "must be between 1 and " + std::to_string(kMaxStudySamples) +
                                        " (got " + std::to_string(n) + ")");
        for (Pattern p : st.patterns)
            if (sampling::is_grid(p) && sampling::grid_side(n) == 0)
                throw InputError(
                    field, std::string("must be a square number n × n (1, 4, 9, 16, …) for "
                                       "the ") +
                               sampling::pattern_id(p) + " pattern (got " + std::to_string(n) +
                               ")");
        if (k > 0 && n <= st.samples[k - 1])
            throw InputError(field, "must be larger than the count before it (got " +
                                        std::to_string(n) + " after " +
                                        std::to_string(st.samples[k - 1]) + ")");
        large += n >= 4;
    }
    if (large < 2)
        throw InputError("study.samples",
                         "must hold at least two counts of 4 or more, to fit a slope (got " +
                             std::to_string(large) + ")");
    if (st.edges < 1 || st.edges > kMaxStudyEdges)
        throw InputError("study.edges", "must be between 1 and " + std::to_string(kMaxStudyEdges) +
                                            " (got " + std::to_string(st.edges) + ")");
    long long sum = 0;
    for (int n : st.samples) sum += n;
    if (st.edges * sum > kMaxStudyWork)
        throw InputError("study.edges", "times the sample counts' sum (" + std::to_string(sum) +
                                            ") must be at most " + std::to_string(kMaxStudyWork) +
                                            ", so that a run stays short (got " +
                                            std::to_string(st.edges) + " × " + std::to_string(sum) +
                                            " = " + std::to_string(st.edges * sum) + ")");
}

void Supersampling::advance_study(State& s) {
    const Study& st = s.in->study;
    s.last = s.phase;
    if (s.phase == Phase::Point) {  // One point: a pattern's RMS error at one N
        s.study.push_back((*s.measured)[s.study.size()]);
        if (s.study.size() == st.patterns.size() * st.samples.size()) s.phase = Phase::Slopes;
    } else if (s.phase == Phase::Slopes) {  // The slopes, fitted
        for (Pattern p : st.patterns) s.slopes.push_back({p, study_slope(s.study, p)});
        s.phase = Phase::Done;
    }
}

namespace {

std::string angles_text(const Supersampling::Study& st) {
    return st.near_axis ? "within 1° of the x axis" : "at any angle";
}

// What each pattern's slope means.
std::string slope_meaning(Pattern p, bool near_axis) {
    switch (p) {
        case Pattern::Random:
            return "the mean of N independent coin flips, so about −½";
        case Pattern::Jittered:
            return "only the cells the edge crosses (about √N of them) are uncertain, so about −¾";
        case Pattern::Poisson:
            return "evenly spread like jittered but not stratified, so between −½ and −¾";
        case Pattern::Regular:
            return near_axis ? "on edges nearly along its rows a whole row of samples flips at "
                               "once, so only about −½, and the error is the same for every "
                               "seed: structured, not noise"
                             : "the edge's random angle breaks the alignment with its rows, so "
                               "about as steep as jittered; still each edge's error is fixed, "
                               "the same for every seed";
    }
    return "";
}

}  // namespace

void Supersampling::narrate_study(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Study& st = in.study;
    const std::string edges = std::to_string(st.edges) + " edges " + angles_text(st);
    if (s.last == Phase::Point) {
        const StudyPoint& q = s.study.back();
        const std::string name = sampling::pattern_id(q.pattern);
        info.event = "point";
        info.line = kLineStudyPoint;
        info.narration = name + ", N = " + std::to_string(q.samples) + ": RMS error " +
                         num(q.rms_error, 3) + " over " + edges + " (" +
                         sampling::filter_id(in.filter) + " filter, pixel (0, 0))";
        info.vars = {{"pattern", name},
                     {"N", static_cast<long long>(q.samples)},
                     {"edges", static_cast<long long>(st.edges)},
                     {"rms_error", q.rms_error}};
        const std::size_t k = s.study.size() - 1;
        if (k % st.samples.size() != 0) {  // the step from the previous N of this pattern
            const StudyPoint& prev = s.study[k - 1];
            const double local =
                std::log10(std::max(q.rms_error, 1e-15) / std::max(prev.rms_error, 1e-15)) /
                std::log10(double(q.samples) / prev.samples);
            info.narration += "; from N = " + std::to_string(prev.samples) + " it fell ×" +
                              num(q.rms_error / std::max(prev.rms_error, 1e-300), 3) +
                              ", a slope of " + num(local, 3) + " on this stretch";
            info.vars.push_back({"local_slope", local});
        }
        info.narration += ".";
        info.math = "e_{" + tex(q.samples) + "} = \\sqrt{\\tfrac{1}{" + tex(st.edges) +
                    "}\\sum (\\hat I - I)^2} = " + tex(q.rms_error, 3);
        return;
    }
    info.event = "slopes";
    info.line = kLineStudySlopes;
    std::string t = "Slopes of log error against log N, least squares over N ≥ 4, " + edges + ":";
    info.vars.clear();
    for (const Slope& sl : s.slopes) {
        const std::string name = sampling::pattern_id(sl.pattern);
        t += " " + name + " " + num(sl.slope, 2) + " — " + slope_meaning(sl.pattern, st.near_axis) +
             ";";
        info.vars.push_back({"slope_" + name, sl.slope});
    }
    t.back() = '.';
    info.narration = t;
    info.math = "e \\propto N^{s}:\\; s = \\frac{\\Delta \\log e}{\\Delta \\log N}";
}

}  // namespace cg
