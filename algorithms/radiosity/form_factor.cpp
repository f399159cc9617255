// Sections: [helpers] [spec] [validate] [pieces] [advance] [narrate] [result and compute] [draw]
#include "radiosity/form_factor.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Phase = FormFactor::Phase;
using State = FormFactor::State;
using Input = FormFactor::Input;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineSetup = 1,
    kLineAnalytic,
    kLineFace,
    kLineDelta,
    kLineBatch,
    kLineReciprocity,
    kLineRowSum
};

bool is_point(const Input& in) {
    return in.from.type == Patch::Type::Point;
}

std::string patch_text(const Patch& p) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return "a rectangle at " + num(p.a, 4) + " with edges u = " + num(p.b, 4) +
                   ", v = " + num(p.c, 4);
        case Patch::Type::Disc:
            return "a disc at " + num(p.a, 4) + " of radius " + num(p.radius, 4);
        case Patch::Type::Triangle:
            return "a triangle " + num(p.a, 4) + ", " + num(p.b, 4) + ", " + num(p.c, 4);
        case Patch::Type::Point:
            return "a differential element dA at " + num(p.a, 4);
    }
    return "";
}

std::string case_text(const ff::Analytic& an) {
    const auto& q = an.params;
    switch (an.kase) {
        case ff::Case::ParallelRectangles:
            return "parallel, directly opposed " + num(q[0], 4) + " × " + num(q[1], 4) +
                   " rectangles at distance c = " + num(q[2], 4) + " (Howell C-11)";
        case ff::Case::PerpendicularRectangles:
            return "perpendicular rectangles sharing an edge l = " + num(q[0], 4) +
                   ", widths w = " + num(q[1], 4) + " (from) and h = " + num(q[2], 4) +
                   " (to) (Howell C-14)";
        case ff::Case::CoaxialDiscs:
            return "coaxial parallel discs r1 = " + num(q[0], 4) + ", r2 = " + num(q[1], 4) +
                   " at distance h = " + num(q[2], 4);
        case ff::Case::PointToDisc:
            return "a differential element facing a coaxial disc r = " + num(q[0], 4) +
                   " at distance h = " + num(q[1], 4);
        case ff::Case::None:
            break;
    }
    return "no formula applies";
}

std::string formula_tex(const ff::Analytic& an) {
    switch (an.kase) {
        case ff::Case::ParallelRectangles:
            return "F = \\frac{2}{\\pi X Y}\\Big[\\ln\\sqrt{\\tfrac{(1+X^2)(1+Y^2)}{1+X^2+Y^2}} + "
                   "X\\sqrt{1+Y^2}\\tan^{-1}\\tfrac{X}{\\sqrt{1+Y^2}} + "
                   "Y\\sqrt{1+X^2}\\tan^{-1}\\tfrac{Y}{\\sqrt{1+X^2}} - X\\tan^{-1}X - "
                   "Y\\tan^{-1}Y\\Big],\\; X = a/c,\\, Y = b/c";
        case ff::Case::PerpendicularRectangles:
            return "F = \\frac{1}{\\pi W}\\Big[W\\tan^{-1}\\tfrac1W + H\\tan^{-1}\\tfrac1H - "
                   "\\sqrt{H^2+W^2}\\tan^{-1}\\tfrac{1}{\\sqrt{H^2+W^2}} + "
                   "\\tfrac14\\ln\\{\\dots\\}"
                   "\\Big],\\; W = w/l,\\, H = h/l";
        case ff::Case::CoaxialDiscs:
            return "F = \\tfrac12\\big(X - \\sqrt{X^2 - 4(R_2/R_1)^2}\\big),\\; X = 1 + "
                   "\\frac{1+R_2^2}{R_1^2},\\; R_i = r_i/h";
        case ff::Case::PointToDisc:
            return "F_{dA \\to disc} = \\frac{r^2}{h^2 + r^2}";
        case ff::Case::None:
            break;
    }
    return "F_{ij} = \\frac{1}{A_i}\\int_{A_i}\\int_{A_j}\\frac{\\cos\\theta_i\\cos\\theta_j}{\\pi "
           "r^2} H_{ij}\\, dA_j\\, dA_i";
}

std::vector<Patch> targets_of(const Input& in) {
    std::vector<Patch> t;
    t.reserve(in.enclosure.size() + 1);
    t.push_back(in.to);
    t.insert(t.end(), in.enclosure.begin(), in.enclosure.end());
    return t;
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& FormFactor::spec() {
    static const Spec spec{
        "form-factor",
        "Form factors: analytic, hemicube and Monte Carlo",
        "Global illumination",
        {
            "A_i, A_j, n_i, n_j;  which analytic case applies (parallel / perpendicular "
            "rectangles, coaxial discs, point to disc)",
            "F_ij ← the case's formula   ▷ F_ij = 1/A_i ∫∫ cos θ_i cos θ_j / (π r²) H dA_j dA_i",
            "for each hemicube face (top, +x, −x, +y, −y), at each of the m × m points of i:",
            "    F_h += ΔF of every cell whose centre sees j  ▷ top ΔA/(π(x²+y²+1)²), side "
            "z ΔA/(π(y²+z²+1)²)",
            "for each batch: N/10 cosine-distributed rays from uniform points of i;  F_mc ← "
            "N_ij / N_i,  σ ← sqrt(F(1−F)/N)",
            "reciprocity: F_ji by each method against A_i F_ij / A_j",
            "row sum: Σ_k F_ik over the closed enclosure (nearest patch per ray) = 1",
        },
        {
            {"setup", "the two patches: areas, normals, and which analytic case applies"},
            {"analytic", "the analytic formula of the case and its value F_ij"},
            {"no-analytic",
             "no closed form for this configuration: the hemicube and Monte Carlo are compared "
             "with each other"},
            {"hemicube-face",
             "one face of the hemicube: the cells through which j is seen and their summed delta "
             "form factors"},
            {"mc-batch",
             "a batch of cosine-distributed rays: hits so far, the estimate N_ij / N_i and its "
             "standard error"},
            {"reciprocity", "F_ji by each method in reverse, against A_i F_ij / A_j"},
            {"row-sum", "the form factors from i to every patch of the closed enclosure sum to 1"},
        },
        {},  // no sliders
        {
            .predict = {{"analytic", {"F_ij"}},
                        {"hemicube-face", {"face_sum"}},
                        {"mc-batch", {"F_mc"}},
                        {"reciprocity", {"F_ji_expected"}}},
            .mistakes =
                {
                    {"analytic", "F_ij", "copy:F_ij_times_pi",
                     "forgot the 1/π of the kernel cos θ_i cos θ_j / (π r²)"},
                    {"reciprocity", "F_ji_expected", "copy:A_j_F_ij_over_A_i",
                     "used A_j F_ij / A_i: the areas the wrong way round in A_i F_ij = A_j F_ji"},
                    {"mc-batch", "F_mc", "copy:N_ij_over_batches",
                     "divided the hits by the number of batches, not by the rays cast"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void FormFactor::validate(const Input& in) {
    validate_patch(in.from, "from", true);
    validate_patch(in.to, "to", false);
    if (in.enclosure.size() > kMaxEnclosure)
        throw InputError("enclosure", "has " + std::to_string(in.enclosure.size()) +
                                          " patches; at most " + std::to_string(kMaxEnclosure));
    for (std::size_t k = 0; k < in.enclosure.size(); ++k)
        validate_patch(in.enclosure[k], "enclosure[" + std::to_string(k) + "]", false);
    if (in.resolution < 2 || in.resolution > kMaxResolution || in.resolution % 2)
        throw InputError("hemicube.resolution", "must be an even number of cells from 2 to " +
                                                    std::to_string(kMaxResolution) + " (got " +
                                                    std::to_string(in.resolution) +
                                                    "): the side faces are R/2 tall");
    if (in.samples < 1 || in.samples > kMaxSamples)
        throw InputError("hemicube.samples", "must be from 1 to " + std::to_string(kMaxSamples) +
                                                 " (got " + std::to_string(in.samples) + ")");
    if (in.rays < 1 || in.rays > kMaxRays)
        throw InputError("monte_carlo.rays", "must be from 1 to " + std::to_string(kMaxRays) +
                                                 " (got " + std::to_string(in.rays) + ")");
    if (!is_point(in)) {
        const double ratio = area(in.from) / area(in.to);
        if (!std::isfinite(ratio) || !(ratio > 0) || !std::isfinite(1 / ratio))
            throw InputError("to", "the areas A_i = " + given(area(in.from)) +
                                       " and A_j = " + given(area(in.to)) +
                                       " differ too much for A_i / A_j to be a double");
    }
}

FormFactor::State FormFactor::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.rng = Rng(in.seed);
    s.batch_rng = s.rng;
    return s;
}

// ---- [pieces] -------------------------------------------------------------------------------

long long FormFactor::batch_size(const Input& in, int batch) {
    const long long base = in.rays / kBatches, extra = in.rays % kBatches;
    return base + (batch < extra ? 1 : 0);
}

FormFactor::Reciprocity FormFactor::reciprocity(const Input& in, const ff::Analytic& an,
                                                double hemicube, double monte_carlo) {
    Reciprocity r;
    const double ai = area(in.from), aj = area(in.to);
    const double f_ij = an.kase != ff::Case::None ? an.value : monte_carlo;
    (void)hemicube;
    r.a_i_f_ij = ai * f_ij;
    r.f_ji_expected = ai / aj * f_ij;
    if (an.kase != ff::Case::None) r.f_ji_analytic = an.reverse;
    r.f_ji_hemicube = ff::hemicube(in.to, in.from, in.resolution, in.samples);
    r.f_ji_monte_carlo = ff::monte_carlo(in.to, in.from, in.rays, in.seed + 1);
    return r;
}

FormFactor::RowSum FormFactor::row_sum(const Input& in, const ff::Analytic& an) {
    RowSum r;
    const std::vector<Patch> t = targets_of(in);
    r.hemicube_terms.assign(t.size(), 0.0);
    const auto points = ff::hemicube_points(in.from, in.samples);
    for (int f = 0; f < ff::kFaces; ++f)
        ff::hemicube_face(in.from, points, t.data(), t.size(), in.resolution, f,
                          r.hemicube_terms.data(), nullptr);
    std::vector<long long> hits(t.size(), 0);
    Rng rng(in.seed + 2);
    double eps = 0;
    for (const Patch& p : t) eps = std::max(eps, ff::ray_eps(in.from, p));
    ff::mc_batch(in.from, t.data(), t.size(), in.rays, rng, hits.data(), eps);
    r.monte_carlo_terms.resize(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) {
        r.monte_carlo_terms[k] = double(hits[k]) / double(in.rays);
        r.hemicube += r.hemicube_terms[k];
        r.monte_carlo += r.monte_carlo_terms[k];
    }
    double sum = an.kase != ff::Case::None ? an.value : 0;
    bool all = an.kase != ff::Case::None;
    for (const Patch& p : in.enclosure) {
        const ff::Analytic a = ff::analytic(in.from, p);
        all = all && a.kase != ff::Case::None;
        sum += a.value;
    }
    if (all) r.analytic = sum;
    return r;
}

// ---- [advance] ------------------------------------------------------------------------------

void FormFactor::advance(State& s) {
    s.last = s.phase;
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Setup:
            s.an = ff::analytic(in.from, in.to);
            s.phase = Phase::Analytic;
            return;
        case Phase::Analytic:
            s.phase = Phase::Hemicube;
            return;
        case Phase::Hemicube: {
            ++s.face;
            const auto points = ff::hemicube_points(in.from, in.samples);
            double sum = 0;
            ff::hemicube_face(in.from, points, &in.to, 1, in.resolution, s.face, &sum, &s.coverage);
            s.face_sum = sum;
            s.face_covered = int(
                std::count_if(s.coverage.begin(), s.coverage.end(), [](float c) { return c > 0; }));
            s.hemicube += sum;
            if (s.face + 1 == ff::kFaces) s.phase = Phase::MonteCarlo;
            return;
        }
        case Phase::MonteCarlo: {
            s.batch_rng = s.rng;
            const long long n = batch_size(in, s.batch);
            long long h = 0;
            ff::mc_batch(in.from, &in.to, 1, n, s.rng, &h, ff::ray_eps(in.from, in.to));
            s.batch_hits = h;
            s.hits += h;
            s.rays_done += n;
            ++s.batch;
            // Fewer rays than batches: the empty batches (always the last ones) are skipped.
            if (s.batch == kBatches || batch_size(in, s.batch) == 0)
                s.phase = is_point(in) ? (in.enclosure.empty() ? Phase::Done : Phase::RowSum)
                                       : Phase::Reciprocity;
            return;
        }
        case Phase::Reciprocity:
            s.reciprocity = reciprocity(in, s.an, s.hemicube, double(s.hits) / double(s.rays_done));
            s.phase = in.enclosure.empty() ? Phase::Done : Phase::RowSum;
            return;
        case Phase::RowSum:
            s.row_sum = row_sum(in, s.an);
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void FormFactor::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

double f_mc(const State& s) {
    return s.rays_done ? double(s.hits) / double(s.rays_done) : 0.0;
}

void narrate_setup(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "setup";
    info.line = kLineSetup;
    const std::string ai = is_point(in) ? "dA (a differential element)" : num(area(in.from), 6);
    info.narration = "Patch i (from) is " + patch_text(in.from) + ", A_i = " + ai +
                     ", n_i = " + num(normal(in.from), 4) + "; patch j (to) is " +
                     patch_text(in.to) + ", A_j = " + num(area(in.to), 6) +
                     ", n_j = " + num(normal(in.to), 4) + ". The centres are " +
                     num(glm::length(centre(in.to) - centre(in.from)), 4) +
                     " apart. Analytic case: " + case_text(s.an) + ".";
    info.math = formula_tex(ff::Analytic{});
}

void narrate_analytic(const State& s, StepInfo& info) {
    if (s.an.kase == ff::Case::None) {
        info.event = "no-analytic";
        info.line = kLineAnalytic;
        info.narration =
            "No closed form covers this pair (the formulas need facing coaxial or edge-sharing "
            "perpendicular shapes): the hemicube and Monte Carlo estimates are compared with "
            "each other, and Monte Carlo's standard error says how far to trust it.";
        info.math = formula_tex(s.an);
        return;
    }
    info.event = "analytic";
    info.line = kLineAnalytic;
    info.narration = "The case is " + case_text(s.an) + ": F_ij = " + num(s.an.value, 6) + ". So " +
                     num(100 * s.an.value, 4) + "% of the energy leaving i diffusely arrives at j.";
    info.math = formula_tex(s.an) + " = " + tex(s.an.value, 6);
}

void narrate_face(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "hemicube-face";
    info.line = s.face == 0 ? kLineFace : kLineDelta;
    const int cells = ff::face_cells(in.resolution, s.face);
    const int pts = int(ff::hemicube_points(in.from, in.samples).size());
    const double w = 2.0 / in.resolution;
    const std::string where = pts == 1 ? "the hemicube at i's centre"
                                       : "the hemicubes on " + std::to_string(pts) +
                                             " equal-area points of i (their mean)";
    info.narration = "The " + std::string(ff::face_name(s.face)) + " face (" +
                     std::to_string(cells) + " cells of ΔA = " + num(w * w, 4) +
                     "): j is seen through " + std::to_string(s.face_covered) + " of them from " +
                     where + "; their ΔF sum to " + num(s.face_sum, 6) +
                     ". Running hemicube sum F_h = " + num(s.hemicube, 6) +
                     (s.face + 1 == ff::kFaces
                          ? (s.an.kase != ff::Case::None
                                 ? " — done; the analytic F_ij = " + num(s.an.value, 6) +
                                       ", error " + num(std::fabs(s.hemicube - s.an.value), 3) + "."
                                 : " — done.")
                          : ".");
    info.math = s.face == 0 ? "\\Delta F = \\frac{\\Delta A}{\\pi (x^2 + y^2 + 1)^2},\\; "
                              "\\sum_{top} \\Delta F = " +
                                  tex(s.face_sum, 6)
                            : "\\Delta F = \\frac{z\\,\\Delta A}{\\pi (y^2 + z^2 + 1)^2},\\; "
                              "\\sum_{side} \\Delta F = " +
                                  tex(s.face_sum, 6);
}

void narrate_batch(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "mc-batch";
    info.line = kLineBatch;
    const double f = f_mc(s);
    const double se = ff::std_error(f, s.rays_done);
    const long long n = FormFactor::batch_size(in, s.batch - 1);
    std::string cmp;
    if (s.an.kase != ff::Case::None) {
        const double err = std::fabs(f - s.an.value);
        cmp = " Against the analytic " + num(s.an.value, 6) + ": error " + num(err, 3) +
              (se > 0 ? " = " + num(err / se, 3) + " standard errors." : ".");
    }
    info.narration = "Batch " + std::to_string(s.batch) + ": " + std::to_string(n) +
                     " cosine-distributed rays from uniform points of i, " +
                     std::to_string(s.batch_hits) +
                     " reach j. So far N_ij = " + std::to_string(s.hits) +
                     " of N_i = " + std::to_string(s.rays_done) + ": F_mc = " + num(f, 6) +
                     ", standard error sqrt(F(1−F)/N) = " + num(se, 3) + "." + cmp;
    info.math = "F_{mc} = \\frac{N_{ij}}{N_i} = \\frac{" + std::to_string(s.hits) + "}{" +
                std::to_string(s.rays_done) + "} = " + tex(f, 6) +
                ",\\; \\sigma = \\sqrt{F(1-F)/N} = " + tex(se, 3);
}

void narrate_reciprocity(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& r = *s.reciprocity;
    info.event = "reciprocity";
    info.line = kLineReciprocity;
    const double ai = area(in.from), aj = area(in.to);
    info.narration =
        "Reciprocity A_i F_ij = A_j F_ji: A_i F_ij = " + num(ai, 6) + " × " +
        num(r.a_i_f_ij / ai, 6) + " = " + num(r.a_i_f_ij, 6) +
        ", so F_ji = A_i F_ij / A_j = " + num(r.f_ji_expected, 6) +
        ". Computed in reverse (from j to i): " +
        (r.f_ji_analytic ? "analytic " + num(*r.f_ji_analytic, 6) + ", " : std::string()) +
        "hemicube " + num(r.f_ji_hemicube, 6) + ", Monte Carlo " + num(r.f_ji_monte_carlo, 6) +
        " (±" + num(ff::std_error(r.f_ji_monte_carlo, in.rays), 3) +
        "). A_j F_ji by Monte Carlo = " + num(aj * r.f_ji_monte_carlo, 6) + ".";
    info.math = "F_{ji} = \\frac{A_i}{A_j} F_{ij} = \\frac{" + tex(ai, 6) + "}{" + tex(aj, 6) +
                "} \\cdot " + tex(r.a_i_f_ij / ai, 6) + " = " + tex(r.f_ji_expected, 6);
}

void narrate_row_sum(const State& s, StepInfo& info) {
    const auto& r = *s.row_sum;
    info.event = "row-sum";
    info.line = kLineRowSum;
    std::string terms;
    for (std::size_t k = 0; k < r.hemicube_terms.size(); ++k)
        terms += (k ? ", " : "") +
                 std::string(k ? "enclosure[" + std::to_string(k - 1) + "]" : "j") + " " +
                 num(r.hemicube_terms[k], 4) + " / " + num(r.monte_carlo_terms[k], 4);
    info.narration =
        "The row sum over the enclosure (hemicube / Monte Carlo per patch: " + terms +
        "): Σ_k F_ik = " + num(r.hemicube, 6) + " by the hemicube (error " +
        num(std::fabs(r.hemicube - 1), 3) + "), " + num(r.monte_carlo, 6) + " by Monte Carlo" +
        (r.analytic ? ", " + num(*r.analytic, 6) + " analytically" : std::string()) +
        ". In a closed enclosure every ray from i lands somewhere, so the sum is 1; less means "
        "a gap.";
    info.math = "\\sum_k F_{ik} = " + tex(r.hemicube, 6) + " \\approx 1";
}

void fill_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.vars = {{"A_i", area(in.from)}, {"A_j", area(in.to)}};
    info.vars.push_back({"case", std::string(ff::case_name(s.an.kase))});
    if (s.last >= Phase::Analytic && s.an.kase != ff::Case::None) {
        info.vars.push_back({"F_ij", s.an.value});
        if (s.last == Phase::Analytic)
            info.vars.push_back({"F_ij_times_pi", s.an.value * 3.14159265358979323846});
    }
    if (s.last == Phase::Hemicube) {
        info.vars.push_back({"face", std::string(ff::face_name(s.face))});
        info.vars.push_back({"covered_cells", (long long)s.face_covered});
        info.vars.push_back({"face_sum", s.face_sum});
    }
    if (s.last >= Phase::Hemicube) info.vars.push_back({"F_h", s.hemicube});
    if (s.last >= Phase::MonteCarlo) {
        info.vars.push_back({"N_ij", (long long)s.hits});
        info.vars.push_back({"N_i", (long long)s.rays_done});
        info.vars.push_back({"F_mc", f_mc(s)});
        info.vars.push_back({"sigma", ff::std_error(f_mc(s), s.rays_done)});
        if (s.last == Phase::MonteCarlo)
            info.vars.push_back({"N_ij_over_batches", double(s.hits) / double(s.batch)});
    }
    if (s.last == Phase::Reciprocity && s.reciprocity) {
        const auto& r = *s.reciprocity;
        info.vars.push_back({"A_i F_ij", r.a_i_f_ij});
        info.vars.push_back({"F_ji_expected", r.f_ji_expected});
        info.vars.push_back(
            {"A_j_F_ij_over_A_i", area(in.to) * r.a_i_f_ij / area(in.from) / area(in.from)});
        if (r.f_ji_analytic) info.vars.push_back({"F_ji_analytic", *r.f_ji_analytic});
        info.vars.push_back({"F_ji_hemicube", r.f_ji_hemicube});
        info.vars.push_back({"F_ji_monte_carlo", r.f_ji_monte_carlo});
    }
    if (s.last == Phase::RowSum && s.row_sum) {
        info.vars.push_back({"row_sum_hemicube", s.row_sum->hemicube});
        info.vars.push_back({"row_sum_monte_carlo", s.row_sum->monte_carlo});
        if (s.row_sum->analytic) info.vars.push_back({"row_sum_analytic", *s.row_sum->analytic});
    }
}

}  // namespace

void FormFactor::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Setup:
            narrate_setup(s, info);
            break;
        case Phase::Analytic:
            narrate_analytic(s, info);
            break;
        case Phase::Hemicube:
            narrate_face(s, info);
            break;
        case Phase::MonteCarlo:
            narrate_batch(s, info);
            break;
        case Phase::Reciprocity:
            narrate_reciprocity(s, info);
            break;
        case Phase::RowSum:
        case Phase::Done:
            narrate_row_sum(s, info);
            break;
    }
    fill_vars(s, info);
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

FormFactor::Result assemble(const Input& in, const ff::Analytic& an, double hemicube,
                            long long hits, long long rays) {
    FormFactor::Result r;
    r.area_from = area(in.from);
    r.area_to = area(in.to);
    r.analytic_case = ff::case_name(an.kase);
    if (an.kase != ff::Case::None) r.analytic = an.value;
    r.hemicube = hemicube;
    r.monte_carlo = rays ? double(hits) / double(rays) : 0.0;
    r.monte_carlo_std_error = ff::std_error(r.monte_carlo, rays);
    if (r.analytic) {
        r.error_hemicube = std::fabs(r.hemicube - *r.analytic);
        r.error_monte_carlo = std::fabs(r.monte_carlo - *r.analytic);
    }
    return r;
}

}  // namespace

FormFactor::Result FormFactor::result(const State& s) {
    Result r = assemble(*s.in, s.an, s.hemicube, s.hits, s.rays_done);
    r.reciprocity = s.reciprocity;
    r.row_sum = s.row_sum;
    return r;
}

FormFactor::Result FormFactor::compute(const Input& in) {
    const ff::Analytic an = ff::analytic(in.from, in.to);
    double hemicube = 0;
    const auto points = ff::hemicube_points(in.from, in.samples);
    for (int f = 0; f < ff::kFaces; ++f) {  // face by face, summed as the steps sum them
        double face = 0;
        ff::hemicube_face(in.from, points, &in.to, 1, in.resolution, f, &face, nullptr);
        hemicube += face;
    }
    Rng rng(in.seed);
    long long hits = 0;
    ff::mc_batch(in.from, &in.to, 1, in.rays, rng, &hits, ff::ray_eps(in.from, in.to));
    Result r = assemble(in, an, hemicube, hits, in.rays);
    if (!is_point(in)) r.reciprocity = reciprocity(in, an, hemicube, r.monte_carlo);
    if (!in.enclosure.empty()) r.row_sum = row_sum(in, an);
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

namespace {

std::vector<dvec3> outline(const Patch& p, int segments = 32) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return {p.a, p.a + p.b, p.a + p.b + p.c, p.a + p.c};
        case Patch::Type::Triangle:
            return {p.a, p.b, p.c};
        case Patch::Type::Disc: {
            std::vector<dvec3> pts;
            for (int k = 0; k < segments; ++k)
                pts.push_back(point_at(p, 1.0, double(k) / segments));
            return pts;
        }
        case Patch::Type::Point:
            break;
    }
    return {};
}

constexpr int kMaxDrawnCells = 32 * 32;
constexpr int kMaxDrawnRays = 60;

}  // namespace

// Both patches (i grey, j green) with their normals, the enclosure faint; the hemicube on i's
// centre (its size a quarter of i's) with the current face's covered cells shaded by the share
// of points that see j through them; the last batch's rays (at most 60), hits green, misses red.
void FormFactor::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const dvec3 ci = centre(in.from), cj = centre(in.to);
    const dvec3 ni = normal(in.from), nj = normal(in.to);
    const double dist = glm::length(cj - ci);
    const double size = std::max({extent(in.from), extent(in.to), 1e-300});
    const double arrow = 0.3 * std::min(size, std::max(dist, 0.3 * size));

    for (std::size_t k = 0; k < in.enclosure.size(); ++k)
        scene.faces3.push_back(
            {outline(in.enclosure[k]), {Role::Construction, 1.0f}, 0.06f, true, false});
    const bool recip = s.last == Phase::Reciprocity;
    if (in.from.type == Patch::Type::Point)
        scene.points3.push_back({ci, "dA (i)", {Role::Subject}, 6.0f});
    else
        scene.faces3.push_back(
            {outline(in.from), {recip ? Role::Kept : Role::Subject, 2.0f}, 0.45f, true, false});
    scene.faces3.push_back(
        {outline(in.to), {recip ? Role::Subject : Role::Kept, 2.0f}, 0.45f, true, false});
    scene.segments3.push_back({ci, ci + arrow * ni, "n_i", {Role::Subject, 2.0f}, true});
    scene.segments3.push_back({cj, cj + arrow * nj, "n_j", {Role::Kept, 2.0f}, true});
    if (in.from.type != Patch::Type::Point)
        scene.labels3.push_back({outline(in.from)[0], "i", {Role::Subject}});
    scene.labels3.push_back({outline(in.to)[0], "j", {Role::Kept}});

    // The hemicube.
    dvec3 t1, t2;
    tangents(in.from, t1, t2);
    const double h =
        in.from.type == Patch::Type::Point ? 0.25 * std::max(dist, size) : 0.25 * extent(in.from);
    auto at = [&](double x, double y, double z) { return ci + h * (x * t1 + y * t2 + z * ni); };
    const bool cube =
        s.last == Phase::Hemicube || s.last == Phase::Setup || s.last == Phase::Analytic;
    if (cube) {
        // The five faces' outlines.
        scene.faces3.push_back({{at(-1, -1, 1), at(1, -1, 1), at(1, 1, 1), at(-1, 1, 1)},
                                {Role::Window, 1.0f},
                                0.05f});
        scene.faces3.push_back(
            {{at(1, -1, 0), at(1, 1, 0), at(1, 1, 1), at(1, -1, 1)}, {Role::Window, 1.0f}, 0.05f});
        scene.faces3.push_back({{at(-1, -1, 0), at(-1, 1, 0), at(-1, 1, 1), at(-1, -1, 1)},
                                {Role::Window, 1.0f},
                                0.05f});
        scene.faces3.push_back(
            {{at(-1, 1, 0), at(1, 1, 0), at(1, 1, 1), at(-1, 1, 1)}, {Role::Window, 1.0f}, 0.05f});
        scene.faces3.push_back({{at(-1, -1, 0), at(1, -1, 0), at(1, -1, 1), at(-1, -1, 1)},
                                {Role::Window, 1.0f},
                                0.05f});
    }
    if (s.last == Phase::Hemicube && int(s.coverage.size()) <= kMaxDrawnCells) {
        const double w = 2.0 / in.resolution;
        for (int k = 0; k < int(s.coverage.size()); ++k) {
            const float c = s.coverage[std::size_t(k)];
            if (c <= 0) continue;
            double x, y, z, dF;
            ff::cell(in.resolution, s.face, k, x, y, z, dF);
            // The cell's corners: across the face ±w/2 in its two in-face directions.
            dvec3 e1, e2;
            if (s.face == 0)
                e1 = {0.5 * w, 0, 0}, e2 = {0, 0.5 * w, 0};
            else if (s.face <= 2)
                e1 = {0, 0.5 * w, 0}, e2 = {0, 0, 0.5 * w};
            else
                e1 = {0.5 * w, 0, 0}, e2 = {0, 0, 0.5 * w};
            const dvec3 m(x, y, z);
            auto P = [&](const dvec3& q) { return at(q.x, q.y, q.z); };
            scene.faces3.push_back(
                {{P(m - e1 - e2), P(m + e1 - e2), P(m + e1 + e2), P(m - e1 + e2)},
                 {Role::Active, 0.5f},
                 0.25f + 0.6f * c,
                 false});
        }
        scene.labels3.push_back(
            {at(0, 0, 1.15),
             std::string(ff::face_name(s.face)) + ": ΣΔF = " + num(s.face_sum, 4),
             {Role::Active}});
    }

    // The last batch's rays.
    if (s.last == Phase::MonteCarlo) {
        Rng rng = s.batch_rng;
        const long long n = std::min<long long>(batch_size(in, s.batch - 1), kMaxDrawnRays);
        const double eps = ff::ray_eps(in.from, in.to);
        const double miss_len = std::max(dist, size) * 0.7;
        for (long long k = 0; k < n; ++k) {
            dvec3 o, d;
            ff::mc_ray(in.from, rng, o, d);
            const auto t = hit(in.to, o, d, eps);
            if (t)
                scene.segments3.push_back({o, o + *t * d, "", {Role::Kept, 1.0f}, false});
            else
                scene.segments3.push_back(
                    {o, o + miss_len * d, "", {Role::Discarded, 1.0f, true}, false});
        }
    }
    scene.extent3 = 0;
    std::erase_if(scene.faces3, [](const Face3& f) { return f.points.size() < 3; });
    drop_non_finite3(scene);
}

}  // namespace cg
