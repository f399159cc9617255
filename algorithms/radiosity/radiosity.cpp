// Sections: [helpers] [spec] [validate and start] [pieces] [advance] [narrate] [result and
// compute] (the picture: radiosity_draw.cpp)
#include "radiosity/radiosity.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Phase = Radiosity::Phase;
using State = Radiosity::State;
using Input = Radiosity::Input;
using Method = Radiosity::Method;
using Scene3 = Radiosity::Scene3;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line { kLineRow = 1, kLineRowCheck, kLineStart, kLineGather, kLineShootPick, kLineShoot,
            kLineStop };

constexpr double kPi = 3.14159265358979323846;

double max_abs(const dvec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}
double channel_sum(const dvec3& v) {
    return v.x + v.y + v.z;
}
std::vector<double> rgb_list(const dvec3& v) {
    return {v.x, v.y, v.z};
}
const char* channel_name(int c) {
    return c == 0 ? "red" : c == 1 ? "green" : "blue";
}
std::string surface_field(const Scene3& sc, int patch, const char* what) {
    return "surfaces[" + std::to_string(sc.surface[std::size_t(patch)]) + "]." + what;
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Radiosity::spec() {
    static const Spec spec{
        "radiosity",
        "Radiosity: form factors, then gathering or shooting",
        "Global illumination",
        {
            "for each patch i:  F_ij ← form factor to every j (nearest patch along each ray), "
            "F_ii = 0",
            "    check: row sum Σ_j F_ij = 1 (closed), reciprocity A_i F_ij = A_j F_ji",
            "B ← E;  ΔB ← E   ▷ B_i = E_i + ρ_i Σ_j F_ij B_j, per channel",
            "gather (Jacobi: from the old B; Gauss-Seidel: in place): B_i ← E_i + ρ_i Σ_j F_ij "
            "B_j;  residual ← max |ΔB|",
            "shoot: i ← the patch with the most unshot power A_i ΔB_i",
            "    for each j: Δ ← ρ_j F_ji ΔB_i with F_ji = A_i F_ij / A_j;  B_j += Δ;  ΔB_j += Δ;"
            "  then ΔB_i ← 0",
            "stop when the residual < tolerance (or after max_steps)",
        },
        {
            {"form-factor-row",
             "one row of the form-factor matrix: F_ij from patch i to every patch, its row sum "
             "and reciprocity against the rows before"},
            {"jacobi-sweep",
             "one Jacobi sweep: every patch gathers from the previous sweep's radiosities"},
            {"gauss-seidel-sweep",
             "one Gauss-Seidel sweep: every patch gathers, using the radiosities already updated "
             "in this sweep"},
            {"shoot",
             "progressive refinement: the patch with the most unshot power shoots it to every "
             "other patch"},
            {"nothing-to-shoot", "no patch has unshot radiosity left: B is final"},
        },
        {},  // no sliders
        {
            .predict = {{"form-factor-row", {"row_sum"}},
                        {"jacobi-sweep", {"residual"}},
                        {"gauss-seidel-sweep", {"residual"}},
                        {"shoot", {"shooter", "F_ji"}}},
            .mistakes =
                {
                    {"shoot", "F_ji", "copy:F_ij",
                     "used F_ij for the shot from i to j: forgot reciprocity, F_ji = A_i F_ij / "
                     "A_j"},
                    {"jacobi-sweep", "B_k", "copy:B_k_without_rho",
                     "forgot the reflectance: B_k = E_k + Σ F_kj B_j, the gathered light not "
                     "multiplied by ρ_k"},
                    {"gauss-seidel-sweep", "B_k", "copy:B_k_without_rho",
                     "forgot the reflectance: B_k = E_k + Σ F_kj B_j, the gathered light not "
                     "multiplied by ρ_k"},
                    {"form-factor-row", "F_ji", "copy:F_ji_areas_swapped",
                     "the areas the wrong way round in reciprocity: F_ji = A_j F_ij / A_i"},
                },
            .costs = {"steps"},
            .variants = {{"jacobi", "/method", "\"jacobi\""},
                         {"gauss-seidel", "/method", "\"gauss-seidel\""},
                         {"progressive", "/method", "\"progressive\""}},
        },
    };
    return spec;
}

// ---- [validate and start] -------------------------------------------------------------------

namespace {

bool finite3(const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_range(double v, double lo, double hi, const std::string& field, const char* why) {
    if (!(v >= lo && v <= hi)) throw InputError(field, std::string(why) + " (got " + given(v) + ")");
}

struct CameraFrame {
    dvec3 origin, right, up, forward;
    double half = 0;
};

CameraFrame camera_frame(const Radiosity::Camera& c) {
    CameraFrame f;
    f.origin = c.position;
    f.forward = glm::normalize(c.target - c.position);
    f.right = glm::normalize(glm::cross(f.forward, c.up));
    f.up = glm::cross(f.right, f.forward);
    f.half = std::tan(c.fov_deg * kPi / 360.0);
    return f;
}

}  // namespace

void Radiosity::validate(const Input& in) {
    if (in.surfaces.empty())
        throw InputError("surfaces", "needs at least one surface (a closed box of patches)");
    if (in.subdivision < 1 || in.subdivision > kMaxSubdivision)
        throw InputError("subdivision", "must be from 1 to " + std::to_string(kMaxSubdivision) +
                                            " (got " + std::to_string(in.subdivision) + ")");
    const std::size_t n2 = std::size_t(in.subdivision) * std::size_t(in.subdivision);
    if (in.surfaces.size() * n2 > kMaxPatches)
        throw InputError("subdivision",
                         std::to_string(in.surfaces.size()) + " surfaces × " +
                             std::to_string(n2) + " make " + std::to_string(in.surfaces.size() * n2) +
                             " patches; at most " + std::to_string(kMaxPatches));
    for (std::size_t k = 0; k < in.surfaces.size(); ++k) {
        const std::string f = "surfaces[" + std::to_string(k) + "]";
        const Surface& s = in.surfaces[k];
        if (s.patch.type == Patch::Type::Disc || s.patch.type == Patch::Type::Point)
            throw InputError(f + ".type", std::string("must be \"rectangle\" or \"triangle\" (got \"") +
                                              type_name(s.patch.type) +
                                              "\"): radiosity subdivides its surfaces into patches");
        validate_patch(s.patch, f, false);
        if (!finite3(s.emission) || s.emission.x < 0 || s.emission.y < 0 || s.emission.z < 0)
            throw InputError(f + ".emission", "must be finite and non-negative in every channel (got " +
                                                  given(s.emission) + ")");
        if (max_abs(s.emission) > 1e100)  // B stays finite: it is at most E / (1 − ρ F)
            throw InputError(f + ".emission", "must be at most 1e100 in every channel (got " +
                                                  given(s.emission) + ")");
        if (!finite3(s.reflectance))
            throw InputError(f + ".reflectance", "must be finite (got " + given(s.reflectance) + ")");
        for (int c = 0; c < 3; ++c)
            check_range(s.reflectance[c], 0, 1, f + ".reflectance",
                        "must lie in [0, 1] in every channel: a surface cannot reflect more light "
                        "than it receives");
    }
    if (in.resolution < 2 || in.resolution > kMaxResolution || in.resolution % 2)
        throw InputError("form_factors.resolution",
                         "must be an even number of cells from 2 to " +
                             std::to_string(kMaxResolution) + " (got " +
                             std::to_string(in.resolution) + ")");
    if (in.samples < 1 || in.samples > kMaxSamples)
        throw InputError("form_factors.samples", "must be from 1 to " +
                                                     std::to_string(kMaxSamples) + " (got " +
                                                     std::to_string(in.samples) + ")");
    if (in.rays < 1 || in.rays > kMaxRays)
        throw InputError("form_factors.rays", "must be from 1 to " + std::to_string(kMaxRays) +
                                                  " (got " + std::to_string(in.rays) + ")");
    if (!(in.tolerance > 0) || !std::isfinite(in.tolerance))
        throw InputError("tolerance", "must be a positive number (got " + given(in.tolerance) + ")");
    if (in.max_steps < 1 || in.max_steps > kMaxSteps)
        throw InputError("max_steps", "must be from 1 to " + std::to_string(kMaxSteps) + " (got " +
                                          std::to_string(in.max_steps) + ")");
    const Camera& c = in.camera;
    if (!finite3(c.position) || !finite3(c.target) || !finite3(c.up) ||
        max_abs(c.position) > 1e15 || max_abs(c.target) > 1e15 || max_abs(c.up) > 1e15)
        throw InputError("camera", "position, target and up must be finite, below 1e15 in size");
    const dvec3 f = c.target - c.position;
    if (!(max_abs(f) > 0))
        throw InputError("camera.target", "equals the position: no view direction");
    const double along = glm::length(glm::cross(f / max_abs(f), c.up / std::max(max_abs(c.up), 1e-300)));
    if (!(max_abs(c.up) > 0) || !(along > 1e-9))
        throw InputError("camera.up", "must not be zero or along the view direction");
    if (!(c.fov_deg > 0 && c.fov_deg < 170))
        throw InputError("camera.fov_deg", "must lie in (0, 170) degrees (got " + given(c.fov_deg) + ")");
    if (c.width < 1 || c.width > kMaxImage)
        throw InputError("camera.width", "must be from 1 to 64 pixels (got " +
                                             std::to_string(c.width) + ")");
    if (c.height < 1 || c.height > kMaxImage)
        throw InputError("camera.height", "must be from 1 to 64 pixels (got " +
                                              std::to_string(c.height) + ")");
}

Radiosity::Scene3 Radiosity::prepare(const Input& in) {
    Scene3 sc;
    const int n = in.subdivision;
    for (std::size_t k = 0; k < in.surfaces.size(); ++k) {
        const Surface& s = in.surfaces[k];
        const Patch& p = s.patch;
        auto add = [&](const Patch& q) {
            sc.patches.push_back(q);
            sc.surface.push_back(int(k));
            sc.area.push_back(area(q));
            sc.emission.push_back(s.emission);
            sc.reflectance.push_back(s.reflectance);
        };
        if (p.type == Patch::Type::Rectangle) {
            const dvec3 du = p.b / double(n), dv = p.c / double(n);
            for (int b = 0; b < n; ++b)
                for (int a = 0; a < n; ++a)
                    add(Patch::rectangle(p.a + double(a) * du + double(b) * dv, du, dv));
        } else {  // a triangle: the n² triangles of its barycentric grid, same orientation
            const dvec3 e1 = (p.b - p.a) / double(n), e2 = (p.c - p.a) / double(n);
            auto at = [&](int a, int b) { return p.a + double(a) * e1 + double(b) * e2; };
            for (int b = 0; b < n; ++b)
                for (int a = 0; a + b < n; ++a) {
                    add(Patch::triangle(at(a, b), at(a + 1, b), at(a, b + 1)));
                    if (a + b + 2 <= n) add(Patch::triangle(at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)));
                }
        }
    }
    // The camera's id buffer: the nearest patch (its front side) through each pixel's centre.
    const CameraFrame f = camera_frame(in.camera);
    const int w = in.camera.width, h = in.camera.height;
    const double aspect = double(w) / double(h);
    sc.pixel.assign(std::size_t(w) * std::size_t(h), -1);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double x = (2.0 * (i + 0.5) / w - 1.0) * f.half * aspect;
            const double y = (2.0 * (j + 0.5) / h - 1.0) * f.half;
            const dvec3 d = f.forward + x * f.right + y * f.up;
            sc.pixel[std::size_t(j) * w + i] =
                ff::nearest(sc.patches.data(), sc.patches.size(), f.origin, d, 1e-12);
        }
    return sc;
}

Radiosity::State Radiosity::start(const Input& in) {
    validate(in);
    State s;
    Scene3 sc = prepare(in);
    const std::size_t n = sc.patches.size();
    bool perfect = false;
    for (const dvec3& r : sc.reflectance) perfect = perfect || max_abs(r) >= 1;
    if (perfect) {  // ρ = 1 somewhere: only the form factors can say whether B converges
        std::vector<double> F(n * n);
        for (std::size_t i = 0; i < n; ++i) form_factor_row(in, sc, int(i), &F[i * n]);
        check_convergence(in, sc, F);
    }
    s.in = Shared<Input>(in);
    s.F.assign(n * n, 0.0);
    s.B = sc.emission;
    s.unshot = sc.emission;
    s.scene = Shared<Scene3>(std::move(sc));
    return s;
}

// ---- [pieces] -------------------------------------------------------------------------------

void Radiosity::form_factor_row(const Input& in, const Scene3& sc, int i, double* row) {
    const std::size_t n = sc.patches.size();
    const Patch& p = sc.patches[std::size_t(i)];
    std::fill(row, row + n, 0.0);
    if (in.form_factors == FormFactors::Hemicube) {
        const auto points = ff::hemicube_points(p, in.samples);
        for (int f = 0; f < ff::kFaces; ++f)
            ff::hemicube_face(p, points, sc.patches.data(), n, in.resolution, f, row, nullptr);
    } else {
        // Each row its own stream, so that a row does not depend on the rows before it.
        Rng rng(in.seed + 0x9e3779b97f4a7c15ull * std::uint64_t(i + 1));
        double eps = 0;
        for (const Patch& q : sc.patches) eps = std::max(eps, ff::ray_eps(p, q));
        std::vector<long long> hits(n, 0);
        ff::mc_batch(p, sc.patches.data(), n, in.rays, rng, hits.data(), eps);
        for (std::size_t j = 0; j < n; ++j) row[j] = double(hits[j]) / double(in.rays);
        if (in.form_factors == FormFactors::Analytic)
            for (std::size_t j = 0; j < n; ++j) {
                if (j == std::size_t(i)) continue;
                const ff::Analytic a = ff::analytic(p, sc.patches[j]);
                if (a.kase != ff::Case::None) row[j] = a.value;
            }
    }
    row[i] = 0;  // a flat patch does not see itself
}

double Radiosity::row_sum(const std::vector<double>& F, std::size_t n, int i) {
    double s = 0;
    for (std::size_t j = 0; j < n; ++j) s += F[std::size_t(i) * n + j];
    return s;
}

double Radiosity::reciprocity_error(const Scene3& sc, const std::vector<double>& F, int i) {
    const std::size_t n = sc.patches.size();
    double e = 0;
    for (std::size_t j = 0; j < std::size_t(i); ++j)
        e = std::max(e, std::fabs(sc.area[std::size_t(i)] * F[std::size_t(i) * n + j] -
                                  sc.area[j] * F[j * n + std::size_t(i)]));
    return e;
}

namespace {
// Σ_j F_kj B_j: what patch k gathers.
dvec3 gather(const double* row, const std::vector<dvec3>& B) {
    dvec3 g(0);
    for (std::size_t j = 0; j < B.size(); ++j) g += row[j] * B[j];
    return g;
}
}  // namespace

Radiosity::Sweep Radiosity::jacobi_sweep(const Scene3& sc, const std::vector<double>& F,
                                         std::vector<dvec3>& B) {
    const std::size_t n = B.size();
    std::vector<dvec3> next(n);
    Sweep w;
    for (std::size_t k = 0; k < n; ++k) {
        const dvec3 g = gather(&F[k * n], B);
        next[k] = sc.emission[k] + sc.reflectance[k] * g;
        const double change = max_abs(next[k] - B[k]);
        if (change > w.residual || w.k < 0) w = {change, int(k), g, B[k]};
    }
    B.swap(next);
    return w;
}

Radiosity::Sweep Radiosity::gauss_seidel_sweep(const Scene3& sc, const std::vector<double>& F,
                                               std::vector<dvec3>& B) {
    const std::size_t n = B.size();
    Sweep w;
    for (std::size_t k = 0; k < n; ++k) {
        const dvec3 g = gather(&F[k * n], B);  // B_j for j < k already this sweep's
        const dvec3 before = B[k];
        B[k] = sc.emission[k] + sc.reflectance[k] * g;
        const double change = max_abs(B[k] - before);
        if (change > w.residual || w.k < 0) w = {change, int(k), g, before};
    }
    return w;
}

int Radiosity::choose_shooter(const Scene3& sc, const std::vector<dvec3>& unshot) {
    int best = -1;
    double most = 0;
    for (std::size_t i = 0; i < unshot.size(); ++i) {
        const double power = sc.area[i] * channel_sum(unshot[i]);
        if (power > most) best = int(i), most = power;
    }
    return best;
}

double Radiosity::shoot(const Scene3& sc, const std::vector<double>& F, int i,
                        std::vector<dvec3>& B, std::vector<dvec3>& unshot, dvec3& shot_power,
                        Shot* shot) {
    const std::size_t n = B.size(), si = std::size_t(i);
    const dvec3 dBi = unshot[si];
    const double Ai = sc.area[si];
    const double* row = &F[si * n];
    if (shot) {
        shot->shooter = i;
        shot->f_ji.assign(n, 0.0);
        shot->delta_b.assign(n, std::vector<double>(3, 0.0));
    }
    for (std::size_t j = 0; j < n; ++j) {
        if (j == si) continue;
        const double f_ji = row[j] * Ai / sc.area[j];  // reciprocity: A_i F_ij = A_j F_ji
        const dvec3 d = sc.reflectance[j] * dBi * f_ji;
        B[j] += d;
        unshot[j] += d;
        if (shot) shot->f_ji[j] = f_ji, shot->delta_b[j] = rgb_list(d);
    }
    shot_power += Ai * dBi;
    unshot[si] = dvec3(0);
    double left = 0;
    for (const dvec3& u : unshot) left = std::max(left, max_abs(u));
    return left;
}

std::vector<std::uint32_t> Radiosity::image(const Scene3& sc, const std::vector<dvec3>& B) {
    // Exposure: the brightest channel of a non-emitting patch maps to 1 (of any patch when
    // every patch emits), so a bright lamp does not leave the walls black.
    double white = 0, any = 0;
    for (std::size_t k = 0; k < B.size(); ++k) {
        any = std::max(any, max_abs(B[k]));
        if (max_abs(sc.emission[k]) == 0) white = std::max(white, max_abs(B[k]));
    }
    if (!(white > 0)) white = any;
    auto byte = [&](double v) {
        const double x = white > 0 ? std::clamp(v / white, 0.0, 1.0) : 0.0;
        return std::uint32_t(std::lround(255 * std::pow(x, 1 / 2.2)));
    };
    std::vector<std::uint32_t> img(sc.pixel.size());
    for (std::size_t q = 0; q < img.size(); ++q) {
        const int k = sc.pixel[q];
        if (k < 0) {
            img[q] = 0x202028ffu;  // nothing there
            continue;
        }
        const dvec3& b = B[std::size_t(k)];
        img[q] = byte(b.x) << 24 | byte(b.y) << 16 | byte(b.z) << 8 | 0xffu;
    }
    return img;
}

void Radiosity::check_convergence(const Input&, const Scene3& sc, const std::vector<double>& F) {
    const std::size_t n = sc.patches.size();
    std::vector<double> S(n);
    for (std::size_t i = 0; i < n; ++i) S[i] = row_sum(F, n, int(i));
    for (int c = 0; c < 3; ++c) {
        bool perfect = false;
        for (std::size_t i = 0; i < n; ++i) perfect = perfect || sc.reflectance[i][c] >= 1;
        if (!perfect) continue;
        // A patch loses energy when ρ_i Σ_j F_ij < 1; a row above 1 (a hemicube's overshoot)
        // makes light grow.
        std::vector<char> ok(n, 0);
        std::vector<std::size_t> queue;
        for (std::size_t i = 0; i < n; ++i) {
            const double kept = sc.reflectance[i][c] * S[i];
            if (kept > 1 + 1e-12)
                throw InputError(surface_field(sc, int(i), "reflectance"),
                                 std::string("ρ = 1 in the ") + channel_name(c) +
                                     " channel on a patch whose form factors sum to " +
                                     given(S[i], 9) +
                                     " > 1: the light would grow on every bounce; use ρ < 1 or "
                                     "more accurate form factors");
            if (kept < 1 - 1e-12) ok[i] = 1, queue.push_back(i);
        }
        // Every patch must reach a losing one along non-zero F_ij (a breadth-first search back
        // from the losing patches): otherwise some light bounces among them forever.
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const std::size_t j = queue[q];
            for (std::size_t i = 0; i < n; ++i)
                if (!ok[i] && F[i * n + j] > 0) ok[i] = 1, queue.push_back(i);
        }
        for (std::size_t i = 0; i < n; ++i)
            if (!ok[i])
                throw InputError(surface_field(sc, int(i), "reflectance"),
                                 std::string("ρ = 1 in the ") + channel_name(c) +
                                     " channel on patches that form a closed set losing no "
                                     "light (every ρ_i Σ_j F_ij = 1 there): the light would "
                                     "bounce forever and B diverges; give some patch of the "
                                     "enclosure ρ < 1, or leave an opening");
    }
}

// ---- [advance] ------------------------------------------------------------------------------

void Radiosity::advance(State& s) {
    const Input& in = *s.in;
    const Scene3& sc = *s.scene;
    const std::size_t n = sc.patches.size();
    s.last = s.phase;
    switch (s.phase) {
        case Phase::FormFactors:
            ++s.row;
            form_factor_row(in, sc, s.row, &s.F[std::size_t(s.row) * n]);
            if (std::size_t(s.row) + 1 == n) s.phase = Phase::Solve;
            return;
        case Phase::Solve:
            ++s.steps;
            switch (in.method) {
                case Method::Jacobi:
                    s.sweep = jacobi_sweep(sc, s.F, s.B);
                    s.residual = s.sweep.residual;
                    break;
                case Method::GaussSeidel:
                    s.sweep = gauss_seidel_sweep(sc, s.F, s.B);
                    s.residual = s.sweep.residual;
                    break;
                case Method::Progressive:
                    s.shooter = choose_shooter(sc, s.unshot);
                    if (s.shooter < 0) {
                        s.residual = 0;
                        break;
                    }
                    s.shot = s.unshot[std::size_t(s.shooter)];
                    s.residual = shoot(sc, s.F, s.shooter, s.B, s.unshot, s.shot_power,
                                       s.first_shot.shooter < 0 ? &s.first_shot : nullptr);
                    break;
            }
            s.history.push_back(s.residual);
            s.converged = s.residual < in.tolerance;
            if (s.converged || s.steps >= in.max_steps) s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void Radiosity::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

constexpr std::size_t kMaxListed = 24;  // rows longer than this are summarised, not listed

void narrate_row(const State& s, StepInfo& info) {
    const Scene3& sc = *s.scene;
    const std::size_t n = sc.patches.size();
    const int i = s.row;
    const double* row = &s.F[std::size_t(i) * n];
    const double sum = Radiosity::row_sum(s.F, n, i);
    const double recip = Radiosity::reciprocity_error(sc, s.F, i);
    std::size_t best = 0;
    for (std::size_t j = 1; j < n; ++j)
        if (row[j] > row[best]) best = j;
    info.event = "form-factor-row";
    info.line = kLineRow;
    const char* how = s.in->form_factors == Radiosity::FormFactors::Hemicube ? "the hemicube"
                      : s.in->form_factors == Radiosity::FormFactors::MonteCarlo
                          ? "Monte Carlo"
                          : "the analytic formulas (Monte Carlo where none applies)";
    info.narration = "Row " + std::to_string(i) + " of F (patch " + std::to_string(i) +
                     " of surface " + std::to_string(sc.surface[std::size_t(i)]) + ", A_i = " +
                     num(sc.area[std::size_t(i)], 5) + ") by " + how +
                     ": the largest entry is F_" + std::to_string(i) + "," +
                     std::to_string(best) + " = " + num(row[best], 5) + " (so by reciprocity F_" +
                     std::to_string(best) + "," + std::to_string(i) + " = A_i F_ij / A_j = " +
                     num(row[best] * sc.area[std::size_t(i)] / sc.area[best], 5) +
                     "); the row sums to " +
                     num(sum, 6) + " (1 in a closed enclosure; the gap is the method's error)" +
                     (i > 0 ? "; reciprocity A_i F_ij = A_j F_ji holds against the rows before "
                              "to " + num(recip, 3)
                            : std::string()) +
                     ".";
    info.math = "\\sum_j F_{" + std::to_string(i) + "j} = " + tex(sum, 6);
    info.vars = {{"i", (long long)i},
                 {"A_i", sc.area[std::size_t(i)]},
                 {"row_sum", sum},
                 {"max_F_ij", row[best]},
                 {"j_max", (long long)best},
                 {"F_ji", row[best] * sc.area[std::size_t(i)] / sc.area[best]},
                 {"F_ji_areas_swapped", row[best] * sc.area[best] / sc.area[std::size_t(i)]},
                 {"reciprocity_error", recip}};
    if (n <= kMaxListed) info.vars.push_back({"F_i", std::vector<double>(row, row + n)});
}

void narrate_sweep(const State& s, StepInfo& info) {
    const Scene3& sc = *s.scene;
    const bool jacobi = s.in->method == Method::Jacobi;
    const auto& w = s.sweep;
    const std::size_t k = std::size_t(w.k);
    const dvec3 without = sc.reflectance[k] * w.gathered;
    const dvec3 bk = sc.emission[k] + without;
    info.event = jacobi ? "jacobi-sweep" : "gauss-seidel-sweep";
    info.line = kLineGather;
    info.narration =
        std::string(jacobi ? "Jacobi" : "Gauss-Seidel") + " sweep " + std::to_string(s.steps) +
        ": every patch gathers B_i = E_i + ρ_i Σ_j F_ij B_j" +
        (jacobi ? " from the previous sweep's B" : " from the newest B (earlier patches already updated)") +
        ". The largest change is at patch " + std::to_string(k) + ": Σ_j F_kj B_j = " +
        num(w.gathered, 4) + ", so B_k = " + num(sc.emission[k], 4) + " + " +
        num(sc.reflectance[k], 3) + " × that = " + num(bk, 5) + " (was " + num(w.before, 5) +
        "). Residual max |ΔB| = " + num(s.residual, 4) +
        (s.converged ? " < tolerance: converged."
                     : s.phase == Phase::Done ? ": stopped at max_steps, not converged." : ".");
    info.math = "B_k = E_k + \\rho_k \\sum_j F_{kj} B_j = " + tex(bk, 5) +
                ",\\; \\max|\\Delta B| = " + tex(s.residual, 4);
    info.vars = {{"sweep", (long long)s.steps},
                 {"k", (long long)k},
                 {"gathered", rgb_list(w.gathered)},
                 {"B_k", rgb_list(bk)},
                 {"B_k_without_rho", rgb_list(sc.emission[k] + w.gathered)},
                 {"residual", s.residual},
                 {"converged", s.converged}};
}

void narrate_shoot(const State& s, StepInfo& info) {
    const Scene3& sc = *s.scene;
    const std::size_t n = sc.patches.size();
    double unshot_power = 0;
    for (std::size_t j = 0; j < n; ++j) unshot_power += sc.area[j] * channel_sum(s.unshot[j]);
    if (s.shooter < 0) {
        info.event = "nothing-to-shoot";
        info.line = kLineStop;
        info.narration = "No patch has unshot radiosity left (no light to distribute): B = E is "
                         "the solution.";
        info.vars = {{"unshot_power", unshot_power}, {"converged", s.converged}};
        return;
    }
    const std::size_t i = std::size_t(s.shooter);
    // The receiver that gained the most, to show one F_ji worked out.
    std::size_t j = i == 0 && n > 1 ? 1 : 0;
    double most = -1;
    for (std::size_t q = 0; q < n; ++q) {
        if (q == i) continue;
        const double gain = channel_sum(sc.reflectance[q] * s.shot) * s.F[i * n + q] *
                            sc.area[i] / sc.area[q];
        if (gain > most) most = gain, j = q;
    }
    const double f_ij = s.F[i * n + j];
    const double f_ji = f_ij * sc.area[i] / sc.area[j];
    const dvec3 d = sc.reflectance[j] * s.shot * f_ji;
    info.event = "shoot";
    info.line = kLineShoot;
    info.narration =
        "Shot " + std::to_string(s.steps) + ": patch " + std::to_string(i) +
        " has the most unshot power (A_i ΔB_i = " + num(sc.area[i] * channel_sum(s.shot), 4) +
        ") and shoots ΔB_i = " + num(s.shot, 4) + ". For example to patch " + std::to_string(j) +
        ": F_ji = A_i F_ij / A_j = " + num(sc.area[i], 4) + " × " + num(f_ij, 4) + " / " +
        num(sc.area[j], 4) + " = " + num(f_ji, 5) + ", so B_j and ΔB_j grow by ρ_j F_ji ΔB_i = " +
        num(d, 4) + ". Unshot power left " + num(unshot_power, 4) + ", largest unshot ΔB " +
        num(s.residual, 4) +
        (s.converged ? " < tolerance: converged."
                     : s.phase == Phase::Done ? ": stopped at max_steps." : ".");
    info.math = "\\Delta B_j += \\rho_j F_{ji} \\Delta B_i,\\; F_{ji} = "
                "\\frac{A_i}{A_j}F_{ij} = " +
                tex(f_ji, 5);
    info.vars = {{"shot", (long long)s.steps},   {"shooter", (long long)i},
                 {"A_i", sc.area[i]},             {"delta_B_i", rgb_list(s.shot)},
                 {"j", (long long)j},             {"A_j", sc.area[j]},
                 {"F_ij", f_ij},                  {"F_ji", f_ji},
                 {"delta_B_j", rgb_list(d)},           {"unshot_power", unshot_power},
                 {"residual", s.residual},        {"converged", s.converged}};
}

}  // namespace

void Radiosity::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    if (s.last == Phase::FormFactors)
        narrate_row(s, info);
    else if (s.in->method == Method::Progressive)
        narrate_shoot(s, info);
    else
        narrate_sweep(s, info);
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

Radiosity::Result assemble(const Shared<Scene3>& scene, const std::vector<double>& F,
                           const std::vector<dvec3>& B, const std::vector<dvec3>& unshot) {
    Radiosity::Result r;
    const Scene3& sc = *scene;
    const std::size_t n = sc.patches.size();
    r.scene = scene;
    r.form_factors = F;
    r.row_sum.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        r.row_sum[i] = Radiosity::row_sum(F, n, int(i));
        r.reciprocity_error = std::max(r.reciprocity_error, Radiosity::reciprocity_error(sc, F, int(i)));
    }
    r.radiosity = B;
    for (std::size_t j = 0; j < n; ++j) r.unshot_power += sc.area[j] * unshot[j];
    r.image = Radiosity::image(sc, B);
    return r;
}

}  // namespace

Radiosity::Result Radiosity::result(const State& s) {
    Result r = assemble(s.scene, s.F, s.B, s.unshot);
    r.steps = s.steps;
    r.converged = s.converged;
    r.residual = s.residual;
    r.shot_power = s.shot_power;
    r.first_shot = s.first_shot;
    return r;
}

Radiosity::Result Radiosity::compute(const Input& in) {
    validate(in);
    const Shared<Scene3> scene(prepare(in));
    const Scene3& sc = *scene;
    const std::size_t n = sc.patches.size();
    std::vector<double> F(n * n);
    for (std::size_t i = 0; i < n; ++i) form_factor_row(in, sc, int(i), &F[i * n]);
    for (const dvec3& r : sc.reflectance)
        if (max_abs(r) >= 1) {
            check_convergence(in, sc, F);
            break;
        }
    std::vector<dvec3> B = sc.emission, unshot = sc.emission;
    dvec3 shot_power(0);
    Shot first;
    int steps = 0;
    double residual = 0;
    bool converged = false;
    while (steps < in.max_steps && !converged) {
        ++steps;
        if (in.method == Method::Jacobi)
            residual = jacobi_sweep(sc, F, B).residual;
        else if (in.method == Method::GaussSeidel)
            residual = gauss_seidel_sweep(sc, F, B).residual;
        else {
            const int i = choose_shooter(sc, unshot);
            residual = i < 0 ? 0
                             : shoot(sc, F, i, B, unshot, shot_power,
                                     first.shooter < 0 ? &first : nullptr);
        }
        converged = residual < in.tolerance;
    }
    Result r = assemble(scene, F, B, unshot);
    r.steps = steps;
    r.converged = converged;
    r.residual = residual;
    r.shot_power = shot_power;
    r.first_shot = first;
    return r;
}

}  // namespace cg
