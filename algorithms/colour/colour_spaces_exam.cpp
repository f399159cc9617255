// Colour-space exam problems: one colour (now and then two) in simple numbers — RGB, CMY and
// the S, V, L of HSV and HSL in tenths, hues in multiples of 15° — converted RGB → HSV (the
// classic, about a quarter of the problems), HSV → RGB, RGB ↔ HSL, RGB ↔ CMY, RGB → YIQ and
// RGB → XYZ (the matrix given in the question). Greys and primaries come up on their own.
#include "colour/colour_spaces.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using Space = ColourSpaces::Space;

double tenth(Rng& rng) {
    return rng.integer(0, 10) / 10.0;
}

std::string upper(Space s) {
    std::string t = ColourSpaces::name(s);
    for (char& c : t) c = static_cast<char>(c - 'a' + 'A');
    return t;
}

std::string components(Space s) {
    return std::string("[") + ColourSpaces::component(s, 0) + ", " + ColourSpaces::component(s, 1) +
           ", " + ColourSpaces::component(s, 2) + "]";
}

}  // namespace

ColourSpaces::Input ColourSpaces::exam_input(Rng& rng) {
    struct Direction {
        Space from, to;
        double weight;
    };
    static constexpr Direction kDirections[] = {
        {Space::Rgb, Space::Hsv, 0.25}, {Space::Hsv, Space::Rgb, 0.17},
        {Space::Rgb, Space::Hsl, 0.12}, {Space::Hsl, Space::Rgb, 0.10},
        {Space::Rgb, Space::Cmy, 0.05}, {Space::Cmy, Space::Rgb, 0.05},
        {Space::Rgb, Space::Yiq, 0.13}, {Space::Rgb, Space::Xyz, 0.13}};
    double pick = rng.uniform(0, 1);
    Direction d = kDirections[0];
    for (const Direction& c : kDirections) {
        d = c;
        if ((pick -= c.weight) < 0) break;
    }
    Input in{d.from, d.to, {}};
    const int n = rng.chance(0.2) ? 2 : 1;
    for (int k = 0; k < n; ++k) {
        if (d.from == Space::Hsv || d.from == Space::Hsl)
            in.colors.push_back({15.0 * rng.integer(0, 23), tenth(rng), tenth(rng)});
        else
            in.colors.push_back({tenth(rng), tenth(rng), tenth(rng)});
    }
    return in;
}

std::string ColourSpaces::question(const Input& in) {
    std::string colours;
    for (std::size_t k = 0; k < in.colors.size(); ++k)
        colours += std::string(k ? " and " : "") + num(in.colors[k]);
    std::string q = "Convert " + colours + " from " + upper(in.from) + " " + components(in.from) +
                    " to " + upper(in.to) + ". Give colors: a list with each converted colour as " +
                    components(in.to) + ".";
    if (in.to == Space::Hsv || in.to == Space::Hsl || in.from == Space::Hsv ||
        in.from == Space::Hsl)
        q += " Hues are in degrees, in [0, 360); a grey has H = 0 and S = 0.";
    if (in.to == Space::Xyz)
        q += " Use linear sRGB with D65 white: X = 0.4124 R + 0.3576 G + 0.1805 B, "
             "Y = 0.2126 R + 0.7152 G + 0.0722 B, Z = 0.0193 R + 0.1192 G + 0.9505 B.";
    if (in.to == Space::Yiq)
        q += " Use the NTSC matrix: Y = 0.299 R + 0.587 G + 0.114 B, I = 0.596 R − 0.274 G − "
             "0.322 B, Q = 0.211 R − 0.523 G + 0.312 B.";
    return q;
}

std::vector<std::string> ColourSpaces::answer_fields() {
    return {"colors"};
}

}  // namespace cg
