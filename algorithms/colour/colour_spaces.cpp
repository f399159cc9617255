// Sections: [spaces and matrices] [conversions] [spec] [validate] [advance] [narrate]
//           [convert] (the picture: colour_spaces_draw.cpp)
#include "colour/colour_spaces.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

using glm::dvec3;
using Space = ColourSpaces::Space;
using Phase = ColourSpaces::Phase;
using Work = ColourSpaces::Work;
using Input = ColourSpaces::Input;

// ---- [spaces and matrices] ------------------------------------------------------------------

const char* ColourSpaces::name(Space s) {
    static const char* const kNames[] = {"rgb", "cmy", "hsv", "hsl", "xyz", "yiq"};
    return kNames[static_cast<int>(s)];
}

const char* ColourSpaces::component(Space s, int i) {
    static const char* const kComponents[6][3] = {{"R", "G", "B"}, {"C", "M", "Y"},
                                                  {"H", "S", "V"}, {"H", "S", "L"},
                                                  {"X", "Y", "Z"}, {"Y", "I", "Q"}};
    return kComponents[static_cast<int>(s)][i];
}

bool ColourSpaces::parse(const std::string& text, Space& out) {
    for (int i = 0; i < 6; ++i)
        if (text == name(static_cast<Space>(i))) {
            out = static_cast<Space>(i);
            return true;
        }
    return false;
}

// IEC 61966-2-1 (sRGB), linear RGB to XYZ, D65.
const std::array<dvec3, 3>& ColourSpaces::xyz_from_rgb() {
    static const std::array<dvec3, 3> m{
        {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}}};
    return m;
}

// The exact inverse of the matrix above (rationals, rounded to double): 28154000/8687829, …
const std::array<dvec3, 3>& ColourSpaces::rgb_from_xyz() {
    static const std::array<dvec3, 3> m{{
        {3.2406254773200533, -1.5372079722103187, -0.4986285986982479},
        {-0.9689307147293194, 1.875756060885241, 0.04151752384295394},
        {0.05571012044551061, -0.2040210505984867, 1.0569959422543882},
    }};
    return m;
}

// NTSC, the FCC's matrix.
const std::array<dvec3, 3>& ColourSpaces::yiq_from_rgb() {
    static const std::array<dvec3, 3> m{
        {{0.299, 0.587, 0.114}, {0.596, -0.274, -0.322}, {0.211, -0.523, 0.312}}};
    return m;
}

// Its exact inverse: 121383/126947, 78889/126947; −34617/126947, −82111/126947;
// −140117/126947, 215889/126947 (the first column is exactly 1).
const std::array<dvec3, 3>& ColourSpaces::rgb_from_yiq() {
    static const std::array<dvec3, 3> m{{
        {1.0, 0.9561706854041451, 0.6214325663465856},
        {1.0, -0.2726886023301063, -0.6468132370201738},
        {1.0, -1.1037440821760263, 1.7006230946773062},
    }};
    return m;
}

namespace {

// ---- [conversions] --------------------------------------------------------------------------

enum Line {
    kLineEach = 1,
    kLineComplement,
    kLineChroma,
    kLineSector,
    kLineAddM,
    kLineInverse,
    kLineMaxMin,
    kLineHue,
    kLineSaturation,
    kLineMatrix,
    kLineResult,
};

bool is_hue(Space s) {
    return s == Space::Hsv || s == Space::Hsl;
}
bool is_linear(Space s) {
    return s == Space::Xyz || s == Space::Yiq;
}

// An angle in degrees, in [0, 360): H = 360 is H = 0.
double wrap_hue(double h) {
    double w = std::fmod(h, 360.0);
    if (w < 0) w += 360;
    return w >= 360 ? 0 : w;  // −1e-20 + 360 rounds to 360
}

double clamp01(double v) {
    return std::clamp(v, 0.0, 1.0);
}
dvec3 clamp01(const dvec3& v) {
    return {clamp01(v.x), clamp01(v.y), clamp01(v.z)};
}

void load(const Input& in, std::size_t k, Work& w) {
    w = {};
    w.src = in.colors[k];
    if (is_hue(in.from)) w.src.x = wrap_hue(w.src.x);
    if (in.from == Space::Rgb) w.rgb = w.src;
}

void from_complement(Work& w) {
    w.rgb = dvec3(1) - w.src;
}

void from_chroma(Space from, Work& w) {
    const double s = w.src.y, third = w.src.z;  // V or L
    w.chroma = from == Space::Hsv ? third * s : (1 - std::fabs(2 * third - 1)) * s;
    w.h_prime = w.src.x / 60;
    w.x = w.chroma * (1 - std::fabs(std::fmod(w.h_prime, 2.0) - 1));
}

void from_sector(Work& w) {
    w.sector = std::min(5, static_cast<int>(std::floor(w.h_prime)));
    const double c = w.chroma, x = w.x;
    static constexpr int kPattern[6][3] = {{2, 1, 0}, {1, 2, 0}, {0, 2, 1},
                                           {0, 1, 2}, {1, 0, 2}, {2, 0, 1}};  // 0: 0, 1: X, 2: C
    for (int i = 0; i < 3; ++i) {
        const int p = kPattern[w.sector][i];
        w.rgb1[i] = p == 2 ? c : p == 1 ? x : 0.0;
    }
}

void from_add_m(Space from, Work& w) {
    w.m = from == Space::Hsv ? w.src.z - w.chroma : w.src.z - w.chroma / 2;
    w.rgb = clamp01(w.rgb1 + w.m);  // rounding only: C + (V − C) may be V + 1 ulp
}

double row_value(Space space, bool forward, int row, const dvec3& v) {
    if (space == Space::Yiq && forward) {
        // The Y row sums to 1 and the I and Q rows to 0: in these forms a grey (R = G = B)
        // gives Y = G and I = Q = 0 exactly.
        if (row == 0) return v.y + 0.299 * (v.x - v.y) + 0.114 * (v.z - v.y);
        if (row == 1) return 0.596 * (v.x - v.y) + 0.322 * (v.y - v.z);
        if (row == 2) return 0.211 * (v.x - v.y) + 0.312 * (v.z - v.y);
    }
    const auto& m = space == Space::Xyz
                        ? (forward ? ColourSpaces::xyz_from_rgb() : ColourSpaces::rgb_from_xyz())
                        : (forward ? ColourSpaces::yiq_from_rgb() : ColourSpaces::rgb_from_yiq());
    return m[row].x * v.x + m[row].y * v.y + m[row].z * v.z;
}

void from_row(Space from, int row, Work& w) {
    w.unclamped[row] = row_value(from, false, row, w.src);
}

void from_gamut(Work& w) {
    const double tol = ColourSpaces::kGamutTolerance;
    for (int i = 0; i < 3; ++i)
        w.out_of_gamut = w.out_of_gamut || w.unclamped[i] < -tol || w.unclamped[i] > 1 + tol;
    w.rgb = clamp01(w.unclamped);
}

void to_complement(Work& w) {
    w.out = dvec3(1) - w.rgb;
}

void to_max_min(Work& w) {
    const dvec3 c = w.rgb;
    w.max = std::max({c.x, c.y, c.z});
    w.min = std::min({c.x, c.y, c.z});
    w.chroma = w.max - w.min;
    w.max_index = c.x == w.max ? 0 : c.y == w.max ? 1 : 2;  // ties: R, then G
}

void to_hue(Work& w) {
    const dvec3 c = w.rgb;
    double h = 0;
    if (w.chroma > 0) {
        if (w.max_index == 0) {
            h = (c.y - c.z) / w.chroma;
            if (h < 0) h += 6;
        } else if (w.max_index == 1) {
            h = (c.z - c.x) / w.chroma + 2;
        } else {
            h = (c.x - c.y) / w.chroma + 4;
        }
    }
    w.out.x = wrap_hue(60 * h);
}

void to_saturation(Space to, Work& w) {
    if (to == Space::Hsv) {
        w.out.z = w.max;
        w.out.y = w.max > 0 ? w.chroma / w.max : 0;
    } else {
        const double sum = w.max + w.min;
        w.out.z = sum / 2;
        double s = 0;
        if (w.chroma > 0) s = w.out.z <= 0.5 ? w.chroma / sum : w.chroma / (2 - w.max - w.min);
        w.out.y = clamp01(s);
    }
}

void to_row(Space to, int row, Work& w) {
    w.out[row] = row_value(to, true, row, w.rgb);
}

std::string triple(const dvec3& v, int digits = 6) {
    return num(v, digits);
}

std::string named(Space s, const dvec3& v, int digits = 6) {
    return std::string(s == Space::Rgb   ? "RGB"
                       : s == Space::Cmy ? "CMY"
                       : s == Space::Hsv ? "HSV"
                       : s == Space::Hsl ? "HSL"
                       : s == Space::Xyz ? "XYZ"
                                         : "YIQ") +
           " " + triple(v, digits);
}

const char* upper(Space s) {
    static const char* const k[] = {"RGB", "CMY", "HSV", "HSL", "XYZ", "YIQ"};
    return k[static_cast<int>(s)];
}

Phase first_to(Space to) {
    switch (to) {
        case Space::Rgb:
            return Phase::Result;
        case Space::Cmy:
            return Phase::ToComplement;
        case Space::Hsv:
        case Space::Hsl:
            return Phase::ToMaxMin;
        default:
            return Phase::ToRow;
    }
}

Phase first_from(const Input& in) {
    switch (in.from) {
        case Space::Rgb:
            return first_to(in.to);
        case Space::Cmy:
            return Phase::FromComplement;
        case Space::Hsv:
        case Space::Hsl:
            return Phase::FromChroma;
        default:
            return Phase::FromRow;
    }
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ColourSpaces::spec() {
    static const Spec spec{
        "colour-spaces",
        "Colour spaces",
        "Colour",
        {
            "for each colour: from its space to RGB, then from RGB to the wanted space",
            "CMY ↔ RGB:  (C, M, Y) = (1 − R, 1 − G, 1 − B)           ▷ the complement",
            "from HSV/HSL:  C ← V·S  (HSL: (1 − |2L − 1|)·S);  H′ ← H/60;  X ← C·(1 − |H′ mod 2 − "
            "1|)",
            "    sector ⌊H′⌋: (R1, G1, B1) ← (C,X,0) (X,C,0) (0,C,X) (0,X,C) (X,0,C) (C,0,X)",
            "    m ← V − C  (HSL: L − C/2);  (R, G, B) ← (R1 + m, G1 + m, B1 + m)",
            "from XYZ/YIQ:  (R, G, B) ← M⁻¹ · (…), row by row;  outside [0, 1]³: out of gamut, "
            "clamp",
            "to HSV/HSL:  max ← max(R, G, B),  min ← min(R, G, B),  C ← max − min",
            "    H ← 60·((G − B)/C mod 6) | 60·((B − R)/C + 2) | 60·((R − G)/C + 4) as max is R | "
            "G | B;  C = 0: H ← 0",
            "    HSV: V ← max, S ← C/V;   HSL: L ← (max + min)/2, S ← C/(1 − |2L − 1|);   grey: S "
            "← "
            "0",
            "to XYZ/YIQ:  M · (R, G, B), row by row",
            "the colour in the wanted space",
        },
        {
            {"complement", "CMY and RGB are complements: each component is 1 minus the other"},
            {"chroma", "from HSV/HSL: the chroma C, H′ = H/60 and the middle component X"},
            {"sector", "the hue's sector ⌊H′⌋ places C and X among (R1, G1, B1)"},
            {"add-m", "m is added to each component: the RGB"},
            {"matrix-row", "one row of a colour matrix times the colour"},
            {"in-gamut", "the RGB from XYZ/YIQ lies in the cube [0, 1]³"},
            {"out-of-gamut", "the RGB from XYZ/YIQ leaves the cube: clamped to it, and reported"},
            {"max-min", "the largest and smallest of R, G, B and the chroma between them"},
            {"hue", "the hue from the sector of the largest component"},
            {"grey", "chroma 0: a grey, whose hue is 0 by convention"},
            {"saturation", "V (or L) and the saturation S"},
            {"result", "the colour converted"},
        },
        {},  // no sliders
        {
            .predict = {
                {"max-min", {"C"}},
                {"hue", {"H"}},
                {"saturation", {"S"}},
                {"sector", {"X"}},
                {"add-m", {"RGB"}},
            },
            .mistakes = {
                {"saturation", "S", "copy:C", "forgot to divide the chroma by V"},
                {"saturation", "V", "copy:min",
                 "took V as the smallest component, not the largest"},
                {"grey", "", "event:hue", "worked out a hue for a grey, dividing by C = 0"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void ColourSpaces::validate(const Input& in) {
    if (in.colors.empty()) throw InputError("colors", "must list at least one colour [a, b, c]");
    if (in.colors.size() > kMaxColours)
        throw InputError("colors", "must list at most " + std::to_string(kMaxColours) +
                                       " colours (got " + std::to_string(in.colors.size()) + ")");
    for (std::size_t k = 0; k < in.colors.size(); ++k)
        for (int i = 0; i < 3; ++i) {
            const double v = in.colors[k][i];
            const std::string field =
                "colors[" + std::to_string(k) + "][" + std::to_string(i) + "]";
            const std::string what = std::string(upper(in.from)) + "'s " + component(in.from, i);
            if (!std::isfinite(v))
                throw InputError(field, "must be a finite number (got " + given(v) + ")");
            if (is_linear(in.from)) {
                if (std::fabs(v) > kMaxLinear)
                    throw InputError(field, what + " must lie within ±1e6 (got " + given(v) + ")");
            } else if (!(is_hue(in.from) && i == 0) && (v < 0 || v > 1)) {
                throw InputError(field, what + " must be in [0, 1] (got " + given(v) + ")");
            }
        }
}

ColourSpaces::State ColourSpaces::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.phase = first_from(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void ColourSpaces::advance(State& s) {
    const Input& in = *s.in;
    if (s.fresh) {      // a new colour
        if (s.k < 0) {  // the first: room for all (here, not in start: copies drop capacity)
            s.done.colors.reserve(in.colors.size());
            s.done.rgb.reserve(in.colors.size());
            s.done.out_of_gamut.reserve(in.colors.size());
        }
        ++s.k;
        load(in, static_cast<std::size_t>(s.k), s.w);
        s.row = 0;
        s.fresh = false;
    }
    Work& w = s.w;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::FromComplement:
            from_complement(w);
            s.phase = first_to(in.to);
            break;
        case Phase::FromChroma:
            from_chroma(in.from, w);
            s.phase = Phase::FromSector;
            break;
        case Phase::FromSector:
            from_sector(w);
            s.phase = Phase::FromAddM;
            break;
        case Phase::FromAddM:
            from_add_m(in.from, w);
            s.phase = first_to(in.to);
            break;
        case Phase::FromRow:
            from_row(in.from, s.row++, w);
            if (s.row == 3) s.phase = Phase::FromGamut;
            break;
        case Phase::FromGamut:
            from_gamut(w);
            s.phase = first_to(in.to);
            s.row = 0;
            break;
        case Phase::ToComplement:
            to_complement(w);
            s.phase = Phase::Result;
            break;
        case Phase::ToMaxMin:
            to_max_min(w);
            s.phase = Phase::ToHue;
            break;
        case Phase::ToHue:
            to_hue(w);
            s.phase = Phase::ToSaturation;
            break;
        case Phase::ToSaturation:
            to_saturation(in.to, w);
            s.phase = Phase::Result;
            break;
        case Phase::ToRow:
            to_row(in.to, s.row++, w);
            if (s.row == 3) s.phase = Phase::Result;
            break;
        case Phase::Result:
            if (in.to == Space::Rgb) w.out = w.rgb;
            s.done.colors.push_back(w.out);
            s.done.rgb.push_back(w.rgb);
            s.done.out_of_gamut.push_back(w.out_of_gamut);
            s.fresh = true;
            s.phase =
                static_cast<std::size_t>(s.k) + 1 < in.colors.size() ? first_from(in) : Phase::Done;
            break;
        case Phase::Done:
            break;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = ColourSpaces::State;

std::string colour_name(const State& s) {
    return "colors[" + std::to_string(s.k) + "] = " + named(s.in->from, s.in->colors[s.k]);
}

void narrate_complement(const State& s, StepInfo& info) {
    const Work& w = s.w;
    info.event = "complement";
    info.line = kLineComplement;
    const bool to_rgb = s.last == Phase::FromComplement;
    const dvec3 a = to_rgb ? w.src : w.rgb, b = to_rgb ? w.rgb : w.out;
    info.narration =
        (to_rgb ? colour_name(s) + ": RGB is its complement, (1 − C, 1 − M, 1 − Y) = "
                : "CMY is the complement of RGB " + triple(a) + ": (1 − R, 1 − G, 1 − B) = ") +
        triple(b) + ".";
    info.math = std::string(to_rgb ? "(R, G, B)" : "(C, M, Y)") + " = (1, 1, 1) - " + tex(a) +
                " = " + tex(b);
}

void narrate_chroma(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Work& w = s.w;
    info.event = "chroma";
    info.line = kLineChroma;
    const bool hsv = in.from == Space::Hsv;
    std::string wrapped;
    const double h_in = in.colors[s.k].x;
    if (h_in != w.src.x) wrapped = " (H = " + num(h_in) + "° is " + num(w.src.x) + "° modulo 360)";
    info.narration =
        colour_name(s) + wrapped + ": C = " +
        (hsv ? "V·S = " + num(w.src.z) + " · " + num(w.src.y)
             : "(1 − |2L − 1|)·S = (1 − |2·" + num(w.src.z) + " − 1|) · " + num(w.src.y)) +
        " = " + num(w.chroma) + ", H′ = H/60 = " + num(w.h_prime) +
        ", X = C·(1 − |H′ mod 2 − 1|) = " + num(w.x) + ".";
    info.math = std::string(hsv ? "C = V S" : "C = (1 - |2L - 1|) S") + " = " + tex(w.chroma) +
                ",\\; H' = \\frac{H}{60} = " + tex(w.h_prime) +
                ",\\; X = C(1 - |H' \\bmod 2 - 1|) = " + tex(w.x);
}

void narrate_sector(const State& s, StepInfo& info) {
    const Work& w = s.w;
    static const char* const kSectors[6] = {
        "red to yellow: (C, X, 0)", "yellow to green: (X, C, 0)", "green to cyan: (0, C, X)",
        "cyan to blue: (0, X, C)",  "blue to magenta: (X, 0, C)", "magenta to red: (C, 0, X)"};
    info.event = "sector";
    info.line = kLineSector;
    info.narration = "⌊H′⌋ = " + std::to_string(w.sector) + ", the sector from " +
                     kSectors[w.sector] + ", so (R1, G1, B1) = " + triple(w.rgb1) + ".";
    info.math = "\\lfloor H' \\rfloor = " + std::to_string(w.sector) +
                ":\\; (R_1, G_1, B_1) = " + tex(w.rgb1);
}

void narrate_add_m(const State& s, StepInfo& info) {
    const Work& w = s.w;
    const bool hsv = s.in->from == Space::Hsv;
    info.event = "add-m";
    info.line = kLineAddM;
    info.narration = std::string("m = ") +
                     (hsv ? "V − C = " + num(w.src.z) + " − " + num(w.chroma)
                          : "L − C/2 = " + num(w.src.z) + " − " + num(w.chroma) + "/2") +
                     " = " + num(w.m) + ", added to each: RGB = " + triple(w.rgb) + ".";
    info.math = std::string(hsv ? "m = V - C" : "m = L - \\tfrac{C}{2}") + " = " + tex(w.m) +
                ",\\; (R, G, B) = (R_1 + m, G_1 + m, B_1 + m) = " + tex(w.rgb);
}

std::string row_text(Space space, bool forward, int row, const dvec3& v, double value, Space left) {
    const auto& m = space == Space::Xyz
                        ? (forward ? ColourSpaces::xyz_from_rgb() : ColourSpaces::rgb_from_xyz())
                        : (forward ? ColourSpaces::yiq_from_rgb() : ColourSpaces::rgb_from_yiq());
    std::string t = std::string(ColourSpaces::component(left, row)) + " = ";
    for (int i = 0; i < 3; ++i) {
        const double c = m[row][i];
        t += (i == 0 ? (c < 0 ? "−" : "") : (c < 0 ? " − " : " + ")) + num(std::fabs(c), 5) + "·" +
             num(v[i]);
    }
    return t + " = " + num(value);
}

void narrate_row(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Work& w = s.w;
    const bool forward = s.last == Phase::ToRow;
    const int row = s.row - 1;
    const Space space = forward ? in.to : in.from;
    const dvec3 v = forward ? w.rgb : w.src;
    const double value = forward ? w.out[row] : w.unclamped[row];
    info.event = "matrix-row";
    info.line = forward ? kLineMatrix : kLineInverse;
    const std::string head =
        row == 0 ? (forward ? "RGB " + triple(w.rgb) + " to " + upper(space) + ", row by row: "
                            : colour_name(s) + " to RGB with the inverse matrix, row by row: ")
                 : "";
    std::string text = head + row_text(space, forward, row, v, value, forward ? space : Space::Rgb);
    static const char* const kYiqForms[3] = {
        " (as G + 0.299(R − G) + 0.114(B − G): the row sums to 1, so a grey keeps its value)",
        " (as 0.596(R − G) + 0.322(G − B): the row sums to 0, so a grey gives 0)",
        " (as 0.211(R − G) + 0.312(B − G): the row sums to 0, so a grey gives 0)"};
    if (forward && space == Space::Yiq) text += kYiqForms[row];
    info.narration = text + ".";
    info.math = std::string(ColourSpaces::component(forward ? space : Space::Rgb, row)) + " = " +
                tex(value);
}

void narrate_gamut(const State& s, StepInfo& info) {
    const Work& w = s.w;
    info.line = kLineInverse;
    if (w.out_of_gamut) {
        info.event = "out-of-gamut";
        std::string which;
        for (int i = 0; i < 3; ++i)
            if (w.unclamped[i] < -ColourSpaces::kGamutTolerance ||
                w.unclamped[i] > 1 + ColourSpaces::kGamutTolerance)
                which += std::string(which.empty() ? "" : ", ") +
                         ColourSpaces::component(Space::Rgb, i) + " = " + num(w.unclamped[i]);
        info.narration = "RGB " + triple(w.unclamped) + " leaves the cube [0, 1]³ (" + which +
                         "): this colour is out of the RGB gamut. Clamped to " + triple(w.rgb) +
                         ", and reported (out_of_gamut).";
    } else {
        info.event = "in-gamut";
        info.narration = "RGB " + triple(w.rgb) + " lies in the cube [0, 1]³: in the gamut.";
    }
    info.math = "(R, G, B) = " + tex(w.rgb);
}

void narrate_max_min(const State& s, StepInfo& info) {
    const Work& w = s.w;
    info.event = "max-min";
    info.line = kLineMaxMin;
    const std::string head = s.in->from == Space::Rgb ? colour_name(s) : "RGB " + triple(w.rgb);
    info.narration = head + ": max = " + num(w.max) + " (" +
                     ColourSpaces::component(Space::Rgb, w.max_index) + "), min = " + num(w.min) +
                     ", chroma C = max − min = " + num(w.chroma) + ".";
    info.math = "\\max = " + tex(w.max) + ",\\; \\min = " + tex(w.min) +
                ",\\; C = \\max - \\min = " + tex(w.chroma);
}

void narrate_hue(const State& s, StepInfo& info) {
    const Work& w = s.w;
    info.line = kLineHue;
    if (w.chroma == 0) {
        info.event = "grey";
        info.narration =
            "C = 0: R = G = B, a grey on the axis of the cone. It has no hue; by "
            "convention H = 0 (and S = 0).";
        info.math = "C = 0 \\Rightarrow H = 0";
        return;
    }
    info.event = "hue";
    const dvec3 c = w.rgb;
    std::string formula;
    if (w.max_index == 0)
        formula = "max is R: H = 60·((G − B)/C mod 6) = 60·((" + num(c.y) + " − " + num(c.z) +
                  ")/" + num(w.chroma) + " mod 6)";
    else if (w.max_index == 1)
        formula = "max is G: H = 60·((B − R)/C + 2) = 60·((" + num(c.z) + " − " + num(c.x) + ")/" +
                  num(w.chroma) + " + 2)";
    else
        formula = "max is B: H = 60·((R − G)/C + 4) = 60·((" + num(c.x) + " − " + num(c.y) + ")/" +
                  num(w.chroma) + " + 4)";
    info.narration = formula + " = " + num(w.out.x) + "°.";
    info.math = "H = " + tex(w.out.x) + "°";
}

void narrate_saturation(const State& s, StepInfo& info) {
    const Work& w = s.w;
    info.event = "saturation";
    info.line = kLineSaturation;
    if (s.in->to == Space::Hsv) {
        info.narration = "V = max = " + num(w.out.z) + ", S = C/V = " +
                         (w.max > 0 ? num(w.chroma) + "/" + num(w.max) + " = " + num(w.out.y)
                                    : "0 (V = 0: black, S = 0 by convention)") +
                         ".";
        info.math = "V = " + tex(w.out.z) + ",\\; S = \\frac{C}{V} = " + tex(w.out.y);
    } else {
        info.narration = "L = (max + min)/2 = " + num(w.out.z) + ", S = C/(1 − |2L − 1|) = " +
                         (w.chroma > 0 ? num(w.chroma) + "/" + num(1 - std::fabs(2 * w.out.z - 1)) +
                                             " = " + num(w.out.y)
                                       : "0 (a grey: S = 0 by convention)") +
                         ".";
        info.math = "L = " + tex(w.out.z) + ",\\; S = \\frac{C}{1 - |2L - 1|} = " + tex(w.out.y);
    }
}

void narrate_result(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "result";
    info.line = kLineResult;
    const dvec3 out = s.done.colors.back();
    info.narration = colour_name(s) + " is " + named(in.to, out) +
                     (s.w.out_of_gamut ? " (out of the RGB gamut: clamped first)" : "") + ".";
    info.math = std::string("(") + ColourSpaces::component(in.to, 0) + ", " +
                ColourSpaces::component(in.to, 1) + ", " + ColourSpaces::component(in.to, 2) +
                ") = " + tex(out);
}

void fill_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Work& w = s.w;
    info.vars = {{"k", static_cast<long long>(s.k)}, {"input", vec(in.colors[s.k])}};
    switch (s.last) {
        case Phase::FromChroma:
        case Phase::FromSector:
        case Phase::FromAddM:
            info.vars.push_back({"C", w.chroma});
            info.vars.push_back({"H'", w.h_prime});
            info.vars.push_back({"X", w.x});
            if (s.last >= Phase::FromSector) {
                info.vars.push_back({"sector", static_cast<long long>(w.sector)});
                info.vars.push_back({"(R1, G1, B1)", vec(w.rgb1)});
            }
            if (s.last == Phase::FromAddM) info.vars.push_back({"m", w.m});
            break;
        case Phase::FromRow:
        case Phase::FromGamut: {
            std::vector<double> part;
            for (int i = 0; i < (s.last == Phase::FromRow ? s.row : 3); ++i)
                part.push_back(w.unclamped[i]);
            info.vars.push_back({"RGB (unclamped)", part});
            if (s.last == Phase::FromGamut) info.vars.push_back({"out_of_gamut", w.out_of_gamut});
            break;
        }
        case Phase::ToMaxMin:
        case Phase::ToHue:
        case Phase::ToSaturation:
            info.vars.push_back({"max", w.max});
            info.vars.push_back({"min", w.min});
            info.vars.push_back({"C", w.chroma});
            if (s.last >= Phase::ToHue) info.vars.push_back({"H", w.out.x});
            if (s.last == Phase::ToSaturation) {
                info.vars.push_back({"S", w.out.y});
                info.vars.push_back({in.to == Space::Hsv ? "V" : "L", w.out.z});
            }
            break;
        case Phase::ToRow: {
            std::vector<double> part;
            for (int i = 0; i < s.row; ++i) part.push_back(w.out[i]);
            info.vars.push_back({std::string(upper(in.to)) + " (so far)", part});
            break;
        }
        default:
            break;
    }
    if (s.last >= Phase::ToComplement || s.last == Phase::FromComplement ||
        s.last == Phase::FromAddM || s.last == Phase::FromGamut)
        info.vars.push_back({"RGB", vec(w.rgb)});
    if (s.last == Phase::Result || s.last == Phase::ToComplement)
        info.vars.push_back(
            {upper(in.to), vec(s.last == Phase::Result ? s.done.colors.back() : w.out)});
}

}  // namespace

void ColourSpaces::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::FromComplement:
        case Phase::ToComplement:
            narrate_complement(s, info);
            break;
        case Phase::FromChroma:
            narrate_chroma(s, info);
            break;
        case Phase::FromSector:
            narrate_sector(s, info);
            break;
        case Phase::FromAddM:
            narrate_add_m(s, info);
            break;
        case Phase::FromRow:
        case Phase::ToRow:
            narrate_row(s, info);
            break;
        case Phase::FromGamut:
            narrate_gamut(s, info);
            break;
        case Phase::ToMaxMin:
            narrate_max_min(s, info);
            break;
        case Phase::ToHue:
            narrate_hue(s, info);
            break;
        case Phase::ToSaturation:
            narrate_saturation(s, info);
            break;
        case Phase::Result:
        case Phase::Done:
            narrate_result(s, info);
            break;
    }
    fill_vars(s, info);
}

void ColourSpaces::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [convert] ------------------------------------------------------------------------------

ColourSpaces::Result ColourSpaces::convert(const Input& in) {
    Result r;
    r.colors.reserve(in.colors.size());
    r.rgb.reserve(in.colors.size());
    r.out_of_gamut.reserve(in.colors.size());
    Work w;
    for (std::size_t k = 0; k < in.colors.size(); ++k) {
        load(in, k, w);
        switch (in.from) {
            case Space::Rgb:
                break;
            case Space::Cmy:
                from_complement(w);
                break;
            case Space::Hsv:
            case Space::Hsl:
                from_chroma(in.from, w);
                from_sector(w);
                from_add_m(in.from, w);
                break;
            case Space::Xyz:
            case Space::Yiq:
                for (int row = 0; row < 3; ++row) from_row(in.from, row, w);
                from_gamut(w);
                break;
        }
        switch (in.to) {
            case Space::Rgb:
                w.out = w.rgb;
                break;
            case Space::Cmy:
                to_complement(w);
                break;
            case Space::Hsv:
            case Space::Hsl:
                to_max_min(w);
                to_hue(w);
                to_saturation(in.to, w);
                break;
            case Space::Xyz:
            case Space::Yiq:
                for (int row = 0; row < 3; ++row) to_row(in.to, row, w);
                break;
        }
        r.colors.push_back(w.out);
        r.rgb.push_back(w.rgb);
        r.out_of_gamut.push_back(w.out_of_gamut);
    }
    return r;
}

}  // namespace cg
