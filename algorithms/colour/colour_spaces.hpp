// Colour spaces: converting colours between RGB, CMY, HSV, HSL, CIE XYZ and YIQ.
//
// Every conversion goes through RGB: first from the given space to RGB, then from RGB to the
// wanted one. The spaces, and the formulas the steps show:
//   - RGB: additive, each of R, G, B in [0, 1].
//   - CMY: subtractive, the complement: (C, M, Y) = (1 − R, 1 − G, 1 − B), and back the same.
//   - HSV (Smith's hexcone): H in degrees [0, 360), S and V in [0, 1].
//       to HSV:  max, min, chroma C = max − min; the hue sector is the largest component:
//                max = R: H = 60 · ((G − B)/C mod 6);  max = G: H = 60 · ((B − R)/C + 2);
//                max = B: H = 60 · ((R − G)/C + 4)   (ties go to R, then G);
//                V = max, S = C / V.
//       from HSV: C = V · S, H′ = H / 60, X = C · (1 − |H′ mod 2 − 1|), the sector ⌊H′⌋ gives
//                (R1, G1, B1) = (C, X, 0), (X, C, 0), (0, C, X), (0, X, C), (X, 0, C), (C, 0, X),
//                then m = V − C is added to each.
//   - HSL (the double hexcone): H as above, S and L in [0, 1]; L = (max + min)/2,
//       S = C / (1 − |2L − 1|) (= C/(max + min) for L ≤ ½, C/(2 − max − min) above);
//       back: C = (1 − |2L − 1|) · S, the same sector, m = L − C/2.
//   - CIE XYZ from linear sRGB (IEC 61966-2-1, D65 white), no gamma: the components are
//       linear light, not the gamma-encoded values of an sRGB file. The standard's matrix
//           X = 0.4124 R + 0.3576 G + 0.1805 B
//           Y = 0.2126 R + 0.7152 G + 0.0722 B
//           Z = 0.0193 R + 0.1192 G + 0.9505 B
//       and back its exact inverse (computed with rationals from these 4-digit entries and
//       rounded to double; the standard prints it to 4 digits: 3.2406, −1.5372, −0.4986 /
//       −0.9689, 1.8758, 0.0415 / 0.0557, −0.2040, 1.0570, which is within 1e-4 of it but not
//       its inverse to 1e-12). White (1, 1, 1) is (0.9505, 1, 1.089), D65.
//   - YIQ (NTSC, the FCC's 1953 matrix):
//           Y = 0.299 R + 0.587 G + 0.114 B  (evaluated as G + 0.299 (R − G) + 0.114 (B − G))
//           I = 0.596 R − 0.274 G − 0.322 B  (evaluated as 0.596 (R − G) + 0.322 (G − B))
//           Q = 0.211 R − 0.523 G + 0.312 B  (evaluated as 0.211 (R − G) + 0.312 (B − G))
//       The Y row sums to 1 and the I and Q rows to 0, so a grey g has Y = g and I = Q = 0 —
//       exactly, in the difference forms.
//       Back: the exact inverse again (R = Y + 0.9562 I + 0.6214 Q, …; its first column is
//       exactly 1). Python's colorsys uses the same FCC definition but rounds Y to
//       0.30 R + 0.59 G + 0.11 B and writes I = 0.74 (R − Y) − 0.27 (B − Y),
//       Q = 0.48 (R − Y) + 0.41 (B − Y), which differ from the matrix above by up to 0.004;
//       the luma weights 0.299, 0.587, 0.114 are the ones textbooks and Rec. 601 give.
//
// Conventions: a grey (C = 0) has H = 0 and S = 0; H = 360 is H = 0, and an output hue is
// always in [0, 360). An input hue may be any finite number of degrees: it is taken modulo 360
// (−30 is 330, 720 is 0). RGB, CMY and the S, V, L of HSV and HSL must lie in [0, 1]
// (refused otherwise, naming colors[k][m]). XYZ and YIQ inputs may be any numbers within ±1e6;
// one whose RGB leaves the cube [0, 1]³ by more than 1e-12 is out of the RGB gamut: it is
// clamped to the cube and reported (out_of_gamut). Within 1e-12 — rounding — the RGB is clamped
// without a report; rounding in the HSV and HSL formulas is clamped the same way.
//
// Steps, per colour: from the input space to RGB (CMY: complement; HSV/HSL: chroma, sector,
// add m; XYZ/YIQ: the inverse matrix row by row, then the gamut check), then from RGB to the
// output space (CMY: complement; HSV/HSL: max-min, hue (or grey), saturation; XYZ/YIQ: the
// matrix row by row), then the colour's result.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct ColourSpaces {
    static constexpr std::size_t kMaxColours = 1000;
    static constexpr double kMaxLinear = 1e6;         // |XYZ or YIQ component| at most this
    static constexpr double kGamutTolerance = 1e-12;  // RGB this far outside [0, 1]: rounding

    enum class Space : std::uint8_t { Rgb, Cmy, Hsv, Hsl, Xyz, Yiq };
    static const char* name(Space s);              // "rgb", …
    static const char* component(Space s, int i);  // "R", "C", "H", … (for narration)
    static bool parse(const std::string& text, Space& out);

    // The matrices (rows), as stated above.
    static const std::array<glm::dvec3, 3>& xyz_from_rgb();
    static const std::array<glm::dvec3, 3>& rgb_from_xyz();
    static const std::array<glm::dvec3, 3>& yiq_from_rgb();
    static const std::array<glm::dvec3, 3>& rgb_from_yiq();

    struct Input {
        Space from = Space::Rgb, to = Space::Hsv;
        std::vector<glm::dvec3> colors;  // 1 … kMaxColours, in the `from` space
        bool operator==(const Input&) const = default;
    };
    struct Result {
        std::vector<glm::dvec3> colors;  // in the `to` space
        std::vector<glm::dvec3> rgb;     // the RGB each went through (in [0, 1]³)
        std::vector<bool> out_of_gamut;  // XYZ/YIQ inputs clamped to the RGB cube
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        FromComplement,  // CMY → RGB
        FromChroma,      // HSV/HSL: C, H′, X
        FromSector,      //          the sector and (R1, G1, B1)
        FromAddM,        //          m and RGB
        FromRow,         // XYZ/YIQ: one row of the inverse matrix
        FromGamut,       //          in the cube, or clamped
        ToComplement,    // RGB → CMY
        ToMaxMin,        // HSV/HSL: max, min, chroma
        ToHue,           //          the hue sector and its formula
        ToSaturation,    //          V and S, or L and S
        ToRow,           // XYZ/YIQ: one row of the matrix
        Result,          // the colour converted
        Done
    };

    // One colour's working, step by step.
    struct Work {
        glm::dvec3 src{0};  // the input colour (an input hue taken modulo 360)
        double chroma = 0, h_prime = 0, x = 0, m = 0;  // from HSV/HSL
        int sector = 0;
        glm::dvec3 rgb1{0};       // (R1, G1, B1) of the sector
        glm::dvec3 unclamped{0};  // from XYZ/YIQ: the matrix's RGB before the gamut check
        bool out_of_gamut = false;
        glm::dvec3 rgb{0};        // the RGB, in [0, 1]³
        double max = 0, min = 0;  // to HSV/HSL
        int max_index = 0;        // 0 R, 1 G, 2 B (the hue's sector)
        glm::dvec3 out{0};        // the output colour, as far as computed
        bool operator==(const Work&) const = default;
    };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Result;  // set by start
        Phase last = Phase::Result;
        int k = -1;         // the colour being converted
        int row = 0;        // FromRow / ToRow: the row done last (0, 1, 2)
        bool fresh = true;  // the next step begins colour k + 1
        Work w;
        Result done;  // the colours finished
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.done; }
    static Result result(State&& s) { return std::move(s.done); }  // run_to_end: moved out
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same conversion as one straight-line function, for the benchmark and the tests.
    static Result convert(const Input& in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
