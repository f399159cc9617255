// Image morphing: Beier–Neely field morphing between two small grey images, warp then
// cross-dissolve.
//
// The course (animation, morphing): linear interpolation between two images gives nice effects
// at low cost; the hard part is saying which pieces of the images correspond. A plain
// cross-dissolve C = (1 − α) A + α B fades one image out and the other in, and features that do
// not line up show twice ("ghosts"). Field morphing lets the user mark the correspondence with
// feature line pairs: P_i Q_i in A goes with P'_i Q'_i in B. For a frame α:
//
//   1. the feature lines are interpolated, endpoint by endpoint: L_i(α) = lerp(P_i, P'_i, α) …
//   2. A is warped so that its lines sit on the interpolated ones, and so is B. By inverse
//      mapping: for every destination pixel centre X, and every destination line P Q (with its
//      source line P' Q', i.e. in A, or in B),
//        u = (X − P)·(Q − P) / |Q − P|²           (along the line, 0 at P, 1 at Q)
//        v = (X − P)·perp(Q − P) / |Q − P|        (signed distance from the line, in pixels)
//        X'_i = P' + u (Q' − P') + v perp(Q' − P') / |Q' − P'|,   D_i = X'_i − X
//        dist = |v| for 0 ≤ u ≤ 1, else the distance to the nearer end
//        w_i = (|Q − P|^p / (a + dist))^b
//      and X' = X + Σ w_i D_i / Σ w_i; the warped pixel is the source image at X', sampled
//      bilinearly (clamped at the border);
//   3. the warped images are blended: C = (1 − α) A_w + α B_w.
//
// perp(x, y) = (−y, x). Pixel (c, r) covers [c, c + 1) × [r, r + 1) with its centre at
// (c + 0.5, r + 0.5); r counts rows down from the top, as images are written.
// lerp(P, P', α) = P + α (P' − P), and P' itself at α = 1: exact at both ends and when P = P'.
// A line mapped onto itself moves nothing (D_i = 0 exactly), so at α = 0 the morph is A, at
// α = 1 it is B, and with the same lines in A and B it is the plain cross-dissolve, all exactly.
// An interpolated line shorter than kMinLength (two opposite lines meet half way) has no
// direction: it is left out of that frame's sum; with no line left a pixel maps to itself.
// Refused: an image empty, ragged or above kMaxSide × kMaxSide, the two of different sizes,
// values not finite or above 1e6 in size, no line pairs or more than kMaxLines, an endpoint not
// finite or above 1e4 in size, a line shorter than kMinLength (P = Q), a, b or p outside their
// ranges, α outside [0, 1], more than kMaxFrames frames or frames × pixels above kMaxPixels,
// the focus pixel outside the image, an unknown pattern.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct ImageMorph {
    static constexpr int kMaxSide = 128;
    static constexpr int kMaxLines = 32;
    static constexpr int kMaxFrames = 120;
    static constexpr long long kMaxPixels = 200000;  // frames × width × height
    static constexpr double kMaxValue = 1e6;
    static constexpr double kMaxCoordinate = 1e4;
    static constexpr double kMinLength = 1e-6;

    // A grey image, row-major, row 0 at the top.
    struct Image {
        int width = 0, height = 0;
        std::vector<double> v;
        double at(int c, int r) const { return v[std::size_t(r) * std::size_t(width) + std::size_t(c)]; }
        bool operator==(const Image&) const = default;
    };
    struct Line {
        glm::dvec2 p{0, 0}, q{1, 0};
        bool operator==(const Line&) const = default;
    };
    struct Pair {
        Line a, b;  // the line in A and the corresponding one in B
        bool operator==(const Pair&) const = default;
    };
    struct Params {
        double a = 0.5, b = 2, p = 0.5;  // w = (length^p / (a + dist))^b
        bool operator==(const Params&) const = default;
    };

    struct Input {
        Image image_a, image_b;
        std::string pattern_a, pattern_b;  // the generated images' names ("" when given as rows)
        std::vector<Pair> lines;
        Params params;
        std::vector<double> alphas;  // the frames' α, in [0, 1]
        int focus_x = -1;            // the narrated pixel's column (−1: the middle one)
        int focus_y = -1;            // and row, for the result (−1: the middle one)
        bool operator==(const Input&) const = default;
    };

    // One line's part in one pixel's mapping.
    struct Term {
        bool used = false;  // false: the interpolated line has no length this frame
        double u = 0, v = 0, dist = 0, weight = 0;
        glm::dvec2 source{0, 0};        // X'_i
        glm::dvec2 displacement{0, 0};  // D_i = X'_i − X
        bool operator==(const Term&) const = default;
    };
    // One side (A or B) of one pixel: where it samples and what it finds there.
    struct Side {
        std::vector<Term> terms;
        glm::dvec2 source{0, 0};  // X'
        double value = 0;         // the image there, bilinearly
        bool operator==(const Side&) const = default;
    };
    struct Focus {
        int x = 0, y = 0;           // the pixel
        glm::dvec2 centre{0, 0};    // X
        double alpha = 0;
        Side a, b;
        double morph = 0, dissolve = 0;
        bool operator==(const Focus&) const = default;
    };
    struct Frame {
        double alpha = 0;
        std::vector<Line> lines;  // the interpolated feature lines
        Image warped_a, warped_b, morph, dissolve;
        bool operator==(const Frame&) const = default;
    };

    struct Result {
        std::vector<Frame> frames;
        Focus focus;  // in the last frame
        // the largest over the frames of mean |morph − dissolve|: what the warp changed
        double difference = 0;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Row, Frame, Done };

    struct State {
        Shared<Input> in;  // resolved: focus filled
        Phase phase = Phase::Row;
        Phase last = Phase::Row;
        int frame = 0;  // the frame being made (or just finished)
        int row = 0;    // rows of it done
        std::vector<Frame> frames;  // the finished ones and the one under way (last)
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static Input resolve(const Input& in);
    static State start(const Input& in);
    static State begin(Shared<Input> resolved);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        std::size_t n = heap_bytes(s.frames);
        for (const Frame& f : s.frames)
            n += heap_bytes(f.lines) + heap_bytes(f.warped_a.v) + heap_bytes(f.warped_b.v) +
                 heap_bytes(f.morph.v) + heap_bytes(f.dissolve.v);
        return n;
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields() {
        return {"focus/a/terms/0/u", "focus/a/terms/0/v", "focus/a/source", "focus/b/source",
                "focus/morph"};
    }

    // Everything in one loop, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use (on a resolved input).
    static glm::dvec2 lerp(glm::dvec2 p, glm::dvec2 q, double alpha);
    static std::vector<Line> interpolate(const Input& in, double alpha);
    // X' for the destination point X; each line's part in `terms` when given.
    static glm::dvec2 source(const std::vector<Line>& dst, const std::vector<Pair>& pairs,
                             bool to_b, const Params& params, glm::dvec2 x,
                             std::vector<Term>* terms = nullptr);
    static double sample(const Image& img, glm::dvec2 x);  // bilinear, clamped
    // Row r of frame f (its lines set, its images sized): warped A, warped B, morph, dissolve.
    static void warp_row(const Input& in, Frame& f, int r);
    static Frame new_frame(const Input& in, double alpha);
    static Focus focus(const Input& in, const Frame& f, int x, int y);
    static Image pattern_image(const std::string& name, int size);
    static double difference(const Frame& f);

  private:
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
