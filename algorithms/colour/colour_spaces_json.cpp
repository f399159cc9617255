// Colour spaces, JSON:
//   input  {"from": space, "to": space, "colors": [[a, b, c], …]} with space one of "rgb",
//          "cmy", "hsv", "hsl", "xyz", "yiq" (HSV and HSL as [H in degrees, S, V or L])
//   result {"colors": [[…], …] (in the `to` space; H in [0, 360)),
//           "rgb": [[R, G, B], …] (the RGB each went through, in [0, 1]),
//           "out_of_gamut": [bool, …] (an XYZ or YIQ input outside the RGB cube, clamped)}
#include "colour/colour_spaces.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

ColourSpaces::Space space(const Reader& r, const char* key) {
    const json& v = r.get(key);
    if (!v.is_string())
        throw InputError(
            key, "must be a colour space (rgb, cmy, hsv, hsl, xyz or yiq), got " + describe(v));
    ColourSpaces::Space s;
    if (!ColourSpaces::parse(v.get<std::string>(), s))
        throw InputError(
            key, "must be one of rgb, cmy, hsv, hsl, xyz, yiq (lower case), got " + describe(v));
    return s;
}

}  // namespace

template <>
struct JsonIo<ColourSpaces> {
    static ColourSpaces::Input input(const json& j) {
        Reader r(j);
        r.only({"from", "to", "colors"});
        ColourSpaces::Input in;
        in.from = space(r, "from");
        in.to = space(r, "to");
        const json& c = r.get("colors");
        if (!c.is_array())
            throw InputError("colors", "must be a list of colours [a, b, c], got " + describe(c));
        if (c.size() > ColourSpaces::kMaxColours)  // before reading a huge list
            throw InputError("colors", "must list at most " +
                                           std::to_string(ColourSpaces::kMaxColours) +
                                           " colours (got " + std::to_string(c.size()) + ")");
        for (std::size_t k = 0; k < c.size(); ++k) {
            const std::string field = "colors[" + std::to_string(k) + "]";
            const json& v = c[k];
            if (!v.is_array() || v.size() != 3)
                throw InputError(field, "must be a colour of three numbers [" +
                                            std::string(ColourSpaces::component(in.from, 0)) +
                                            ", " + ColourSpaces::component(in.from, 1) + ", " +
                                            ColourSpaces::component(in.from, 2) + "], got " +
                                            describe(v));
            glm::dvec3 p;
            for (int i = 0; i < 3; ++i)
                p[i] = as_number(v[i], field + "[" + std::to_string(i) + "]");
            in.colors.push_back(p);
        }
        return in;
    }

    static json input_json(const ColourSpaces::Input& in) {
        json colors = json::array();
        for (const auto& c : in.colors) colors.push_back(nice_point(c));
        return json{{"from", ColourSpaces::name(in.from)},
                    {"to", ColourSpaces::name(in.to)},
                    {"colors", std::move(colors)}};
    }

    static json result(const ColourSpaces::Result& r) {
        json colors = json::array(), rgb = json::array(), gamut = json::array();
        for (const auto& c : r.colors) colors.push_back(to_json(c));
        for (const auto& c : r.rgb) rgb.push_back(to_json(c));
        for (bool b : r.out_of_gamut) gamut.push_back(b);
        return json{{"colors", std::move(colors)},
                    {"rgb", std::move(rgb)},
                    {"out_of_gamut", std::move(gamut)}};
    }

    static json example() {
        // The exam's colour, a primary, a grey.
        return json{{"from", "rgb"},
                    {"to", "hsv"},
                    {"colors", {{0.3, 0.8, 0.5}, {1, 0, 0}, {0.5, 0.5, 0.5}}}};
    }
};

Algorithm colour_spaces_algorithm() {
    return make_algorithm<ColourSpaces>(
        [](const ColourSpaces::Input& in) { return ColourSpaces::convert(in); });
}

}  // namespace cg
