// Sections: [spec] [table and integral] [start] [advance] [narrate] [step and result] [draw].
#include "curves/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "curves/bezier.hpp"

namespace cg {

namespace {

using curves::point_name;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineFirst = 1,
    kLineLoop,
    kLineSample,
    kLineLength,
    kLineQueries,
    kLineBracket,
    kLineInterpolate,
};

std::string pt(glm::dvec3 p, int dim) {
    return dim == 3 ? num(p) : num(curves::xy(p));
}
std::vector<double> coords(glm::dvec3 p, int dim) {
    return dim == 3 ? vec(p) : std::vector<double>{p.x, p.y};
}

// |P'(u)| in long double: the derivative curve n Σ (P_{i+1} − P_i) B_i^{n−1}(u), by de Casteljau.
long double speed(const std::vector<glm::dvec3>& p, long double u) {
    const std::size_t n = p.size() - 1;
    std::array<std::array<long double, 3>, curves::kMaxDegree> d;
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            d[i][static_cast<std::size_t>(c)] = static_cast<long double>(p[i + 1][c]) - p[i][c];
    for (std::size_t k = 1; k < n; ++k)
        for (std::size_t i = 0; i + k < n; ++i)
            for (std::size_t c = 0; c < 3; ++c) d[i][c] = (1 - u) * d[i][c] + u * d[i + 1][c];
    const long double x = d[0][0], y = d[0][1], z = d[0][2];
    return static_cast<long double>(n) * std::sqrt(x * x + y * y + z * z);
}

struct Simpson {
    const std::vector<glm::dvec3>& p;
    long double tolerance;

    // One panel [a, b] with f at a, the midpoint and b; recursive halving until Richardson's
    // estimate of the error is under the panel's share of the tolerance.
    long double integrate(long double a, long double b, long double fa, long double fm,
                          long double fb, long double whole, long double tol, int depth) const {
        const long double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
        const long double flm = speed(p, lm), frm = speed(p, rm);
        const long double left = (m - a) / 6 * (fa + 4 * flm + fm),
                          right = (b - m) / 6 * (fm + 4 * frm + fb);
        const long double delta = left + right - whole;
        if (depth <= 0 || std::fabs(delta) <= 15 * tol) return left + right + delta / 15;
        return integrate(a, m, fa, flm, fm, left, tol / 2, depth - 1) +
               integrate(m, b, fm, frm, fb, right, tol / 2, depth - 1);
    }
};

}  // namespace

// --- [spec] -------------------------------------------------------------------------------------

const Spec& ArcLength::spec() {
    static const Spec spec{
        "arc-length",
        "Arc-length parameterisation by a chord-length table",
        "Animation",
        {
            "u_0 ← 0,  s_0 ← 0",
            "for j = 1 .. N:",
            "    u_j ← j / N,   s_j ← s_{j−1} + |P(u_j) − P(u_{j−1})|",
            "L ← s_N                              ▷ a little under ∫|P′(u)| du",
            "for each distance s (or s ← f L):",
            "    find j with s_j ≤ s ≤ s_{j+1}",
            "    u ← u_j + (s − s_j) / (s_{j+1} − s_j) · (u_{j+1} − u_j);  the point is P(u)",
        },
        {
            {"sample", "one row of the table: the next sample and the distance to it"},
            {"length", "the table's total length, against the true arc length"},
            {"query", "a distance turned into a parameter by interpolating in the table"},
        },
        {},  // no sliders
        {
            .predict = {{"sample", {"s_j"}}, {"length", {"L"}}, {"query", {"j", "u"}}},
            .mistakes = {
                {"sample", "s_j", "copy:chord", "stored each chord instead of the running sum"},
                {"query", "u", "copy:s / L", "took u = s / L, as if the speed were uniform"},
                {"query", "j", "off-by-one", "interpolated in the next interval of the table"},
            },
        },
    };
    return spec;
}

// --- [table and integral] -----------------------------------------------------------------------

double ArcLength::table_length(const std::vector<glm::dvec3>& control_points, int samples) {
    double length = 0;
    glm::dvec3 previous = control_points.front();
    for (int j = 1; j <= samples; ++j) {
        const glm::dvec3 p = curves::bezier_point(control_points, static_cast<double>(j) / samples);
        length += glm::length(p - previous);
        previous = p;
    }
    return length;
}

double ArcLength::exact_length(const std::vector<glm::dvec3>& p) {
    // 16 panels first, so that no feature hides between the first few samples; the tolerance
    // is relative to the control polygon's length (an upper bound of the arc length).
    long double polygon = 0;
    for (std::size_t i = 1; i < p.size(); ++i) polygon += glm::length(p[i] - p[i - 1]);
    if (polygon == 0) return 0;
    const Simpson simpson{p, 1e-14L * polygon};
    long double total = 0;
    constexpr int kPanels = 16;
    for (int k = 0; k < kPanels; ++k) {
        const long double a = static_cast<long double>(k) / kPanels,
                          b = static_cast<long double>(k + 1) / kPanels;
        const long double fa = speed(p, a), fm = speed(p, (a + b) / 2), fb = speed(p, b);
        total += simpson.integrate(a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb),
                                   simpson.tolerance / kPanels, 40);
    }
    return static_cast<double>(total);
}

ArcLength::Query ArcLength::invert(const std::vector<double>& u, const std::vector<double>& s,
                                   double distance) {
    Query q;
    q.s = distance;
    // The first entry reaching the distance: s_{j+1} ≥ s > s_j, so that interval has length.
    const auto it = std::lower_bound(s.begin(), s.end(), distance);
    if (it == s.begin() || it == s.end()) {  // s ≤ s_0 = 0 (or past the end: the last entry)
        q.bracket = it == s.begin() ? 0 : static_cast<int>(s.size()) - 2;
        q.u = it == s.begin() ? u.front() : u.back();
        return q;
    }
    const std::size_t j = static_cast<std::size_t>(it - s.begin()) - 1;
    q.bracket = static_cast<int>(j);
    q.u = u[j] + (distance - s[j]) / (s[j + 1] - s[j]) * (u[j + 1] - u[j]);
    return q;
}

// --- [start] ------------------------------------------------------------------------------------

void ArcLength::validate(const Input& in) {
    curves::validate_points(in.control_points, in.dim, "control_points", 2);
    if (in.samples < 1 || in.samples > kMaxSamples)
        throw InputError("samples",
                         "must be between 1 and 10000 (got " + std::to_string(in.samples) + ")");
    if (!in.distances.empty() && !in.fractions.empty())
        throw InputError("fractions", "give distances or fractions, not both");
    for (std::size_t i = 0; i < in.fractions.size(); ++i) {
        const double f = in.fractions[i];
        const std::string field = "fractions[" + std::to_string(i) + "]";
        if (!std::isfinite(f))
            throw InputError(field, "must be a finite number (got " + given(f) + ")");
        if (f < 0 || f > 1) throw InputError(field, "must lie in [0, 1] (got " + given(f) + ")");
    }
    if (in.distances.empty()) return;
    const double length = table_length(in.control_points, in.samples);
    for (std::size_t i = 0; i < in.distances.size(); ++i) {
        const double d = in.distances[i];
        const std::string field = "distances[" + std::to_string(i) + "]";
        if (!std::isfinite(d))
            throw InputError(field, "must be a finite number (got " + given(d) + ")");
        if (d < 0 || d > length)
            throw InputError(field,
                             "must lie in [0, " + given(length) + "], the length of the table with " +
                                 std::to_string(in.samples) + " samples (got " + given(d) + ")");
    }
}

ArcLength::State ArcLength::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    s.u.reserve(static_cast<std::size_t>(in.samples) + 1);
    s.s.reserve(static_cast<std::size_t>(in.samples) + 1);
    s.points.reserve(static_cast<std::size_t>(in.samples) + 1);
    return s;
}

// --- [advance] ----------------------------------------------------------------------------------

// The algorithm proper: one step of the math.
void ArcLength::advance(State& s) {
    const int n = s.in.samples;
    s.taken = s.phase;
    switch (s.phase) {
        case Phase::Sample: {  // One more row of the table
            const int j = ++s.j;
            const double u = j == n ? 1.0 : static_cast<double>(j) / n;
            const glm::dvec3 p = curves::bezier_point(s.in.control_points, u);
            s.u.push_back(u);
            s.s.push_back(j == 0 ? 0.0 : s.s.back() + glm::length(p - s.points.back()));
            s.points.push_back(p);
            if (j == n) s.phase = Phase::Length;
            return;
        }
        case Phase::Length:  // The table's total, and the accurate integral for comparison
            s.length = s.s.back();
            s.length_exact = exact_length(s.in.control_points);
            s.phase = s.in.distances.empty() && s.in.fractions.empty() ? Phase::Done : Phase::Query;
            return;
        case Phase::Query: {  // Invert the table at one distance
            const std::size_t k = s.queries.size();
            const bool by_fraction = !s.in.fractions.empty();
            // A fraction of 1 is the end exactly (f L might round past s_N).
            const double distance =
                by_fraction ? (s.in.fractions[k] == 1 ? s.length : s.in.fractions[k] * s.length)
                            : s.in.distances[k];
            Query q = invert(s.u, s.s, distance);
            q.point = curves::bezier_point(s.in.control_points, q.u);
            s.queries.push_back(q);
            const std::size_t total = by_fraction ? s.in.fractions.size() : s.in.distances.size();
            if (s.queries.size() == total) s.phase = Phase::Done;
            return;
        }
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// --- [narrate] ----------------------------------------------------------------------------------

// What the step just taken means, told with its numbers. `s` is the state after the step.
void ArcLength::narrate(const State& s, StepInfo& info) {
    const int dim = s.in.dim;
    if (s.taken == Phase::Sample) {
        const int j = s.j;
        const std::size_t k = static_cast<std::size_t>(j);
        const std::string J = std::to_string(j);
        info.event = "sample";
        info.vars = {{"j", static_cast<long long>(j)},
                     {"u_j", s.u[k]},
                     {"P(u_j)", coords(s.points[k], dim)},
                     {"s_j", s.s[k]}};
        if (j == 0) {
            info.line = kLineFirst;
            info.narration = "The table starts at u₀ = 0, the curve's first point P(0) = P₀ = " +
                             pt(s.points[0], dim) + ", with s₀ = 0.";
            info.math = "u_0 = 0,\\quad P(0) = " +
                        (dim == 3 ? tex(s.points[0]) : tex(curves::xy(s.points[0]))) +
                        ",\\quad s_0 = 0";
            return;
        }
        const double chord = s.s[k] - s.s[k - 1];
        const std::string sj = "s" + curves::subscript(j), sp = "s" + curves::subscript(j - 1);
        info.line = kLineSample;
        info.narration = "u" + curves::subscript(j) + " = " + num(s.u[k]) + ": P(u" +
                         curves::subscript(j) + ") = " + pt(s.points[k], dim) + ", " + num(chord) +
                         " from the previous sample, so " + sj + " = " + num(s.s[k - 1]) + " + " +
                         num(chord) + " = " + num(s.s[k]) + ".";
        const auto tp = [&](glm::dvec3 p) { return dim == 3 ? tex(p) : tex(curves::xy(p)); };
        info.math = "u_{" + J + "} = " + tex(s.u[k]) + ",\\quad P(u_{" + J +
                    "}) = " + tp(s.points[k]) + ",\\quad s_{" + J + "} = s_{" +
                    std::to_string(j - 1) + "} + |P(u_{" + J + "}) - P(u_{" +
                    std::to_string(j - 1) + "})| = " + tex(s.s[k - 1]) + " + " + tex(chord) +
                    " = " + tex(s.s[k]);
        info.vars.push_back({"chord", chord});
        return;
    }
    if (s.taken == Phase::Length) {
        const double error = s.length - s.length_exact;
        info.event = "length";
        info.line = kLineLength;
        const std::string head = "The table's length is L = s" + curves::subscript(s.in.samples) +
                                 " = " + num(s.length) + "; integrating |P′(u)| accurately gives " +
                                 num(s.length_exact, 10);
        if (std::fabs(error) <= 1e-12 * s.length_exact)
            info.narration =
                head + ", the same to rounding: the chords are exact because the path is straight.";
        else
            info.narration = head + ", so the " + std::to_string(s.in.samples) +
                             " chords fall short by " + num(-error, 3) + " (" +
                             num(-100 * error / s.length_exact, 3) +
                             "%). More samples shrink the gap roughly with 1/N².";
        info.math = "L = s_{" + std::to_string(s.in.samples) + "} = " + tex(s.length) +
                    ",\\quad L^* = \\int_0^1 |P'(u)|\\,du = " + tex(s.length_exact, 10) +
                    ",\\quad L - L^* = " + tex(error, 3);
        info.vars = {{"L", s.length}, {"L*", s.length_exact}, {"L − L*", error}};
        return;
    }
    const std::size_t k = s.queries.size() - 1;
    const Query& q = s.queries.back();
    const std::size_t j = static_cast<std::size_t>(q.bracket);
    const bool by_fraction = !s.in.fractions.empty();
    const double naive = s.length > 0 ? q.s / s.length : 0;
    info.event = "query";
    info.line = kLineInterpolate;
    std::string head =
        by_fraction ? "f = " + num(s.in.fractions[k]) + " of the length: s = " + num(q.s) + ". "
                    : "s = " + num(q.s) + ". ";
    const std::string J = curves::subscript(static_cast<int>(j)),
                      J1 = curves::subscript(static_cast<int>(j) + 1);
    std::string tail = " P(u) = " + pt(q.point, dim) +
                       " (equal steps of u would have used u = s/L = " + num(naive) + ").";
    if (s.length == 0) {
        info.narration = head + "The curve has no length: every distance is 0, at u = 0." + tail;
        info.math = "u = 0";
    } else if (q.s <= s.s[0]) {
        info.narration = head + "The start of the table: u = 0." + tail;
        info.math = "s = 0 \\Rightarrow u = 0";
    } else {
        info.narration = head + "It lies between s" + J + " = " + num(s.s[j]) +
                         " (u = " + num(s.u[j]) + ") and s" + J1 + " = " + num(s.s[j + 1]) +
                         " (u = " + num(s.u[j + 1]) + "), so u = " + num(s.u[j]) + " + (" +
                         num(q.s) + " − " + num(s.s[j]) + ")/(" + num(s.s[j + 1]) + " − " +
                         num(s.s[j]) + ")·" + num(s.u[j + 1] - s.u[j]) + " = " + num(q.u) + "." +
                         tail;
        const std::string a = std::to_string(j), b = std::to_string(j + 1);
        info.math = "s_{" + a + "} = " + tex(s.s[j]) + " \\le " + tex(q.s) + " \\le s_{" + b +
                    "} = " + tex(s.s[j + 1]) + ",\\quad u = " + tex(s.u[j]) + " + \\frac{" +
                    tex(q.s) + " - " + tex(s.s[j]) + "}{" + tex(s.s[j + 1]) + " - " + tex(s.s[j]) +
                    "} \\cdot " + tex(s.u[j + 1] - s.u[j]) + " = " + tex(q.u);
    }
    info.vars = {{"s", q.s},      {"j", static_cast<long long>(j)},
                 {"s_j", s.s[j]}, {"s_j+1", s.s[std::min(j + 1, s.s.size() - 1)]},
                 {"u", q.u},      {"P(u)", coords(q.point, dim)},
                 {"s / L", naive}};
}

// --- [step and result] --------------------------------------------------------------------------

void ArcLength::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

ArcLength::Result ArcLength::result(const State& s) {
    Result r;
    r.dim = s.in.dim;
    r.u = s.u;
    r.s = s.s;
    r.length = s.length;
    r.length_exact = s.length_exact;
    r.length_error = s.length - s.length_exact;
    r.queries = s.queries;
    return r;
}

// --- [draw] -------------------------------------------------------------------------------------

void ArcLength::draw(const State& s, Scene& scene) {
    const auto& control = s.in.control_points;
    const int n = static_cast<int>(control.size()) - 1;
    const bool measured =
        s.phase == Phase::Query || s.phase == Phase::Done;  // (the length is known)

    std::vector<glm::dvec2> polygon;
    for (const glm::dvec3& p : control) polygon.push_back(curves::xy(p));
    scene.polygons.push_back(
        {curves::bezier_polyline(control, 0, 1, 200), {Role::Construction, 3.5f}, false, false});
    scene.polygons.push_back({polygon, {Role::Subject, 1.0f, true}, false, false});

    // The table's chords so far, and the samples (every one labelled when there are few).
    std::vector<glm::dvec2> chords;
    for (const glm::dvec3& p : s.points) chords.push_back(curves::xy(p));
    if (chords.size() > 1)
        scene.polygons.push_back(
            {chords, {Role::Neutral, 1.5f, false, curves::shade(1)}, false, false});
    const bool sampling = s.taken == Phase::Sample;
    if (sampling && s.j >= 1) {
        const std::size_t j = static_cast<std::size_t>(s.j);
        scene.segments.push_back({chords[j - 1], chords[j], "", {Role::Active, 3.0f}, false});
    }
    const bool few = s.in.samples <= 12;
    for (std::size_t j = 0; j < chords.size(); ++j) {
        const bool newest = sampling && static_cast<int>(j) == s.j;
        if (!few && !newest &&
            j % std::max<std::size_t>(1, static_cast<std::size_t>(s.in.samples) / 50) != 0)
            continue;
        const std::string label =
            newest ? "s" + curves::subscript(static_cast<int>(j)) + " = " + num(s.s[j], 4)
            : few && !measured ? "u = " + num(s.u[j], 3)
                               : "";
        scene.points.push_back(
            {chords[j],
             label,
             {newest ? Role::Active : Role::Neutral, 1.5f, false, newest ? 0u : curves::shade(1)},
             newest     ? 5.0f
             : measured ? 2.5f
                        : 3.5f});
    }

    // Queries: the point at distance s (green) against the point at u = s/L (red). At the end
    // the first pair names the two kinds.
    const bool finished = s.phase == Phase::Done;
    for (std::size_t k = 0; k < s.queries.size(); ++k) {
        const Query& q = s.queries[k];
        const bool newest = k + 1 == s.queries.size() && !finished;
        const glm::dvec2 naive =
            curves::xy(curves::bezier_point(control, s.length > 0 ? q.s / s.length : 0));
        const glm::dvec2 corrected = curves::xy(q.point);
        const bool legend = finished && k == 0;
        scene.points.push_back({naive,
                                newest   ? "u = s/L"
                                : legend ? "u = s/L (naive)"
                                         : "",
                                {Role::Discarded},
                                4.0f});
        std::string label =
            newest || (s.queries.size() <= 6 && !legend) ? "s = " + num(q.s, 4) : "";
        if (legend) label = "distance s (corrected)";
        scene.points.push_back({corrected, label, {Role::Kept}, newest ? 6.0f : 5.0f});
        if (newest && q.bracket + 1 < static_cast<int>(chords.size())) {
            const std::size_t j = static_cast<std::size_t>(q.bracket);
            scene.segments.push_back({chords[j], chords[j + 1], "", {Role::Active, 3.0f}, false});
            scene.points.push_back({chords[j],
                                    "s" + curves::subscript(q.bracket) + " = " + num(s.s[j], 4),
                                    {Role::Active},
                                    4.0f});
            scene.points.push_back(
                {chords[j + 1],
                 "s" + curves::subscript(q.bracket + 1) + " = " + num(s.s[j + 1], 4),
                 {Role::Active},
                 4.0f});
        }
    }

    for (int i = 0; i <= n; ++i) {
        const std::string base = "/control_points/" + std::to_string(i) + "/";
        scene.points.push_back(
            {polygon[static_cast<std::size_t>(i)], point_name(i), {Role::Subject}, 3.5f});
        scene.handles.push_back(
            {polygon[static_cast<std::size_t>(i)], point_name(i), base + "0", base + "1"});
    }
    if (s.in.dim == 3) {
        glm::dvec2 lo = polygon[0];
        for (glm::dvec2 p : polygon) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        scene.labels.push_back({lo, "3D points drawn as (x, y): z is dropped", {Role::Neutral}});
    }
}

}  // namespace cg
