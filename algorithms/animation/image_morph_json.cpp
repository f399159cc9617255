// Image morphing, JSON:
//   input  {"image_a": [[row 0], [row 1], …] (grey values, row 0 at the top, ≤ 128 × 128)
//                      or {"pattern": "disc" | "square" | "bar" | "column" | "cross" | "ramp", "size": n},
//           "image_b": likewise, the same size,
//           "lines": [{"a": [P, Q], "b": [P', Q']}, …] (1 to 32 feature line pairs, points
//                    [x, y] in pixels: pixel (c, r) has its centre at (c + 0.5, r + 0.5)),
//           "params": {"a": 0.5, "b": 2, "p": 0.5} (w = (length^p / (a + dist))^b),
//           "alphas": [α, …] (0 to 1, 1 to 120 frames) or "frames": n (2 to 120: α = k/(n − 1)),
//           default "frames": 5,
//           "focus": [column, row] (the pixel narrated on each row and reported, default the
//           middle)}
//   result {"frames": [{"alpha", "lines", "warped_a", "warped_b", "morph", "dissolve"}],
//           "focus": {"x", "y", "X", "alpha", "a": {"terms": [{"used", "u", "v", "source",
//                     "displacement", "dist", "weight"}], "source", "value"}, "b": likewise,
//                     "morph", "dissolve"} (in the last frame),
//           "difference": the largest over the frames of mean |morph − dissolve|}
#include "animation/image_morph.hpp"
#include "core/format.hpp"
#include "io/registry.hpp"

namespace cg {

namespace image_morph_json {

using Image = ImageMorph::Image;

Image image(const json& v, const std::string& field, std::string& pattern) {
    Image img;
    if (v.is_object()) {
        const Reader p(v, field);
        p.only({"pattern", "size"});
        pattern = p.string("pattern");
        const int n = int(p.integer("size", 1, ImageMorph::kMaxSide,
                                    "1 to " + std::to_string(ImageMorph::kMaxSide) + " pixels"));
        try {
            return ImageMorph::pattern_image(pattern, n);
        } catch (const InputError& e) {
            throw InputError(p.field("pattern"), std::string(e.what()).substr(9));
        }
    }
    if (!v.is_array() || v.empty())
        throw InputError(field, "must be a list of rows (lists of grey values) or {\"pattern\", "
                                "\"size\"}, got " + describe(v));
    if (v.size() > std::size_t(ImageMorph::kMaxSide))
        throw InputError(field, "has " + std::to_string(v.size()) + " rows; at most " +
                                    std::to_string(ImageMorph::kMaxSide));
    img.height = int(v.size());
    for (std::size_t r = 0; r < v.size(); ++r) {
        const std::string rf = element(field, r);
        const json& row = v[r];
        if (!row.is_array() || row.empty())
            throw InputError(rf, "must be a row (a list of grey values), got " + describe(row));
        if (row.size() > std::size_t(ImageMorph::kMaxSide))
            throw InputError(rf, "has " + std::to_string(row.size()) + " pixels; at most " +
                                     std::to_string(ImageMorph::kMaxSide));
        if (r == 0) img.width = int(row.size());
        if (row.size() != std::size_t(img.width))
            throw InputError(rf, "has " + std::to_string(row.size()) + " pixels, row 0 has " +
                                     std::to_string(img.width) + ": the rows must be equally long");
        for (std::size_t c = 0; c < row.size(); ++c) img.v.push_back(as_number(row[c], element(rf, c)));
    }
    return img;
}

ImageMorph::Line line(const json& v, const std::string& field) {
    if (!v.is_array() || v.size() != 2)
        throw InputError(field, "must be a line [P, Q] of two points [x, y], got " + describe(v));
    return {as_point2(v[0], element(field, 0)), as_point2(v[1], element(field, 1))};
}

json rows(const Image& img) {
    json out = json::array();
    for (int r = 0; r < img.height; ++r)
        out.push_back(std::vector<double>(img.v.begin() + std::ptrdiff_t(r) * img.width,
                                          img.v.begin() + std::ptrdiff_t(r + 1) * img.width));
    return out;
}

json side(const ImageMorph::Side& s) {
    json terms = json::array();
    for (const auto& t : s.terms)
        terms.push_back({{"used", t.used},
                         {"u", t.u},
                         {"v", t.v},
                         {"source", to_json(t.source)},
                         {"displacement", to_json(t.displacement)},
                         {"dist", t.dist},
                         {"weight", t.weight}});
    return {{"terms", terms}, {"source", to_json(s.source)}, {"value", s.value}};
}

}  // namespace image_morph_json

template <>
struct JsonIo<ImageMorph> {
    static ImageMorph::Input input(const json& j) {
        namespace im = image_morph_json;
        Reader r(j);
        r.only({"image_a", "image_b", "lines", "params", "alphas", "frames", "focus"});
        ImageMorph::Input in;
        in.image_a = im::image(r.get("image_a"), r.field("image_a"), in.pattern_a);
        in.image_b = im::image(r.get("image_b"), r.field("image_b"), in.pattern_b);
        const json& ls = r.get("lines");
        const std::string lf = r.field("lines");
        if (!ls.is_array())
            throw InputError(lf, "must be a list of line pairs {\"a\": [P, Q], \"b\": [P', Q']}, "
                                 "got " + describe(ls));
        if (ls.size() > std::size_t(ImageMorph::kMaxLines))
            throw InputError(lf, "has " + std::to_string(ls.size()) + " pairs; at most " +
                                     std::to_string(ImageMorph::kMaxLines));
        for (std::size_t i = 0; i < ls.size(); ++i) {
            const Reader l(ls[i], element(lf, i));
            l.only({"a", "b"});
            in.lines.push_back(
                {im::line(l.get("a"), l.field("a")), im::line(l.get("b"), l.field("b"))});
        }
        if (r.has("params")) {
            const Reader p = r.object("params");
            p.only({"a", "b", "p"});
            if (p.has("a")) in.params.a = p.number("a");
            if (p.has("b")) in.params.b = p.number("b");
            if (p.has("p")) in.params.p = p.number("p");
        }
        if (r.has("alphas") && r.has("frames"))
            throw InputError(r.field("frames"), "give either \"alphas\" or \"frames\", not both");
        if (r.has("alphas")) {
            const json& as = r.get("alphas");
            const std::string af = r.field("alphas");
            if (!as.is_array()) throw InputError(af, "must be a list of α values, got " + describe(as));
            if (as.size() > std::size_t(ImageMorph::kMaxFrames))
                throw InputError(af, "has " + std::to_string(as.size()) + " frames; at most " +
                                         std::to_string(ImageMorph::kMaxFrames));
            for (std::size_t k = 0; k < as.size(); ++k) in.alphas.push_back(as_number(as[k], element(af, k)));
        } else {
            const int n = r.has("frames")
                              ? int(r.integer("frames", 2, ImageMorph::kMaxFrames,
                                              "2 to " + std::to_string(ImageMorph::kMaxFrames)))
                              : 5;
            for (int k = 0; k < n; ++k) in.alphas.push_back(k == n - 1 ? 1.0 : double(k) / (n - 1));
        }
        if (r.has("focus")) {
            const json& f = r.get("focus");
            const std::string ff = r.field("focus");
            if (!f.is_array() || f.size() != 2 || !f[0].is_number_integer() ||
                !f[1].is_number_integer())
                throw InputError(ff, "must be a pixel [column, row] of two integers, got " +
                                         describe(f));
            const long long x = f[0].get<long long>(), y = f[1].get<long long>();
            if (x < 0 || x > ImageMorph::kMaxSide || y < 0 || y > ImageMorph::kMaxSide)
                throw InputError(ff, "must be a pixel inside the image, got [" +
                                         std::to_string(x) + ", " + std::to_string(y) + "]");
            in.focus_x = int(x);
            in.focus_y = int(y);
        }
        return in;
    }

    static json input_json(const ImageMorph::Input& in) {
        namespace im = image_morph_json;
        json j;
        j["image_a"] = in.pattern_a.empty()
                           ? im::rows(in.image_a)
                           : json{{"pattern", in.pattern_a}, {"size", in.image_a.width}};
        j["image_b"] = in.pattern_b.empty()
                           ? im::rows(in.image_b)
                           : json{{"pattern", in.pattern_b}, {"size", in.image_b.width}};
        json ls = json::array();
        for (const auto& p : in.lines)
            ls.push_back({{"a", {nice_point(p.a.p), nice_point(p.a.q)}},
                          {"b", {nice_point(p.b.p), nice_point(p.b.q)}}});
        j["lines"] = ls;
        j["params"] = {{"a", nice_number(in.params.a)},
                       {"b", nice_number(in.params.b)},
                       {"p", nice_number(in.params.p)}};
        json as = json::array();
        for (double a : in.alphas) as.push_back(nice_number(a));
        j["alphas"] = as;
        if (in.focus_x != -1 || in.focus_y != -1)
            j["focus"] = {in.focus_x == -1 ? in.image_a.width / 2 : in.focus_x,
                          in.focus_y == -1 ? in.image_a.height / 2 : in.focus_y};
        return j;
    }

    static json result(const ImageMorph::Result& r) {
        namespace im = image_morph_json;
        json j;
        json fs = json::array();
        for (const auto& f : r.frames) {
            json ls = json::array();
            for (const auto& l : f.lines) ls.push_back({to_json(l.p), to_json(l.q)});
            fs.push_back({{"alpha", f.alpha},
                          {"lines", ls},
                          {"warped_a", im::rows(f.warped_a)},
                          {"warped_b", im::rows(f.warped_b)},
                          {"morph", im::rows(f.morph)},
                          {"dissolve", im::rows(f.dissolve)}});
        }
        j["frames"] = fs;
        const auto& p = r.focus;
        j["focus"] = {{"x", p.x},
                      {"y", p.y},
                      {"X", to_json(p.centre)},
                      {"alpha", p.alpha},
                      {"a", im::side(p.a)},
                      {"b", im::side(p.b)},
                      {"morph", p.morph},
                      {"dissolve", p.dissolve}};
        j["difference"] = r.difference;
        return j;
    }

    static json example() {
        // The exam-style case: a 4 × 4 image with a bright column, one feature line moved two
        // pixels right in B; half way, the column sits one pixel right, not smeared over two.
        return parse_json(R"({
            "image_a": [[0, 200, 0, 0], [0, 200, 0, 0], [0, 200, 0, 0], [0, 200, 0, 0]],
            "image_b": [[0, 0, 0, 100], [0, 0, 0, 100], [0, 0, 0, 100], [0, 0, 0, 100]],
            "lines": [{"a": [[1.5, 0.5], [1.5, 3.5]], "b": [[3.5, 0.5], [3.5, 3.5]]}],
            "alphas": [0, 0.5, 1], "focus": [2, 1]})");
    }
};

Algorithm image_morph_algorithm() {
    return make_algorithm<ImageMorph>(
        [](const ImageMorph::Input& in) { return ImageMorph::compute(in); });
}

}  // namespace cg
