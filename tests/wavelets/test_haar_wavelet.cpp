// Haar wavelets: the course's small examples by hand ([8 4 1 3], [9 7 3 5], a 2 × 2 image, the
// 4 × 4 example both ways), digit for digit; an independent long-double reference — the 1D
// transform as a matrix W (row i the basis function of coefficient i), the standard 2D one as
// W X Wᵀ, the non-standard one by its 2 × 2 block formulas — on 3,000 random signals and 600
// random images, including constant, length-1, huge (±1e300) and tiny (1e-300) inputs:
// coefficients to 1e-12, reconstruction to 1e-12 of the largest value, Parseval when
// normalised; compression: the predicted error is the measured one, the threshold and keep
// rules hold; standard and non-standard differ but both reconstruct; errors naming the field;
// replay on the example and the presets; the exam problems; the picture.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"
#include "wavelets/haar_wavelet.hpp"

using cg::HaarWavelet;
using Input = HaarWavelet::Input;
using Mode = HaarWavelet::Mode;
using LD = long double;

namespace {

Input signal(std::vector<double> x, bool normalised = false) {
    Input in;
    in.mode = Mode::OneD;
    in.n = int(x.size());
    in.data = std::move(x);
    in.normalised = normalised;
    return in;
}

Input image(int n, std::vector<double> x, Mode mode, bool normalised = false) {
    Input in;
    in.mode = mode;
    in.n = n;
    in.data = std::move(x);
    in.normalised = normalised;
    return in;
}

// ---- the reference, in long double ----

// The analysis matrix: coefficient 0 is the mean; coefficient i in [2^j, 2^j+1) is half the
// difference of the means of the two halves of block p = i − 2^j, S = n / 2^j long: entries
// ±1/S. Normalised, row i is multiplied by √S (√n for the mean).
std::vector<std::vector<LD>> analysis(int n, bool normalised) {
    std::vector<std::vector<LD>> W(std::size_t(n), std::vector<LD>(std::size_t(n), 0));
    for (int j = 0; j < n; ++j) W[0][j] = LD(1) / n;
    if (normalised)
        for (int j = 0; j < n; ++j) W[0][j] *= std::sqrt(LD(n));
    for (int i = 1; i < n; ++i) {
        int level = 0;
        while ((2 << level) <= i) ++level;
        const int S = n >> level, p = i - (1 << level);
        const LD scale = normalised ? std::sqrt(LD(S)) : 1;
        for (int j = 0; j < S; ++j) W[i][p * S + j] = (j < S / 2 ? 1 : -1) * scale / LD(S);
    }
    return W;
}

std::vector<LD> ref_1d(const std::vector<double>& x, bool normalised) {
    const int n = int(x.size());
    const auto W = analysis(n, normalised);
    std::vector<LD> c(std::size_t(n), 0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) c[i] += W[i][j] * LD(x[j]);
    return c;
}

// Standard: C = W X Wᵀ.
std::vector<LD> ref_standard(int n, const std::vector<double>& x, bool normalised) {
    const auto W = analysis(n, normalised);
    std::vector<LD> t(std::size_t(n) * n, 0), c(std::size_t(n) * n, 0);
    for (int r = 0; r < n; ++r)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) t[r * n + i] += LD(x[r * n + j]) * W[i][j];
    for (int i = 0; i < n; ++i)
        for (int col = 0; col < n; ++col)
            for (int r = 0; r < n; ++r) c[i * n + col] += W[i][r] * t[r * n + col];
    return c;
}

// Non-standard: each 2 × 2 block [a b; c d] of the m × m averages gives (a + b + c + d)/4, and
// the row, column and diagonal details (a − b + c − d)/4, (a + b − c − d)/4, (a − b − c + d)/4
// (normalised: /2 instead of /4).
std::vector<LD> ref_nonstandard(int n, const std::vector<double>& x, bool normalised) {
    std::vector<LD> c(x.begin(), x.end());
    const LD f = normalised ? LD(0.5) : LD(0.25);
    for (int m = n; m >= 2; m /= 2) {
        const int h = m / 2;
        std::vector<LD> out(c);
        for (int i = 0; i < h; ++i)
            for (int j = 0; j < h; ++j) {
                const LD a = c[(2 * i) * n + 2 * j], b = c[(2 * i) * n + 2 * j + 1];
                const LD cc = c[(2 * i + 1) * n + 2 * j], d = c[(2 * i + 1) * n + 2 * j + 1];
                out[i * n + j] = f * (a + b + cc + d);
                out[i * n + h + j] = f * (a - b + cc - d);
                out[(h + i) * n + j] = f * (a + b - cc - d);
                out[(h + i) * n + h + j] = f * (a - b - cc + d);
            }
        c = out;
    }
    return c;
}

std::vector<LD> reference(const Input& in) {
    if (in.mode == Mode::OneD) return ref_1d(in.data, in.normalised);
    if (in.mode == Mode::Standard) return ref_standard(in.n, in.data, in.normalised);
    return ref_nonstandard(in.n, in.data, in.normalised);
}

double max_abs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::fabs(x));
    return m;
}

bool all_finite(const std::vector<double>& v) {
    for (double x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

// Random values of one of several kinds: small integers, uniform, a constant, huge, tiny,
// mixed magnitudes.
std::vector<double> values(cg::Rng& rng, std::size_t count, int kind) {
    std::vector<double> v(count);
    const double c = rng.uniform(-10, 10);
    for (auto& x : v) switch (kind) {
            case 0:
                x = double(rng.integer(0, 9));
                break;
            case 1:
                x = rng.uniform(-1, 1);
                break;
            case 2:
                x = c;
                break;
            case 3:
                x = rng.chance(0.5) ? 1e300 : -1e300;
                break;
            case 4:
                x = rng.uniform(-1, 1) * 1e300;
                break;
            case 5:
                x = rng.uniform(-1, 1) * 1e-300;
                break;
            default:
                x = rng.uniform(-1, 1) * std::pow(10.0, double(rng.integer(-30, 30)));
                break;
        }
    return v;
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("haar-wavelet");
    if (!l) throw std::runtime_error("no lesson for haar-wavelet");
    return *l;
}

// The coefficients, the reconstruction and the norms against the reference.
void check_against_reference(const Input& in) {
    const HaarWavelet::Result r = HaarWavelet::compute(in);
    const std::vector<LD> ref = reference(in);
    const double scale = max_abs(in.data);
    const double grow =
        in.normalised ? (in.mode == Mode::OneD ? std::sqrt(double(in.n)) : in.n) : 1;
    REQUIRE(r.coefficients.size() == ref.size());
    REQUIRE(all_finite(r.coefficients));
    REQUIRE(all_finite(r.reconstruction));
    for (std::size_t i = 0; i < ref.size(); ++i) {
        INFO("coefficient " << i);
        CHECK(std::fabs(LD(r.coefficients[i]) - ref[i]) <= 1e-12L * scale * grow + 1e-300L);
    }
    for (std::size_t i = 0; i < in.data.size(); ++i) {
        INFO("sample " << i);
        CHECK(std::fabs(r.reconstruction[i] - in.data[i]) <= 1e-12 * scale + 1e-300);
    }
    CHECK(r.l2_error <= 1e-12 * r.signal_norm + 1e-300);
    if (in.normalised)  // Parseval
        CHECK(std::fabs(r.coefficient_norm - r.signal_norm) <= 1e-12 * r.signal_norm);
    CHECK(r.zeroed == 0);
}

}  // namespace

TEST_CASE("haar-wavelet: the course's examples by hand, digit for digit",
          "[wavelets][haar-wavelet]") {
    SECTION("[8 4 1 3]: [6 2 2 -1], then [4 2 2 -1]") {
        const auto r = HaarWavelet::compute(signal({8, 4, 1, 3}));
        CHECK(r.levels == std::vector<std::vector<double>>{{6, 2, 2, -1}, {4, 2, 2, -1}});
        CHECK(r.coefficients == std::vector<double>{4, 2, 2, -1});
        CHECK(r.reconstruction == std::vector<double>{8, 4, 1, 3});
    }
    SECTION("[9 7 3 5]: [8 4 1 -1], then [6 2 1 -1]") {
        const auto r = HaarWavelet::compute(signal({9, 7, 3, 5}));
        CHECK(r.levels == std::vector<std::vector<double>>{{8, 4, 1, -1}, {6, 2, 1, -1}});
    }
    SECTION("normalised [9 7 3 5]: [12 4 √2 -√2], the norm kept") {
        const auto r = HaarWavelet::compute(signal({9, 7, 3, 5}, true));
        CHECK(r.coefficients[0] == Approx(12).epsilon(1e-15));
        CHECK(r.coefficients[1] == Approx(4).epsilon(1e-15));
        CHECK(r.coefficients[2] == Approx(std::sqrt(2.0)).epsilon(1e-15));
        CHECK(r.coefficients[3] == Approx(-std::sqrt(2.0)).epsilon(1e-15));
        CHECK(r.coefficient_norm == Approx(std::sqrt(164.0)).epsilon(1e-15));
        CHECK(r.signal_norm == Approx(std::sqrt(164.0)).epsilon(1e-15));
    }
    SECTION("eight samples, details below 1.5 zeroed: the error is √(Σ w c²) = 2") {
        Input in = signal({9, 7, 3, 5, 6, 10, 2, 6});
        in.compress = HaarWavelet::Compress::Threshold;
        in.threshold = 1.5;
        const auto r = HaarWavelet::compute(in);
        // Level 1: [8 4 8 4 | 1 -1 -2 -2]; level 2: [6 6 | 2 2]; level 3: [6 | 0].
        CHECK(r.levels[0] == std::vector<double>{8, 4, 8, 4, 1, -1, -2, -2});
        CHECK(r.coefficients == std::vector<double>{6, 0, 2, 2, 1, -1, -2, -2});
        CHECK(r.compressed == std::vector<double>{6, 0, 2, 2, 0, 0, -2, -2});
        CHECK(r.zeroed == 2);  // 1 and -1, each spanning 2 samples: error² = 2 + 2
        CHECK(r.kept == 5);
        CHECK(r.l2_error == Approx(2).epsilon(1e-15));
        CHECK(r.predicted_error == Approx(2).epsilon(1e-15));
        CHECK(r.reconstruction == std::vector<double>{8, 8, 4, 4, 6, 10, 2, 6});
    }
    SECTION("a 2 × 2 image: standard and non-standard agree") {
        for (Mode m : {Mode::Standard, Mode::NonStandard}) {
            const auto r = HaarWavelet::compute(image(2, {9, 7, 3, 5}, m));
            // rows [8 1], [4 -1]; columns [6 2], [0 1]
            CHECK(r.coefficients == std::vector<double>{6, 0, 2, 1});
        }
    }
    SECTION("the 4 × 4 example both ways") {
        const std::vector<double> x{9, 7, 3, 5, 7, 9, 5, 3, 2, 2, 2, 2, 4, 0, 2, 2};
        const auto st = HaarWavelet::compute(image(4, x, Mode::Standard));
        CHECK(st.coefficients ==
              std::vector<double>{4, 1, 0.5, 0, 2, 1, -0.5, 0, 0, 0, 1, -1, 0, 0, -1, 0});
        // Non-standard by hand: the 2 × 2 blocks [9 7; 7 9], [3 5; 5 3], [2 2; 4 0], [2 2; 2 2]
        // give averages [8 4; 2 2], row details [0 0; 1 0], column details 0 and diagonals
        // [1 -1; -1 0]; the averages' own level gives 4, 1 (row), 2 (column) and 1 (diagonal).
        const auto ns = HaarWavelet::compute(image(4, x, Mode::NonStandard));
        CHECK(ns.coefficients ==
              std::vector<double>{4, 1, 0, 0, 2, 1, 1, 0, 0, 0, 1, -1, 0, 0, -1, 0});
        CHECK(st.coefficients != ns.coefficients);
        CHECK(st.reconstruction == x);
        CHECK(ns.reconstruction == x);
    }
}

TEST_CASE("haar-wavelet: the narration of [8 4 1 3], level by level", "[wavelets][haar-wavelet]") {
    const auto t = cg::test::run_traced<HaarWavelet>(signal({8, 4, 1, 3}));
    CHECK(cg::test::events(t) ==
          std::vector<std::string>{"level", "level", "reconstruct", "reconstruct", "summary"});
    CHECK(t.steps[0].narration.find("(8, 4) → s = 6, d = 2; (1, 3) → s = 2, d = −1") !=
          std::string::npos);
    CHECK(t.steps[1].narration.find("c = [4, 2, 2, −1]") != std::string::npos);
    CHECK(t.steps[3].narration.find("[8, 4, 1, 3]") != std::string::npos);
}

TEST_CASE("haar-wavelet: 3,000 random signals against the matrix form in long double",
          "[wavelets][haar-wavelet]") {
    cg::Rng rng(2026);
    int cases = 0;
    for (int k = 0; k < 3000; ++k) {
        const int n = 1 << int(rng.integer(0, k < 2900 ? 6 : 10));
        const int kind = int(rng.integer(0, 6));
        Input in = signal(values(rng, std::size_t(n), kind), rng.chance(0.5));
        CAPTURE(n, kind, in.normalised);
        check_against_reference(in);
        const auto r = HaarWavelet::compute(in);
        REQUIRE(int(r.levels.size()) == (n > 1 ? int(std::log2(n)) : 0));
        if (!r.levels.empty()) CHECK(r.levels.back() == r.coefficients);
        if (kind == 2)  // a constant: every detail exactly 0
            for (int i = 1; i < n; ++i) CHECK(r.coefficients[i] == 0);
        ++cases;
    }
    CHECK(cases == 3000);
}

TEST_CASE("haar-wavelet: 600 random images, standard and non-standard, against the reference",
          "[wavelets][haar-wavelet]") {
    cg::Rng rng(77);
    int differ = 0, both = 0;
    for (int k = 0; k < 600; ++k) {
        const int n = 1 << int(rng.integer(0, k < 580 ? 4 : 6));
        const int kind = int(rng.integer(0, 6));
        const auto x = values(rng, std::size_t(n) * n, kind);
        const bool normalised = rng.chance(0.5);
        CAPTURE(n, kind, normalised);
        const Input st = image(n, x, Mode::Standard, normalised);
        const Input ns = image(n, x, Mode::NonStandard, normalised);
        check_against_reference(st);
        check_against_reference(ns);
        if (n >= 4 && (kind == 0 || kind == 1)) {
            ++both;
            differ +=
                HaarWavelet::compute(st).coefficients != HaarWavelet::compute(ns).coefficients;
        }
    }
    // Standard and non-standard differ in general (from 4 × 4 on; at 2 × 2 they are one).
    CHECK(both > 50);
    CHECK(differ == both);
}

TEST_CASE("haar-wavelet: compression, the predicted error is the measured one",
          "[wavelets][haar-wavelet]") {
    cg::Rng rng(5);
    for (int k = 0; k < 1500; ++k) {
        const int choice = int(rng.integer(0, 2));
        const int n = 1 << int(rng.integer(0, choice == 0 ? 8 : 4));
        Input in;
        const auto mode = choice == 0   ? Mode::OneD
                          : choice == 1 ? Mode::Standard
                                        : Mode::NonStandard;
        const int kind = int(rng.integer(0, 6));
        in = mode == Mode::OneD ? signal(values(rng, std::size_t(n), kind))
                                : image(n, values(rng, std::size_t(n) * n, kind), mode);
        in.normalised = rng.chance(0.5);
        const bool keep = rng.chance(0.5);
        const double scale = max_abs(in.data);
        if (keep) {
            in.compress = HaarWavelet::Compress::Keep;
            in.keep = rng.uniform(0.01, 1);
        } else {
            in.compress = HaarWavelet::Compress::Threshold;
            in.threshold = rng.uniform(0, 0.5) * scale;
        }
        CAPTURE(n, int(mode), kind, in.normalised, keep, in.keep, in.threshold);
        const auto r = HaarWavelet::compute(in);
        REQUIRE(all_finite(r.reconstruction));
        // Σ w c² over what was dropped is ‖x − x̃‖² (the basis is orthogonal).
        CHECK(std::fabs(r.predicted_error - r.l2_error) <= 1e-10 * r.signal_norm + 1e-300);
        const std::size_t N = r.coefficients.size();
        long long zeroed = 0, kept = 0;
        for (std::size_t i = 0; i < N; ++i) {
            zeroed += r.coefficients[i] != 0 && r.compressed[i] == 0;
            kept += r.compressed[i] != 0;
            if (r.compressed[i] != 0) CHECK(r.compressed[i] == r.coefficients[i]);
        }
        CHECK(r.compressed[0] == r.coefficients[0]);  // the overall average stays
        CHECK(zeroed == r.zeroed);
        CHECK(kept == r.kept);
        if (keep) {
            CHECK(double(kept) <= std::ceil(in.keep * double(N) - 1e-9));
            // Everything kept is at least as large as everything dropped (details).
            double smallest_kept = 1e308, largest_dropped = 0;
            for (std::size_t i = 1; i < N; ++i) {
                if (r.compressed[i] != 0)
                    smallest_kept = std::min(smallest_kept, std::fabs(r.compressed[i]));
                else
                    largest_dropped = std::max(largest_dropped, std::fabs(r.coefficients[i]));
            }
            CHECK(largest_dropped <= smallest_kept);
        } else {
            for (std::size_t i = 1; i < N; ++i) {
                if (std::fabs(r.coefficients[i]) < in.threshold)
                    CHECK(r.compressed[i] == 0);
                else
                    CHECK(r.compressed[i] == r.coefficients[i]);
            }
        }
        // Normalised, the error is the norm of the dropped coefficients themselves.
        if (in.normalised) {
            std::vector<double> dropped;
            for (std::size_t i = 0; i < N; ++i)
                dropped.push_back(r.coefficients[i] - r.compressed[i]);
            CHECK(std::fabs(HaarWavelet::norm(dropped) - r.l2_error) <=
                  1e-10 * r.signal_norm + 1e-300);
        }
    }
}

TEST_CASE("haar-wavelet: the state machine gives what compute gives, through the registry too",
          "[wavelets][haar-wavelet]") {
    cg::Rng rng(9);
    for (int k = 0; k < 200; ++k) {
        const int choice = int(rng.integer(0, 2));
        const int n = 1 << int(rng.integer(0, 5));
        const auto mode = choice == 0   ? Mode::OneD
                          : choice == 1 ? Mode::Standard
                                        : Mode::NonStandard;
        Input in = mode == Mode::OneD ? signal(values(rng, std::size_t(n), 1))
                                      : image(n, values(rng, std::size_t(n) * n, 1), mode);
        in.normalised = rng.chance(0.5);
        if (rng.chance(0.5)) {
            in.compress = HaarWavelet::Compress::Keep;
            in.keep = 0.3;
        }
        const auto traced = cg::test::run_traced<HaarWavelet>(in);
        CHECK(traced.result == HaarWavelet::compute(in));
        CHECK(cg::run_to_end<HaarWavelet>(HaarWavelet::start(in)) == HaarWavelet::compute(in));
    }
    // Through JSON: the presets' results as the CLI prints them.
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("haar-wavelet", p.input);
        CHECK(j["l2_error"].get<double>() ==
              Approx(j["predicted_error"].get<double>()).epsilon(1e-9).margin(1e-12));
    }
}

TEST_CASE("haar-wavelet: the steps, one level (or one row, one column) at a time",
          "[wavelets][haar-wavelet]") {
    SECTION("1D: L levels, the threshold, L reconstructions, the summary") {
        Input in = signal({9, 7, 3, 5, 6, 10, 2, 6});
        in.compress = HaarWavelet::Compress::Threshold;
        in.threshold = 1.5;
        const auto t = cg::test::run_traced<HaarWavelet>(in);
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"level", "level", "level", "threshold", "reconstruct",
                                       "reconstruct", "reconstruct", "summary"});
    }
    SECTION("length 1: nothing to average") {
        const auto t = cg::test::run_traced<HaarWavelet>(signal({3.5}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"summary"});
        CHECK(t.result.coefficients == std::vector<double>{3.5});
    }
    SECTION("standard 4 × 4: four rows, four columns; non-standard: two levels of each") {
        const std::vector<double> x(16, 1.0);
        const auto st = cg::test::run_traced<HaarWavelet>(image(4, x, Mode::Standard));
        const auto ns = cg::test::run_traced<HaarWavelet>(image(4, x, Mode::NonStandard));
        CHECK(cg::test::events(ns) ==
              std::vector<std::string>{"rows", "columns", "rows", "columns", "reconstruct",
                                       "reconstruct", "reconstruct", "reconstruct", "summary"});
        CHECK(cg::test::events(st).size() == 4 + 4 + 8 + 1);
    }
    SECTION("64 × 64 standard: rows in 16 groups of 4, said so") {
        Input in = image(64, HaarWavelet::pattern_image("rings", 64, 1), Mode::Standard);
        const auto t = cg::test::run_traced<HaarWavelet>(in);
        CHECK(t.steps.size() == 16 + 16 + 32 + 1);
        CHECK(t.steps[0].narration.find("rows 0–3") != std::string::npos);
        CHECK(t.steps[0].narration.find("4 lines in one step") != std::string::npos);
    }
}

TEST_CASE("haar-wavelet: huge and tiny values stay finite and exact", "[wavelets][haar-wavelet]") {
    for (bool normalised : {false, true}) {
        const auto r = HaarWavelet::compute(signal(std::vector<double>(1024, 1e300), normalised));
        CHECK(all_finite(r.coefficients));
        CHECK(std::isfinite(r.signal_norm));
        for (double v : r.reconstruction)
            if (normalised)
                CHECK(v == Approx(1e300).epsilon(1e-14));
            else
                CHECK(v == 1e300);
        const auto alt = HaarWavelet::compute(signal({1e300, -1e300, 1e300, -1e300}, normalised));
        CHECK(all_finite(alt.coefficients));
        CHECK(alt.coefficients[2] == Approx(normalised ? std::sqrt(2.0) * 1e300 : 1e300));
        const auto img = HaarWavelet::compute(
            image(256, std::vector<double>(256 * 256, -1e300), Mode::NonStandard, normalised));
        CHECK(all_finite(img.coefficients));
        CHECK(img.coefficients[0] == Approx(normalised ? -256e300 : -1e300));
        CHECK(std::isfinite(img.l2_error));
    }
}

TEST_CASE("haar-wavelet: bad input names the field and the reason", "[wavelets][haar-wavelet]") {
    auto err = [](const std::string& text) { return cg::test::error_of("haar-wavelet", text); };
    CHECK(err(R"({"signal": [1, 2, 3]})") ==
          "signal: has 3 values; the length must be a power of two (1, 2, 4, 8, …): each level "
          "halves it");
    CHECK(err(R"({"signal": []})") == "signal: must have at least 1 value (got none)");
    CHECK(err(R"({"image": [[1, 2], [3]]})")
              .rfind("image[1]: has 1 values, but the image has 2 rows", 0) == 0);
    CHECK(err(R"({"image": [[1, 2, 3], [4, 5, 6], [7, 8, 9]]})")
              .rfind("image: is 3 × 3; the side must be a power of two", 0) == 0);
    CHECK(err(R"({"signal": [1, 2], "mode": "standard"})")
              .rfind("mode: \"standard\" is a 2D decomposition", 0) == 0);
    CHECK(err(R"({"image": [[1, 2], [3, 4]], "mode": "1d"})")
              .rfind("mode: \"1d\" transforms a signal", 0) == 0);
    CHECK(err(R"({"signal": [1, 2], "mode": "wavelet"})")
              .rfind("mode: must be \"1d\", \"standard\" or \"nonstandard\"", 0) == 0);
    CHECK(err(R"({"signal": [1, 2], "threshold": 1, "keep": 0.5})") ==
          "keep: give either threshold or keep, not both");
    CHECK(err(R"({"signal": [1, 2], "threshold": -1})") == "threshold: must be ≥ 0 (got −1)");
    CHECK(err(R"({"signal": [1, 2], "keep": 0})").rfind("keep: must be a fraction in (0, 1]", 0) ==
          0);
    CHECK(
        err(R"({"signal": [1, 2], "keep": 1.5})").rfind("keep: must be a fraction in (0, 1]", 0) ==
        0);
    CHECK(err(R"({"signal": [1, 1e301]})").rfind("signal[1]: is too large", 0) == 0);
    CHECK(err(R"({"image": [[1, 2], [-1e301, 4]]})").rfind("image[1][0]: is too large", 0) == 0);
    CHECK(err(R"({"signal": [1, "2"]})").rfind("signal[1]: must be a number", 0) == 0);
    CHECK(err(R"({"pattern": {"name": "mandrill", "size": 8}})")
              .rfind("pattern.name: must be one of gradient", 0) == 0);
    CHECK(err(R"({"pattern": {"name": "disc", "size": 6}})") ==
          "pattern.size: must be a power of two (1, 2, 4, 8, …), got 6");
    CHECK(err(R"({"pattern": {"name": "disc", "size": 512}})")
              .rfind("pattern.size: must be 1 to 256 pixels", 0) == 0);
    CHECK(err(R"({"signal": [1, 2], "image": [[1]]})") ==
          "signal: give one of \"signal\", \"image\" and \"pattern\", not several");
    CHECK(err(R"({})").rfind("signal: is missing", 0) == 0);
    CHECK(err(R"({"signal": [1, 2], "normalized": true})")
              .rfind("normalized: is not a known field", 0) == 0);
    std::string big = "{\"signal\": [0";
    for (int i = 1; i < 2048; ++i) big += ", 0";
    CHECK(err(big + "]}") == "signal: has 2048 values; at most 1024 are stepped");
    CHECK(err(R"({"pattern": {"name": "disc", "size": 8, "seed": 3}})") ==
          "pattern.seed: only the \"noise\" pattern is seeded");
    CHECK(err(R"({"pattern": {"name": "noise", "size": 8, "seed": 3}})") == "(accepted)");
    CHECK(err(R"({"signal": [4]})") == "(accepted)");
}

TEST_CASE("haar-wavelet: replay on the example and the presets", "[wavelets][haar-wavelet]") {
    const auto& a = cg::test::algorithm("haar-wavelet");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 3);
    }
}

TEST_CASE("haar-wavelet: exam problems are by-hand sized and answered by the reference",
          "[wavelets][haar-wavelet][exam]") {
    const auto& a = cg::test::algorithm("haar-wavelet");
    int one_d = 0, two_d = 0, constant = 0, thresholded = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const Input in = cg::test::input_of<HaarWavelet>("haar-wavelet", p.input);
        CAPTURE(seed, p.question);
        CHECK_FALSE(in.normalised);
        for (double v : in.data) CHECK((v >= 0 && v <= 9 && v == std::floor(v)));
        const std::vector<LD> ref = reference(in);
        const auto& coefficients = p.expected["coefficients"];
        std::vector<double> flat;
        if (in.mode == Mode::OneD) {
            ++one_d;
            CHECK((in.n == 4 || in.n == 8));
            flat = coefficients.get<std::vector<double>>();
            // The last level is the transform; each level's averages are quarter-integers.
            CHECK(p.expected["levels"].back() == coefficients);
            std::string digits = "[";
            for (int i = 0; i < in.n; ++i)
                digits += (i ? " " : "") + std::to_string(int(in.data[i]));
            CHECK(p.question.find(digits + "]") != std::string::npos);
            constant += std::all_of(in.data.begin(), in.data.end(),
                                    [&](double v) { return v == in.data[0]; });
        } else {
            ++two_d;
            CHECK((in.n == 2 || in.n == 4));
            for (const auto& row : coefficients)
                for (double v : row.get<std::vector<double>>()) flat.push_back(v);
        }
        REQUIRE(flat.size() == ref.size());
        for (std::size_t i = 0; i < ref.size(); ++i) CHECK(LD(flat[i]) == ref[i]);  // exact: dyadic
        if (in.compress == HaarWavelet::Compress::Threshold) {
            ++thresholded;
            CHECK(p.answers.size() == 4);
        }
    }
    CHECK(one_d > 150);
    CHECK(two_d > 60);
    CHECK(constant > 5);
    CHECK(thresholded > 20);
}

TEST_CASE("haar-wavelet: the picture — bar charts in 1D, image panels in 2D",
          "[wavelets][haar-wavelet]") {
    SECTION("1D: the pairs bracketed; averages and details in two colours; one value scale") {
        auto s = HaarWavelet::start(signal({8, 4, 1, 3}));
        HaarWavelet::step(s, nullptr);
        cg::Scene scene;
        HaarWavelet::draw(s, scene);
        CHECK_FALSE(scene.has_2d());  // nothing on the world's grid
        REQUIRE(scene.panels.size() == 2);
        const cg::Panel &before = scene.panels[0], &after = scene.panels[1];
        for (const cg::Panel* p : {&before, &after}) {
            CHECK(p->kind == cg::PanelKind::Chart);
            CHECK(p->y.lo == before.y.lo);
            CHECK(p->y.hi == before.y.hi);
            CHECK(p->x.lo == -0.5);
            CHECK(p->x.hi == 3.5);
        }
        int kept = 0, details = 0, active = 0;
        for (const cg::Panel* p : {&before, &after})
            for (const auto& q : p->polygons) {
                kept += q.style.role == cg::Role::Kept;
                details += q.style.role == cg::Role::Entering;
            }
        for (const auto& g : before.segments) active += g.style.role == cg::Role::Active;
        CHECK(kept == 2 + 4);  // the averages after the level (2) and the samples before (4)
        CHECK(details == 2);
        CHECK(active == 2);  // two pairs bracketed
        CHECK(after.x.label == "i: s_k at k, d_k at 2 + k");
        CHECK(after.labels.size() == 4);  // the values
    }
    SECTION("1D thresholding: the zeroed details as dashed red outlines") {
        Input in = signal({9, 7, 3, 5, 6, 10, 2, 6});
        in.compress = HaarWavelet::Compress::Threshold;
        in.threshold = 1.5;
        auto s = HaarWavelet::start(in);
        for (int k = 0; k < 4; ++k) HaarWavelet::step(s, nullptr);
        cg::Scene scene;
        HaarWavelet::draw(s, scene);
        REQUIRE(scene.panels.size() == 2);
        int dashed = 0;
        for (const auto& p : scene.panels[1].polygons) dashed += p.style.role == cg::Role::Discarded;
        CHECK(dashed == 2);
    }
    SECTION("2D: the image beside the coefficients, then beside the reconstruction") {
        Input in = image(8, HaarWavelet::pattern_image("disc", 8, 1), Mode::NonStandard);
        auto s = HaarWavelet::start(in);
        HaarWavelet::step(s, nullptr);
        HaarWavelet::step(s, nullptr);
        cg::Scene scene;
        HaarWavelet::draw(s, scene);
        REQUIRE(scene.panels.size() == 2);
        for (const auto& p : scene.panels) CHECK(p.kind == cg::PanelKind::Image);
        bool quadrants = false;
        for (const auto& l : scene.panels[1].labels) quadrants = quadrants || l.text == "diagonal";
        CHECK(quadrants);
        REQUIRE(scene.focus2.size() == 1);  // this step's lines, in the coefficients
        CHECK(scene.focus2[0].panel == 1);
        while (!HaarWavelet::done(s)) HaarWavelet::step(s, nullptr);
        scene.clear();
        HaarWavelet::draw(s, scene);
        REQUIRE(scene.panels.size() == 2);
        CHECK(scene.panels[1].title == "reconstruction");
        // The finished reconstruction of an exact run looks like the image.
        CHECK(scene.panels[1].grids[0].rgba == scene.panels[0].grids[0].rgba);
    }
}
