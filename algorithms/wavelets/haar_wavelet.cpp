// Sections: [transform] [compression] [patterns] [spec] [validate] [advance] [narrate]
//           [result and compute]; the picture is in haar_wavelet_draw.cpp
#include "wavelets/haar_wavelet.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = HaarWavelet::Input;
using Mode = HaarWavelet::Mode;
using Compress = HaarWavelet::Compress;
using Pass = HaarWavelet::Pass;
using Phase = HaarWavelet::Phase;
using State = HaarWavelet::State;

constexpr double kInvSqrt2 = 0.70710678118654752440;

enum Line {
    kLineStart = 1,
    kLineLevel,
    kLineStore,
    kLineStandard,
    kLineNonStandard,
    kLineCompress,
    kLineReconstruct,
    kLineReport
};

int log2_of(int n) {  // n a power of two
    int l = 0;
    while ((1 << l) < n) ++l;
    return l;
}

bool two_d(const Input& in) {
    return in.mode != Mode::OneD;
}

// ---- [transform] ----------------------------------------------------------------------------

// One averaging/differencing level on x[0 … m): averages first, then the details.
void forward_level(double* x, int m, double h, double* t) {
    const int half = m / 2;
    for (int k = 0; k < half; ++k) {
        const double a = x[2 * k] * h, b = x[2 * k + 1] * h;  // a/2 + b/2: no overflow
        t[k] = a + b;
        t[half + k] = a - b;
    }
    std::copy(t, t + m, x);
}

// Its inverse: x_2k = s_k + d_k, x_2k+1 = s_k − d_k (times g = 1, or 1/√2 normalised).
void inverse_level(double* x, int m, double g, double* t) {
    const int half = m / 2;
    for (int k = 0; k < half; ++k) {
        const double s = x[k] * g, d = x[half + k] * g;
        t[2 * k] = s + d;
        t[2 * k + 1] = s - d;
    }
    std::copy(t, t + m, x);
}

}  // namespace

std::vector<HaarWavelet::Pass> HaarWavelet::plan(const Input& in) {
    std::vector<Pass> f;
    const int n = in.n;
    if (n < 2) return f;
    if (in.mode == Mode::OneD) {
        for (int m = n; m >= 2; m /= 2) f.push_back({false, true, 0, 1, m, 1});
    } else if (in.mode == Mode::Standard) {
        const int g = std::max(1, n / kMaxGroups), L = log2_of(n);
        for (int dir = 0; dir < 2; ++dir)
            for (int first = 0; first < n; first += g)
                f.push_back({false, dir == 0, first, g, n, L});
    } else {
        for (int m = n; m >= 2; m /= 2) {
            f.push_back({false, true, 0, m, m, 1});
            f.push_back({false, false, 0, m, m, 1});
        }
    }
    // The reconstruction undoes the passes in reverse order.
    std::vector<Pass> all = f;
    for (auto it = f.rbegin(); it != f.rend(); ++it) {
        Pass p = *it;
        p.inverse = true;
        all.push_back(p);
    }
    return all;
}

void HaarWavelet::apply(const Input& in, const Pass& p, std::vector<double>& c) {
    const int n = in.n;
    const double h = in.normalised ? kInvSqrt2 : 0.5;
    const double g = in.normalised ? kInvSqrt2 : 1.0;
    std::vector<double> line(std::size_t(p.len)), tmp(std::size_t(p.len));
    for (int l = p.first; l < p.first + p.count; ++l) {
        // A row is contiguous; a column is gathered (stride n) and scattered back.
        double* x = nullptr;
        if (p.rows) {
            x = c.data() + std::size_t(l) * (two_d(in) ? n : 0);
        } else {
            for (int j = 0; j < p.len; ++j) line[j] = c[std::size_t(j) * n + l];
            x = line.data();
        }
        if (!p.inverse) {
            int m = p.len;
            for (int k = 0; k < p.levels; ++k, m /= 2) forward_level(x, m, h, tmp.data());
        } else {
            int m = p.len >> (p.levels - 1);
            for (int k = 0; k < p.levels; ++k, m *= 2) inverse_level(x, m, g, tmp.data());
        }
        if (!p.rows)
            for (int j = 0; j < p.len; ++j) c[std::size_t(j) * n + l] = line[j];
    }
}

std::vector<double> HaarWavelet::before_pass(const State& s, int p) {
    std::vector<double> b = s.c;
    Pass q = (*s.passes)[p];
    q.inverse = !q.inverse;
    apply(*s.in, q, b);
    return b;
}

// ---- [compression] --------------------------------------------------------------------------

double HaarWavelet::norm(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::fabs(x));
    if (m == 0) return 0;
    double sum = 0;
    for (double x : v) sum += (x / m) * (x / m);
    return m * std::sqrt(sum);
}

namespace {
// The samples a coefficient's basis function spans along one line: the average and the
// coarsest detail all n, a detail at index i in [2^j, 2^j+1) n / 2^j.
int support(int n, int i) {
    return i == 0 ? n : n >> (31 - __builtin_clz(unsigned(i)));
}
}  // namespace

double HaarWavelet::weight(const Input& in, std::size_t at) {
    if (in.normalised) return 1;
    const int n = in.n;
    if (in.mode == Mode::OneD) return support(n, int(at));
    const int r = int(at / std::size_t(n)), c = int(at % std::size_t(n));
    if (in.mode == Mode::Standard) return double(support(n, r)) * support(n, c);
    const int s = std::min(support(n, r), support(n, c));  // both directions at one scale
    return double(s) * s;
}

double HaarWavelet::compress(const Input& in, std::vector<double>& c, long long& zeroed,
                             long long& kept, double& cut) {
    std::vector<double> dropped;  // √w c of each dropped coefficient
    auto drop = [&](std::size_t i) {
        if (c[i] == 0) return;
        dropped.push_back(std::sqrt(weight(in, i)) * c[i]);
        c[i] = 0;
    };
    if (in.compress == Compress::Threshold) {
        cut = in.threshold;
        for (std::size_t i = 1; i < c.size(); ++i)
            if (std::fabs(c[i]) < in.threshold) drop(i);
    } else if (in.compress == Compress::Keep) {
        const double total = double(c.size());
        const auto k = std::size_t(std::clamp(std::ceil(in.keep * total - 1e-9), 1.0, total));
        std::vector<std::size_t> order(c.size() - 1);
        std::iota(order.begin(), order.end(), std::size_t(1));
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return std::fabs(c[a]) > std::fabs(c[b]);
        });
        cut = k >= 2 ? std::fabs(c[order[k - 2]]) : 0;
        for (std::size_t q = k - 1; q < order.size(); ++q) drop(order[q]);
    }
    zeroed = (long long)dropped.size();
    kept = (long long)std::count_if(c.begin(), c.end(), [](double v) { return v != 0; });
    return norm(dropped);
}

// ---- [patterns] -----------------------------------------------------------------------------

const std::vector<std::string>& HaarWavelet::pattern_names() {
    static const std::vector<std::string> names{"gradient", "disc",   "checker",
                                                "rings",    "blocks", "noise"};
    return names;
}

// Values 0 … 255 (a grey image). Row 0 is the top row.
std::vector<double> HaarWavelet::pattern_image(const std::string& name, int n, std::uint64_t seed) {
    std::vector<double> v(std::size_t(n) * n, 0.0);
    Rng rng(seed);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const double x = (c + 0.5) / n, y = (r + 0.5) / n;  // in (0, 1)
            double g = 0;
            if (name == "gradient") {
                g = 255 * (x + y) / 2;
            } else if (name == "disc") {
                g = std::hypot(x - 0.5, y - 0.5) < 0.3 ? 220 : 40;
            } else if (name == "checker") {
                g = ((c * 4 / n + r * 4 / n) % 2) ? 200 : 50;
            } else if (name == "rings") {
                g = 127.5 + 127.5 * std::cos(40 * std::hypot(x - 0.5, y - 0.5));
            } else if (name == "blocks") {  // piecewise constant on dyadic squares
                g = (x < 0.5 ? 60 : 180) + (y < 0.25 ? 40 : 0) + (x > 0.75 && y > 0.5 ? 30 : 0);
            } else {  // noise: uniform, seeded
                g = double(rng.integer(0, 255));
            }
            v[std::size_t(r) * n + c] = std::round(g);
        }
    return v;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& HaarWavelet::spec() {
    static const Spec spec{
        "haar-wavelet",
        "The Haar wavelet transform: averages and details, level by level, and compression",
        "Wavelets",
        {
            "c ← x   (n = 2^L samples; in 2D an n × n image)",
            "for m = n, n/2, …, 2:  s_k ← (c_2k + c_2k+1)/2,  d_k ← (c_2k − c_2k+1)/2   "
            "(normalised: / √2)",
            "    c[0 … m) ← [s_0 … s_m/2−1, d_0 … d_m/2−1]   ▷ averages first, then details",
            "standard 2D: every row fully (all L levels), then every column",
            "non-standard 2D: one level on the rows of the m × m averages block, then one on its "
            "columns; m ← m/2",
            "compress: zero the details with |c| < threshold (or all but the largest)   ▷ "
            "error² = Σ w c² dropped",
            "reconstruct in reverse order:  c_2k ← s_k + d_k,  c_2k+1 ← s_k − d_k",
            "report ‖x − x′‖₂ and how many coefficients were kept",
        },
        {
            {"level", "one averaging and differencing level of the signal"},
            {"rows", "rows of the image transformed (fully, or by one level)"},
            {"columns", "columns of the image transformed (fully, or by one level)"},
            {"threshold", "the small details set to 0, with the error that will cost"},
            {"reconstruct", "one level (or pass) undone: pairs rebuilt from average and detail"},
            {"summary", "the reconstruction compared with the input: the error and what was kept"},
        },
        {},  // no sliders
        {
            .predict = {{"level", {"s_0", "d_0"}},
                        {"rows", {"s_0", "d_0"}},
                        {"columns", {"s_0", "d_0"}},
                        {"threshold", {"zeroed"}},
                        {"reconstruct", {"x_0", "x_1"}}},
            .mistakes =
                {
                    {"level", "d_0", "negate",
                     "took the detail as x_2k+1 − s_k instead of x_2k − s_k: every detail's sign "
                     "flipped"},
                    {"reconstruct", "x_1", "swap:x_0",
                     "put s − d first and s + d second: each pair comes back reversed"},
                    {"rows", "d_0", "negate", "differenced the row's pairs right minus left"},
                    {"threshold", "zeroed", "off-by-one",
                     "counted the overall average as a small detail and dropped it too"},
                },
            .variants = {{"standard", "/mode", "\"standard\""},
                         {"nonstandard", "/mode", "\"nonstandard\""},
                         {"unnormalised", "/normalised", "false"},
                         {"normalised", "/normalised", "true"}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void HaarWavelet::validate(const Input& in) {
    const bool img = two_d(in);
    const std::string what = img ? "image" : "signal";
    if (in.n < 1)
        throw InputError(what, img ? "must have at least 1 row (got none)"
                                   : "must have at least 1 value (got none)");
    if ((in.n & (in.n - 1)) != 0)
        throw InputError(
            what, (img ? "is " + std::to_string(in.n) + " × " + std::to_string(in.n) + "; the side"
                       : "has " + std::to_string(in.n) + " values; the length") +
                      " must be a power of two (1, 2, 4, 8, …): each level halves it");
    const int limit = img ? kMaxImage : kMaxSignal;
    if (in.n > limit)
        throw InputError(what, img ? "is " + std::to_string(in.n) + " × " + std::to_string(in.n) +
                                         "; at most " + std::to_string(limit) + " × " +
                                         std::to_string(limit) + " is stepped"
                                   : "has " + std::to_string(in.n) + " values; at most " +
                                         std::to_string(limit) + " are stepped");
    if (in.data.size() != (img ? std::size_t(in.n) * in.n : std::size_t(in.n)))
        throw InputError(what, "holds " + std::to_string(in.data.size()) +
                                   " values for n = " + std::to_string(in.n));
    for (std::size_t i = 0; i < in.data.size(); ++i) {
        const double v = in.data[i];
        const std::string f =
            img ? "image[" + std::to_string(i / in.n) + "][" + std::to_string(i % in.n) + "]"
                : "signal[" + std::to_string(i) + "]";
        if (!std::isfinite(v)) throw InputError(f, "must be a finite number (got " + given(v) + ")");
        if (std::fabs(v) > kMaxValue)
            throw InputError(f, "is too large (" + given(v) +
                                    "): at most 1e300 in size, so that the normalised transform's "
                                    "growth (√2 a level) stays finite");
    }
    if (in.compress == Compress::Threshold && !(in.threshold >= 0 && std::isfinite(in.threshold)))
        throw InputError("threshold", "must be ≥ 0 (got " + given(in.threshold) + ")");
    if (in.compress == Compress::Keep && !(in.keep > 0 && in.keep <= 1))
        throw InputError(
            "keep", "must be a fraction in (0, 1] of the coefficients (got " + given(in.keep) + ")");
}

HaarWavelet::State HaarWavelet::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

HaarWavelet::State HaarWavelet::begin(Shared<Input> shared) {
    const Input& in = *shared;
    State s;
    s.in = std::move(shared);
    s.passes = Shared<std::vector<Pass>>(plan(in));
    s.c = in.data;
    if (s.passes->empty()) {  // n = 1: nothing to average
        s.coefficients = s.c;
        if (in.compress == Compress::None) s.compressed = s.c;
        s.phase = in.compress == Compress::None ? Phase::Summary : Phase::Threshold;
    }
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {
void finish(const Input& in, const std::vector<double>& x, const std::vector<double>& coefficients,
            double& l2, double& max_error, double& signal_norm, double& coefficient_norm) {
    std::vector<double> diff(x.size());
    max_error = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        diff[i] = in.data[i] - x[i];
        max_error = std::max(max_error, std::fabs(diff[i]));
    }
    l2 = HaarWavelet::norm(diff);
    signal_norm = HaarWavelet::norm(in.data);
    coefficient_norm = HaarWavelet::norm(coefficients);
}
}  // namespace

void HaarWavelet::advance(State& s) {
    const Input& in = *s.in;
    const auto& passes = *s.passes;
    const int forward = int(passes.size() / 2);
    switch (s.phase) {
        case Phase::Forward:
            apply(in, passes[s.next], s.c);
            if (in.mode == Mode::OneD) s.levels.push_back(s.c);
            ++s.next;
            s.last = Phase::Forward;
            if (s.next == forward) {
                s.coefficients = s.c;
                if (in.compress == Compress::None) {
                    s.compressed = s.c;
                    s.phase = Phase::Inverse;
                } else {
                    s.phase = Phase::Threshold;
                }
            }
            return;
        case Phase::Threshold:
            s.predicted_error = compress(in, s.c, s.zeroed, s.kept, s.cut);
            s.compressed = s.c;
            s.last = Phase::Threshold;
            s.phase = s.next < int(passes.size()) ? Phase::Inverse : Phase::Summary;
            return;
        case Phase::Inverse:
            apply(in, passes[s.next], s.c);
            ++s.next;
            s.last = Phase::Inverse;
            if (s.next == int(passes.size())) s.phase = Phase::Summary;
            return;
        case Phase::Summary:
            if (in.compress == Compress::None)
                s.kept = (long long)std::count_if(s.compressed.begin(), s.compressed.end(),
                                                  [](double v) { return v != 0; });
            finish(in, s.c, s.coefficients, s.l2_error, s.max_error, s.signal_norm,
                   s.coefficient_norm);
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string list(const double* v, int count, int digits = 6, int limit = 16) {
    std::string t = "[";
    for (int i = 0; i < count && i < limit; ++i) t += (i ? ", " : "") + num(v[i], digits);
    if (count > limit) t += ", … (" + std::to_string(count) + " in all)";
    return t + "]";
}

std::vector<double> part(const std::vector<double>& v, std::size_t from, std::size_t count) {
    return {v.begin() + std::ptrdiff_t(from), v.begin() + std::ptrdiff_t(from + count)};
}

// Line l of c (a row, or a column), its first `len` entries.
std::vector<double> line_of(const Input& in, const std::vector<double>& c, bool rows, int l,
                            int len) {
    std::vector<double> v(static_cast<std::size_t>(len));
    for (int j = 0; j < len; ++j)
        v[j] = in.mode == Mode::OneD ? c[j]
               : rows                ? c[std::size_t(l) * in.n + j]
                                     : c[std::size_t(j) * in.n + l];
    return v;
}

std::string h_text(const Input& in) {
    return in.normalised ? "√2" : "2";
}

void narrate_level(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const int j = s.next;  // levels done, 1-based
    const Pass& p = (*s.passes)[j - 1];
    const int m = p.len, half = m / 2;
    const std::vector<double>& prev = j >= 2 ? s.levels[j - 2] : in.data;
    info.event = "level";
    info.line = kLineStore;
    std::string pairs;
    for (int k = 0; k < half && k < 8; ++k)
        pairs += (k ? "; " : "") + std::string("(") + num(prev[2 * k]) + ", " +
                 num(prev[2 * k + 1]) + ") → s = " + num(s.c[k]) + ", d = " + num(s.c[half + k]);
    if (half > 8) pairs += "; …";
    info.narration = "Level " + std::to_string(j) + ": the " + std::to_string(m) +
                     (j == 1 ? " samples" : " averages of the level before") +
                     " in pairs, s = (a + b)/" + h_text(in) + ", d = (a − b)/" + h_text(in) + ": " +
                     pairs + ". The averages " + list(s.c.data(), half) +
                     " go first and the details " + list(s.c.data() + half, half) +
                     " after them: c = " + list(s.c.data(), in.n) + "." +
                     (half == 1 ? " One average is left: the overall average." : "");
    info.math = "s_0 = \\frac{" + tex(prev[0]) + " + " + tex(prev[1]) + "}{" +
                (in.normalised ? std::string("\\sqrt{2}") : std::string("2")) +
                "} = " + tex(s.c[0]) + ",\\; d_0 = \\frac{" + tex(prev[0]) + " - " + tex(prev[1]) +
                "}{" + (in.normalised ? std::string("\\sqrt{2}") : std::string("2")) +
                "} = " + tex(s.c[half]);
    info.vars = {{"level", (long long)j},
                 {"m", (long long)m},
                 {"s_0", s.c[0]},
                 {"d_0", s.c[half]},
                 {"averages", part(s.c, 0, std::size_t(half))},
                 {"details", part(s.c, std::size_t(half), std::size_t(half))}};
    if (in.n <= 64) info.vars.push_back({"c", s.c});
}

std::string lines_text(const Pass& p) {
    const char* what = p.rows ? "row" : "column";
    if (p.count == 1) return std::string(what) + " " + std::to_string(p.first);
    return std::string(what) + "s " + std::to_string(p.first) + "–" +
           std::to_string(p.first + p.count - 1);
}

void narrate_pass(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const int idx = s.next - 1;
    const Pass& p = (*s.passes)[idx];
    const std::vector<double> b = HaarWavelet::before_pass(s, idx);
    const std::vector<double> before = line_of(in, b, p.rows, p.first, p.len);
    const std::vector<double> after = line_of(in, s.c, p.rows, p.first, p.len);
    const int half = p.len / 2;
    const bool standard = in.mode == Mode::Standard;
    info.event = p.rows ? "rows" : "columns";
    info.line = standard ? kLineStandard : kLineNonStandard;
    const std::string lines = lines_text(p);
    const std::string how = standard ? "all " + std::to_string(p.levels) + " level" +
                                           (p.levels == 1 ? "" : "s") + " of the 1D transform"
                                     : "one level on the first " + std::to_string(p.len) +
                                           " entries (the " + std::to_string(p.len) + " × " +
                                           std::to_string(p.len) + " averages block)";
    info.narration =
        std::string(p.rows ? "Rows" : "Columns") + ": " + lines + " — " + how +
        (p.count > 1 ? " (" + std::to_string(p.count) + " lines in one step at this size)" : "") +
        ". " + (p.rows ? "Row " : "Column ") + std::to_string(p.first) + ": " +
        list(before.data(), p.len, 6, 8) + " → " + list(after.data(), p.len, 6, 8) + "." +
        (standard && !p.rows && p.first + p.count == in.n
             ? " Every row and column is done: the standard decomposition."
             : "") +
        (!standard && !p.rows && p.len == 2
             ? " One average is left: the non-standard decomposition is done."
             : "");
    info.math = "s_0 = " + tex(after[0]) + ",\\; d_0 = " + tex(after[half]);
    info.vars = {{"lines", std::vector<double>{double(p.first), double(p.first + p.count - 1)}},
                 {"m", (long long)p.len},
                 {"levels", (long long)p.levels},
                 {"s_0", after[0]},
                 {"d_0", after[half]}};
    if (p.len <= 16) info.vars.push_back({"line", after});
}

void narrate_threshold(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "threshold";
    info.line = kLineCompress;
    const long long total = (long long)s.c.size();
    const std::string rule =
        in.compress == Compress::Threshold
            ? "Every detail with |c| < " + num(in.threshold) + " is set to 0"
            : "Keeping " + num(in.keep * 100, 4) + "% of the " + std::to_string(total) +
                  " coefficients: the overall average and the largest details" +
                  (s.cut > 0 ? " (down to |c| = " + num(s.cut) + ")" : " (none: all details go)") +
                  "; the rest are set to 0";
    info.narration =
        rule + ": " + std::to_string(s.zeroed) + " non-zero coefficient" +
        (s.zeroed == 1 ? "" : "s") + " dropped, " + std::to_string(s.kept) + " of " +
        std::to_string(total) +
        " left. The L2 error this will cost is √(Σ w c²) over the dropped "
        "ones = " +
        num(s.predicted_error) +
        (in.normalised ? " (normalised: w = 1, Parseval)."
                       : ", w the number of samples each one's basis function spans "
                         "(unnormalised coefficients are not weighted equally, so a small one "
                         "at a coarse level can cost more than a larger fine one).");
    info.math =
        "\\lVert x - x' \\rVert_2 = \\sqrt{\\textstyle\\sum w\\, c^2} = " + tex(s.predicted_error);
    info.vars = {{in.compress == Compress::Threshold ? "threshold" : "keep",
                  in.compress == Compress::Threshold ? in.threshold : in.keep},
                 {"zeroed", s.zeroed},
                 {"kept", s.kept},
                 {"predicted_error", s.predicted_error}};
}

void narrate_inverse(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const int idx = s.next - 1;
    const Pass& p = (*s.passes)[idx];
    const std::vector<double> b = HaarWavelet::before_pass(s, idx);
    const std::vector<double> before = line_of(in, b, p.rows, p.first, p.len);
    const std::vector<double> after = line_of(in, s.c, p.rows, p.first, p.len);
    info.event = "reconstruct";
    info.line = kLineReconstruct;
    const std::string g = in.normalised ? " (both / √2)" : "";
    if (in.mode == Mode::OneD) {
        const int half = p.len / 2;
        std::string pairs;
        for (int k = 0; k < half && k < 8; ++k)
            pairs += (k ? "; " : "") + std::string("(s, d) = (") + num(before[k]) + ", " +
                     num(before[half + k]) + ") → " + num(after[2 * k]) + ", " +
                     num(after[2 * k + 1]);
        if (half > 8) pairs += "; …";
        info.narration = "Undo the level of length " + std::to_string(p.len) +
                         ": each pair is s + d, s − d" + g + ": " + pairs + ". The first " +
                         std::to_string(p.len) + " entries are now " + list(after.data(), p.len) +
                         ".";
    } else {
        info.narration = "Undo " + lines_text(p) + " (" + std::to_string(p.levels) + " level" +
                         (p.levels == 1 ? "" : "s") + " on " + std::to_string(p.len) +
                         " entries, pairs s + d, s − d" + g +
                         "): " + (p.rows ? "row " : "column ") + std::to_string(p.first) + " " +
                         list(before.data(), p.len, 6, 8) + " → " +
                         list(after.data(), p.len, 6, 8) + ".";
    }
    info.math = "x_0 = s_0 + d_0 = " + tex(after[0]) + ",\\; x_1 = s_0 - d_0 = " + tex(after[1]);
    info.vars = {{"m", (long long)p.len}, {"x_0", after[0]}, {"x_1", after[1]}};
    if (p.len <= 16) info.vars.push_back({"line", after});
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "summary";
    info.line = kLineReport;
    const long long total = (long long)s.c.size();
    const double rel = s.signal_norm > 0 ? s.l2_error / s.signal_norm : 0;
    info.narration =
        "Reconstructed " + std::string(two_d(in) ? "image" : "signal") +
        (in.n <= 16 && !two_d(in) ? " " + list(s.c.data(), in.n) : "") +
        ": ‖x − x′‖₂ = " + num(s.l2_error) + " (relative " + num(rel, 4) +
        "), max |x − x′| = " + num(s.max_error) + ". " + std::to_string(s.kept) + " of " +
        std::to_string(total) + " coefficients are non-zero" +
        (in.compress != Compress::None
             ? "; the thresholding predicted an error of " + num(s.predicted_error) + "."
             : "; nothing was dropped, so the reconstruction is exact up to rounding.") +
        (in.normalised ? " Normalised: ‖c‖₂ = " + num(s.coefficient_norm) +
                             " = ‖x‖₂ = " + num(s.signal_norm) + " (Parseval)."
                       : "");
    info.math = "\\lVert x - x' \\rVert_2 = " + tex(s.l2_error);
    info.vars = {{"l2_error", s.l2_error},
                 {"max_error", s.max_error},
                 {"predicted_error", s.predicted_error},
                 {"kept", s.kept},
                 {"zeroed", s.zeroed}};
}

}  // namespace

void HaarWavelet::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Forward:
            if (s.in->mode == Mode::OneD)
                narrate_level(s, info);
            else
                narrate_pass(s, info);
            break;
        case Phase::Threshold:
            narrate_threshold(s, info);
            break;
        case Phase::Inverse:
            narrate_inverse(s, info);
            break;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            break;
    }
}

void HaarWavelet::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

HaarWavelet::Result HaarWavelet::result(const State& s) {
    State copy = s;
    return result(std::move(copy));
}

HaarWavelet::Result HaarWavelet::result(State&& s) {
    Result r;
    r.mode = s.in->mode;
    r.n = s.in->n;
    r.levels = std::move(s.levels);
    r.coefficients = std::move(s.coefficients);
    r.compressed = std::move(s.compressed);
    r.reconstruction = std::move(s.c);
    r.zeroed = s.zeroed;
    r.kept = s.kept;
    r.predicted_error = s.predicted_error;
    r.l2_error = s.l2_error;
    r.max_error = s.max_error;
    r.signal_norm = s.signal_norm;
    r.coefficient_norm = s.coefficient_norm;
    r.relative_error = s.signal_norm > 0 ? s.l2_error / s.signal_norm : 0;
    return r;
}

HaarWavelet::Result HaarWavelet::compute(const Input& in) {
    Result r;
    r.mode = in.mode;
    r.n = in.n;
    const std::vector<Pass> passes = plan(in);
    const std::size_t forward = passes.size() / 2;
    std::vector<double> c = in.data;
    for (std::size_t p = 0; p < forward; ++p) {
        apply(in, passes[p], c);
        if (in.mode == Mode::OneD) r.levels.push_back(c);
    }
    r.coefficients = c;
    if (in.compress != Compress::None) {
        double cut;
        r.predicted_error = compress(in, c, r.zeroed, r.kept, cut);
    } else {
        r.kept = (long long)std::count_if(c.begin(), c.end(), [](double v) { return v != 0; });
    }
    r.compressed = c;
    for (std::size_t p = forward; p < passes.size(); ++p) apply(in, passes[p], c);
    finish(in, c, r.coefficients, r.l2_error, r.max_error, r.signal_norm, r.coefficient_norm);
    r.reconstruction = std::move(c);
    r.relative_error = r.signal_norm > 0 ? r.l2_error / r.signal_norm : 0;
    return r;
}

}  // namespace cg
