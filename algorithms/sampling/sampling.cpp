// Sections: [helpers] [plain functions] [spec] [validate] [advance] [narrate] [result]; the
// picture is in sampling_draw.cpp.
#include "sampling/sampling.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"
#include "sampling/coverage.hpp"

namespace cg {

namespace {

using glm::dvec2;
using Phase = Sampling::Phase;
using Mode = Sampling::Mode;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineSample = 1,
    kLineFold,
    kLineReconstruct,
    kLineRow,
    kLineCompare,
};

constexpr double kPi = 3.14159265358979323846;

double rad(double deg) {
    return deg * kPi / 180;
}

// An angle in degrees reduced to (−180, 180].
double wrap_deg(double a) {
    a = std::fmod(a, 360.0);
    if (a > 180) a -= 360;
    if (a <= -180) a += 360;
    return a;
}

double sinc(double u) {
    if (u == 0) return 1;
    const double x = kPi * u;
    return std::sin(x) / x;
}

const char* image_id(Sampling::ImageKind k) {
    switch (k) {
        case Sampling::ImageKind::Edge:
            return "edge";
        case Sampling::ImageKind::Checkerboard:
            return "checkerboard";
        case Sampling::ImageKind::ZonePlate:
            return "zone-plate";
    }
    return "edge";
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v))
        throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

}  // namespace

// ---- [plain functions] ----------------------------------------------------------------------

double Sampling::signal(const std::vector<Component>& c, double t) {
    double s = 0;
    for (const Component& k : c)
        s += k.amplitude * std::sin(2 * kPi * k.frequency * t + rad(k.phase));
    return s;
}

Sampling::Alias Sampling::fold(double f, double phase_deg, double rate) {
    Alias a;
    a.frequency = f;
    a.k = static_cast<long long>(std::floor(f / rate + 0.5));
    const double d = f - double(a.k) * rate;  // in [−f_s/2, f_s/2]
    a.alias = std::fabs(d);
    a.alias_phase = d < 0 ? wrap_deg(180 - phase_deg) : wrap_deg(phase_deg);
    a.aliased = rate <= 2 * f;
    return a;
}

long long Sampling::sample_count(double rate, double duration) {
    // n / f_s ≤ duration, with a little slack for rounding (duration 1, f_s 10: 11 samples).
    return static_cast<long long>(std::floor(duration * rate * (1 + 1e-12) + 1e-9)) + 1;
}

double Sampling::reconstruct(const Input& in, double t) {
    const double u = t * in.rate;
    auto x = [&](long long n) { return signal(in.signal, double(n) / in.rate); };
    switch (in.reconstruction) {
        case Reconstruction::Nearest:
            return x(static_cast<long long>(std::floor(u + 0.5)));
        case Reconstruction::Linear: {
            const double n0 = std::floor(u);
            const double a = u - n0;
            const long long n = static_cast<long long>(n0);
            return a == 0 ? x(n) : (1 - a) * x(n) + a * x(n + 1);
        }
        case Reconstruction::Sinc: {
            const long long n0 = static_cast<long long>(std::floor(u));
            double sum = 0;
            for (long long n = n0 - kLanczos + 1; n <= n0 + kLanczos; ++n) {
                const double d = u - double(n);
                sum += x(n) * sinc(d) * sinc(d / kLanczos);
            }
            return sum;
        }
    }
    return 0;
}

double Sampling::error_rms(const Input& in, std::vector<dvec2>* curve) {
    const long long intervals = std::max<long long>(1, sample_count(in.rate, in.duration) - 1);
    const int m =
        static_cast<int>(std::min<long long>(kMaxErrorPoints, intervals * kPointsPerInterval));
    // The picture keeps every stride-th point of the curve: about 400 of them.
    const int stride = std::max(1, m / 400);
    if (curve) curve->reserve(static_cast<std::size_t>(m / stride + 2));
    double sum = 0;
    for (int q = 0; q <= m; ++q) {
        const double t = in.duration * q / m;
        const double r = reconstruct(in, t);
        const double e = r - signal(in.signal, t);
        sum += e * e;
        if (curve && (q % stride == 0 || q == m)) curve->push_back({t, r});
    }
    return std::sqrt(sum / (m + 1));
}

double Sampling::image_value(const Input& in, dvec2 p) {
    const Image& im = in.image;
    switch (im.kind) {
        case ImageKind::Edge:
            return sampling::edge_value(im.point, sampling::edge_direction(im.angle), p);
        case ImageKind::Checkerboard: {
            const double below = im.horizon - p.y;
            if (below <= 0) return 0.5;  // the sky
            // Camera 1 above the ground: the ground point seen at (x, y) is at distance
            // Z = focal / (horizon − y) and to the side X = (x − width/2) / (horizon − y).
            const double X = (p.x - in.width / 2.0) / below, Z = im.focal / below;
            const double a = std::floor(X / im.square) + std::floor(Z / im.square);
            return std::fmod(std::fabs(a), 2.0) == 0 ? 1.0 : 0.0;
        }
        case ImageKind::ZonePlate: {
            const dvec2 d = p - dvec2(in.width / 2.0, in.height / 2.0);
            const double r2 = d.x * d.x + d.y * d.y;
            return 0.5 * (1 + std::cos(kPi * r2 / (2 * im.nyquist_radius)));
        }
    }
    return 0;
}

double Sampling::supersample_pixel(const Input& in, int i, int j) {
    const auto pts = sampling::generate(
        in.pattern, in.samples, sampling::mix_seed(in.seed, std::uint64_t(i), std::uint64_t(j)),
        sampling::default_radius(in.samples));
    double sw = 0, swv = 0;
    for (const auto& q : pts) {
        const double w = sampling::weight(in.filter, q.p - dvec2(0.5));
        sw += w;
        swv += w * image_value(in, dvec2(i, j) + q.p);
    }
    return swv / sw;
}

namespace {

double rms_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0;
    for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return a.empty() ? 0 : std::sqrt(s / double(a.size()));
}

double nyquist_rate(const std::vector<Sampling::Component>& c) {
    double f = 0;
    for (const auto& k : c) f = std::max(f, k.frequency);
    return 2 * f;
}

}  // namespace

Sampling::Result Sampling::run(const Input& in) {
    Result r;
    r.mode = in.mode;
    if (in.mode == Mode::Signal) {
        const long long n = sample_count(in.rate, in.duration);
        r.samples.reserve(static_cast<std::size_t>(n));
        for (long long k = 0; k < n; ++k) {
            const double t = double(k) / in.rate;
            r.samples.push_back({t, signal(in.signal, t)});
        }
        for (const auto& c : in.signal) r.aliases.push_back(fold(c.frequency, c.phase, in.rate));
        r.nyquist_rate = nyquist_rate(in.signal);
        r.error_rms = error_rms(in);
        return r;
    }
    r.width = in.width, r.height = in.height;
    const std::size_t n = std::size_t(in.width) * in.height;
    r.point_sampled.reserve(n);
    r.supersampled.reserve(n);
    for (int j = 0; j < in.height; ++j)
        for (int i = 0; i < in.width; ++i) {
            r.point_sampled.push_back(image_value(in, {i + 0.5, j + 0.5}));
            r.supersampled.push_back(supersample_pixel(in, i, j));
        }
    r.rms_difference = rms_difference(r.point_sampled, r.supersampled);
    return r;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Sampling::spec() {
    static const Spec spec{
        "sampling",
        "Sampling, aliasing and the Nyquist limit",
        "Ray Tracing",
        {
            "for n = 0, 1, …: x_n ← s(n / f_s)            ▷ s(t) = Σ A sin(2π f t + φ)",
            "for each frequency f: k ← round(f / f_s);  alias ← |f − k f_s|   ▷ aliased if f_s ≤ "
            "2f",
            "r(t) ← reconstruct(x_n) (nearest, linear, windowed sinc);  error ← rms(r − s)",
            "for each row j: pixel ← f(centre);  supersampled ← Σ w f(samples) / Σ w",
            "compare the two images: rms difference",
        },
        {
            {"sample", "one sample x_n = s(t_n), with each frequency's share"},
            {"fold", "a frequency at or above f_s/2 folds to its alias |f − k f_s|"},
            {"below-nyquist", "a frequency below f_s/2: the samples keep it as it is"},
            {"reconstruct", "the curve rebuilt from the samples, and its RMS error"},
            {"row", "one row of pixels sampled once at the centre and supersampled"},
            {"compare", "the point-sampled and the supersampled image side by side"},
        },
        {},  // no sliders
        {
            .predict = {{"sample", {"x_n"}}, {"fold", {"alias"}}},
            .mistakes =
                {
                    {"fold", "alias", "copy:f", "forgot to fold: took the alias to be f itself"},
                    {"fold", "aliased", "not", "compared f with f_s instead of f_s / 2"},
                    {"fold", "k", "off-by-one", "folded about the wrong multiple of f_s"},
                },
            .variants =
                {
                    {"nearest", "/reconstruction", "\"nearest\""},
                    {"linear", "/reconstruction", "\"linear\""},
                    {"sinc", "/reconstruction", "\"sinc\""},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Sampling::validate(const Input& in) {
    if (in.mode == Mode::Signal) {
        if (in.signal.empty() || in.signal.size() > std::size_t(kMaxComponents))
            throw InputError("signal", "must list between 1 and " + std::to_string(kMaxComponents) +
                                           " sines (got " + std::to_string(in.signal.size()) + ")");
        for (std::size_t k = 0; k < in.signal.size(); ++k) {
            const std::string f = "signal[" + std::to_string(k) + "]";
            const Component& c = in.signal[k];
            check_finite(c.frequency, f + ".frequency");
            check_finite(c.amplitude, f + ".amplitude");
            check_finite(c.phase, f + ".phase");
            if (c.frequency < 0 || c.frequency > kMaxFrequency)
                throw InputError(f + ".frequency",
                                 "must be between 0 and 10¹² (got " + given(c.frequency) + ")");
            if (std::fabs(c.amplitude) > 1e6)
                throw InputError(f + ".amplitude",
                                 "must be within ±10⁶ (got " + given(c.amplitude) + ")");
            if (std::fabs(c.phase) > 1e6)
                throw InputError(f + ".phase",
                                 "must be within ±10⁶ degrees (got " + given(c.phase) + ")");
        }
        check_finite(in.rate, "rate");
        check_finite(in.duration, "duration");
        if (in.rate <= 0 || in.rate > kMaxFrequency)
            throw InputError("rate",
                             "must be positive and at most 10¹² (got " + given(in.rate) + ")");
        if (in.duration <= 0)
            throw InputError("duration", "must be positive (got " + given(in.duration) + ")");
        if (in.duration * in.rate > double(kMaxSamples - 1))
            throw InputError("duration", "gives " + given(std::floor(in.duration * in.rate) + 1) +
                                             " samples at this rate; at most " +
                                             std::to_string(kMaxSamples) + " are allowed");
        // f t must stay small enough for sin to keep its digits: at most 10⁹ cycles over the
        // times the samples are taken at (the duration, and the 4 + 1 sample periods beyond it
        // that the reconstruction reads).
        const double beyond = (kLanczos + 1) / in.rate;
        for (std::size_t k = 0; k < in.signal.size(); ++k) {
            const double f = in.signal[k].frequency;
            if (!(f * (in.duration + beyond) > 1e9)) continue;
            if (beyond > in.duration)
                throw InputError("rate", "is too low for signal[" + std::to_string(k) +
                                             "]: 5 sample periods of it hold more than 10⁹ "
                                             "cycles (got " +
                                             given(in.rate) + ")");
            throw InputError("signal[" + std::to_string(k) + "].frequency",
                             "makes more than 10⁹ cycles over the duration (got " + given(f) + ")");
        }
        return;
    }
    if (in.width < 1 || in.width > kMaxSide)
        throw InputError("width", "must be between 1 and " + std::to_string(kMaxSide) + " (got " +
                                      std::to_string(in.width) + ")");
    if (in.height < 1 || in.height > kMaxSide)
        throw InputError("height", "must be between 1 and " + std::to_string(kMaxSide) + " (got " +
                                       std::to_string(in.height) + ")");
    if (in.samples < 1 || in.samples > kMaxSupersamples)
        throw InputError("supersampling.samples", "must be between 1 and " +
                                                      std::to_string(kMaxSupersamples) + " (got " +
                                                      std::to_string(in.samples) + ")");
    if (sampling::is_grid(in.pattern) && sampling::grid_side(in.samples) == 0)
        throw InputError("supersampling.samples",
                         std::string("must be a square number n × n (1, 4, 9, 16, …) for the ") +
                             sampling::pattern_id(in.pattern) + " pattern (got " +
                             std::to_string(in.samples) + ")");
    if (in.pattern == sampling::Pattern::Poisson &&
        double(in.width) * in.height * in.samples * in.samples > kMaxPoissonWork)
        throw InputError("supersampling.samples",
                         "makes Poisson dart throwing cost about " +
                             given(double(in.width) * in.height * in.samples * in.samples) +
                             " distance tests for the image (samples² per pixel); at most 10⁹ "
                             "are allowed: use fewer samples or pixels");
    if (double(in.width) * in.height * in.samples > kMaxImageWork)
        throw InputError("supersampling.samples",
                         "makes " + given(double(in.width) * in.height * in.samples) +
                             " samples for the image; at most 4·10⁶ are allowed");
    const Image& im = in.image;
    switch (im.kind) {
        case ImageKind::Edge:
            check_finite(im.angle, "image.angle");
            for (int c = 0; c < 2; ++c) {
                const std::string f = "image.point[" + std::to_string(c) + "]";
                check_finite(im.point[c], f);
                if (std::fabs(im.point[c]) > 1e6)
                    throw InputError(f,
                                     "must be within ±10⁶ pixels (got " + given(im.point[c]) + ")");
            }
            break;
        case ImageKind::Checkerboard:
            check_finite(im.horizon, "image.horizon");
            check_finite(im.square, "image.square");
            check_finite(im.focal, "image.focal");
            if (im.horizon <= 0 || im.horizon > 1e6)
                throw InputError("image.horizon",
                                 "must be above the bottom row: between 0 (excluded) "
                                 "and 10⁶ pixels (got " +
                                     given(im.horizon) + ")");
            if (im.square < 1e-6 || im.square > 1e6)
                throw InputError("image.square",
                                 "must be between 10⁻⁶ and 10⁶ (got " + given(im.square) + ")");
            if (im.focal < 1e-6 || im.focal > 1e6)
                throw InputError("image.focal", "must be between 10⁻⁶ and 10⁶ pixels (got " +
                                                    given(im.focal) + ")");
            break;
        case ImageKind::ZonePlate:
            check_finite(im.nyquist_radius, "image.nyquist_radius");
            if (im.nyquist_radius < 1e-3 || im.nyquist_radius > 1e6)
                throw InputError(
                    "image.nyquist_radius",
                    "must be between 10⁻³ and 10⁶ pixels (got " + given(im.nyquist_radius) + ")");
            break;
    }
}

Sampling::State Sampling::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    if (in.mode == Mode::Signal) {
        s.phase = Phase::Sample;
        s.count = sample_count(in.rate, in.duration);
        s.samples.reserve(static_cast<std::size_t>(s.count));
    } else {
        s.phase = Phase::Row;
        s.point_sampled.reserve(std::size_t(in.width) * in.height);
        s.supersampled.reserve(std::size_t(in.width) * in.height);
    }
    s.last = s.phase;
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Sampling::advance(State& s) {
    const Input& in = *s.in;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Sample: {  // x_n = s(n / f_s)
            const double t = double(s.samples.size()) / in.rate;
            s.samples.push_back({t, signal(in.signal, t)});
            if (std::ssize(s.samples) == s.count) s.phase = Phase::Fold;
            return;
        }
        case Phase::Fold: {  // One frequency's alias
            const Component& c = in.signal[s.aliases.size()];
            s.aliases.push_back(fold(c.frequency, c.phase, in.rate));
            if (s.aliases.size() == in.signal.size()) s.phase = Phase::Reconstruct;
            return;
        }
        case Phase::Reconstruct:  // The error, and the curve for the picture
            s.error_rms = error_rms(in, &s.curve);
            s.phase = Phase::Done;
            return;
        case Phase::Row: {  // One row of pixels, both ways
            const int j = ++s.row;
            for (int i = 0; i < in.width; ++i) {
                s.point_sampled.push_back(image_value(in, {i + 0.5, j + 0.5}));
                s.supersampled.push_back(supersample_pixel(in, i, j));
            }
            if (s.row + 1 == in.height) s.phase = Phase::Compare;
            return;
        }
        case Phase::Compare:
            s.rms_difference = rms_difference(s.point_sampled, s.supersampled);
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = Sampling::State;

// A sample that is zero but for rounding (sin 2πk) reads as 0 in the narration.
double tidy(double v) {
    return std::fabs(v) < 1e-12 ? 0.0 : v;
}

std::string sine_text(const Sampling::Component& c) {
    return num(c.amplitude, 4) + " sin(2π·" + num(c.frequency, 6) + "·t" +
           (c.phase != 0 ? " + " + num(c.phase, 4) + "°" : "") + ")";
}

void narrate_sample(const State& s, StepInfo& info) {
    const Sampling::Input& in = *s.in;
    const std::size_t n = s.samples.size() - 1;
    const dvec2 x = s.samples.back();
    info.event = "sample";
    info.line = kLineSample;
    std::string parts;
    if (in.signal.size() > 1) {
        parts = " = ";
        for (std::size_t k = 0; k < in.signal.size(); ++k) {
            const auto& c = in.signal[k];
            const double v = c.amplitude * std::sin(2 * kPi * c.frequency * x.x + rad(c.phase));
            parts += (k ? " + " : "") + num(tidy(v), 4);
        }
    }
    info.narration = "Sample " + std::to_string(n) + " at t = " + std::to_string(n) + " / " +
                     num(in.rate, 6) + " = " + num(x.x, 6) + ": x = s(t)" + parts + " = " +
                     num(tidy(x.y), 6) + ".";
    info.math = "x_{" + std::to_string(n) + "} = s(" + tex(x.x, 6) + ") = " + tex(tidy(x.y), 6);
}

void narrate_fold(const State& s, StepInfo& info) {
    const Sampling::Input& in = *s.in;
    const Sampling::Alias& a = s.aliases.back();
    const auto& c = in.signal[s.aliases.size() - 1];
    const std::string f = num(a.frequency, 6), fs = num(in.rate, 6), k = std::to_string(a.k);
    info.line = kLineFold;
    if (a.aliased) {
        info.event = "fold";
        info.narration =
            sine_text(c) + ": f = " + f + " ≥ f_s/2 = " + num(in.rate / 2, 6) +
            " (its Nyquist rate 2f = " + num(2 * a.frequency, 6) + " is not below f_s = " + fs +
            "). k = round(" + f + " / " + fs + ") = " + k + ", so it folds to |" + f + " − " + k +
            "·" + fs + "| = " + num(a.alias, 6) +
            (a.alias == a.frequency
                 ? " — itself, but at exactly f_s = 2f its amplitude and phase are lost"
                 : "") +
            ": at every sample time it is indistinguishable from " + num(c.amplitude, 4) +
            " sin(2π·" + num(a.alias, 6) + "·t + " + num(a.alias_phase, 4) + "°)" +
            (a.alias_phase != wrap_deg(c.phase) ? " (the fold mirrors it: phase 180° − φ)" : "") +
            ".";
    } else {
        info.event = "below-nyquist";
        info.narration = sine_text(c) + ": f = " + f + " < f_s/2 = " + num(in.rate / 2, 6) +
                         ": sampled above its Nyquist rate 2f = " + num(2 * a.frequency, 6) +
                         ", it is its own alias (k = 0) and the samples keep it.";
    }
    info.math = "k = \\mathrm{round}(" + tex(a.frequency, 6) + "/" + tex(in.rate, 6) + ") = " + k +
                ",\\; |f - k f_s| = " + tex(a.alias, 6);
}

void narrate_reconstruct(const State& s, StepInfo& info) {
    const Sampling::Input& in = *s.in;
    double fmax = 0;
    bool any = false;
    for (const auto& a : s.aliases) fmax = std::max(fmax, a.frequency), any = any || a.aliased;
    info.event = "reconstruct";
    info.line = kLineReconstruct;
    const char* how = in.reconstruction == Sampling::Reconstruction::Nearest
                          ? "nearest sample (a staircase)"
                      : in.reconstruction == Sampling::Reconstruction::Linear
                          ? "linear interpolation between neighbouring samples"
                          : "windowed sinc, Σ x_n sinc(u − n) sinc((u − n)/4)";
    info.narration = std::string("Reconstruction by ") + how +
                     ". The Nyquist rate is 2 f_max = " + num(2 * fmax, 6) +
                     (in.rate > 2 * fmax ? " < " : " ≥ ") + "f_s = " + num(in.rate, 6) +
                     (any ? ": some frequency is aliased, so no reconstruction can bring it back — "
                            "the curve follows the alias"
                          : ": every frequency is below f_s/2") +
                     ". RMS error against s(t) over [0, " + num(in.duration, 6) +
                     "]: " + num(s.error_rms, 4) + ".";
    info.math = "f_{Nyquist} = 2 f_{max} = " + tex(2 * fmax, 6) +
                ",\\; \\mathrm{rms}(r - s) = " + tex(s.error_rms, 4);
}

void narrate_row(const State& s, StepInfo& info) {
    const Sampling::Input& in = *s.in;
    const std::size_t from = std::size_t(s.row) * in.width;
    double diff = 0, worst = 0;
    for (int i = 0; i < in.width; ++i) {
        const double d = std::fabs(s.point_sampled[from + i] - s.supersampled[from + i]);
        diff += d, worst = std::max(worst, d);
    }
    info.event = "row";
    info.line = kLineRow;
    info.narration = "Row " + std::to_string(s.row) + ": " + std::to_string(in.width) +
                     " pixels sampled once at their centres (left) and with " +
                     std::to_string(in.samples) + " " + sampling::pattern_id(in.pattern) +
                     " samples and the " + sampling::filter_id(in.filter) +
                     " filter (right); they differ by " + num(diff / in.width, 3) +
                     " on average, at most " + num(worst, 3) + ".";
    info.math = "\\overline{|p - \\hat p|} = " + tex(diff / in.width, 3);
}

void narrate_compare(const State& s, StepInfo& info) {
    const Sampling::Input& in = *s.in;
    info.event = "compare";
    info.line = kLineCompare;
    std::string what;
    switch (in.image.kind) {
        case Sampling::ImageKind::Edge:
            what =
                "the point-sampled edge is a staircase of whole pixels; supersampled, the "
                "pixels it crosses take in-between greys";
            break;
        case Sampling::ImageKind::Checkerboard:
            what =
                "toward the horizon the squares get smaller than a pixel: one sample per "
                "pixel turns them into moiré, supersampling into the grey they average to";
            break;
        case Sampling::ImageKind::ZonePlate:
            what = "beyond r = ρ = " + num(in.image.nyquist_radius, 4) +
                   " pixels the rings are finer than ½ cycle per pixel: point sampling shows "
                   "false rings (aliases) there, supersampling mostly grey";
            break;
    }
    info.narration = std::string("The two images (") + image_id(in.image.kind) + "): " + what +
                     ". RMS difference " + num(s.rms_difference, 4) + ".";
    info.math = "\\mathrm{rms}(p - \\hat p) = " + tex(s.rms_difference, 4);
}

void fill_vars(const State& s, StepInfo& info) {
    const Sampling::Input& in = *s.in;
    if (in.mode == Mode::Signal) {
        info.vars = {{"f_s", in.rate}, {"N", s.count}};
        if (!s.samples.empty()) {
            info.vars.push_back({"t_n", s.samples.back().x});
            info.vars.push_back({"x_n", s.samples.back().y});
        }
        if (!s.aliases.empty()) {
            const auto& a = s.aliases.back();
            info.vars.push_back({"f", a.frequency});
            info.vars.push_back({"k", a.k});
            info.vars.push_back({"alias", a.alias});
            info.vars.push_back({"aliased", a.aliased});
        }
        if (s.last == Phase::Reconstruct) info.vars.push_back({"error_rms", s.error_rms});
        return;
    }
    info.vars = {{"width", static_cast<long long>(in.width)},
                 {"height", static_cast<long long>(in.height)},
                 {"samples", static_cast<long long>(in.samples)},
                 {"row", static_cast<long long>(s.row)}};
    if (s.last == Phase::Compare) info.vars.push_back({"rms_difference", s.rms_difference});
}

}  // namespace

void Sampling::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Sample:
            narrate_sample(s, info);
            break;
        case Phase::Fold:
            narrate_fold(s, info);
            break;
        case Phase::Reconstruct:
            narrate_reconstruct(s, info);
            break;
        case Phase::Row:
            narrate_row(s, info);
            break;
        case Phase::Compare:
        case Phase::Done:
            narrate_compare(s, info);
            break;
    }
    fill_vars(s, info);
}

void Sampling::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result] -------------------------------------------------------------------------------

Sampling::Result Sampling::result(const State& s) {
    Result r;
    const Input& in = *s.in;
    r.mode = in.mode;
    if (in.mode == Mode::Signal) {
        r.samples = s.samples;
        r.aliases = s.aliases;
        r.nyquist_rate = nyquist_rate(in.signal);
        r.error_rms = s.error_rms;
        return r;
    }
    r.width = in.width, r.height = in.height;
    r.point_sampled = s.point_sampled;
    r.supersampled = s.supersampled;
    r.rms_difference = s.rms_difference;
    return r;
}

}  // namespace cg
