// Sections: [image files] [textures] [heights] [solid textures] [surfaces] [paths]
#include "rays/texture_json.hpp"

#include <stb_image.h>  // the implementation is in libstb

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "rays/rays_json.hpp"

namespace cg::texture_json {

using glm::dvec3;

namespace {

TexColor colour_value(const json& v, const std::string& field) {
    if (v.is_number()) return TexColor(as_number(v, field));
    if (v.is_array() && v.size() == 3) return as_point3(v, field);
    throw InputError(field, "must be a colour: a number (grey) or [r, g, b], got " + describe(v));
}

int whole(const Reader& r, const char* key, int lo, int hi, const char* what) {
    const long long n = r.integer(key);
    if (n < lo || n > hi)
        throw InputError(r.field(key), std::string("must be ") + what + " from " +
                                           std::to_string(lo) + " to " + std::to_string(hi) +
                                           " (got " + std::to_string(n) + ")");
    return static_cast<int>(n);
}

}  // namespace

// ---- [image files] --------------------------------------------------------------------------

TextureImage read_image_file(const std::string& path, const std::string& field) {
    // Only regular files: a directory, a device or a pipe (which could block) is refused.
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw InputError(field, "cannot read \"" + path + "\": not a regular file");
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f)
        throw InputError(field, "cannot read \"" + path + "\": " +
                                    (errno == ENOENT ? std::string("no such file")
                                                     : std::string(std::strerror(errno))));
    int w = 0, h = 0, n = 0;
    // The size first, from the header: an oversized image is refused before it is decoded.
    if (!stbi_info_from_file(f, &w, &h, &n)) {
        std::fclose(f);
        throw InputError(field, "cannot read \"" + path + "\": not an image stb_image can read (" +
                                    stbi_failure_reason() + ")");
    }
    if (w < 1 || h < 1 || w > kMaxTextureSide || h > kMaxTextureSide ||
        static_cast<long long>(w) * h > kMaxTexels) {
        std::fclose(f);
        throw InputError(field, "\"" + path + "\" is " + std::to_string(w) + "×" +
                                    std::to_string(h) +
                                    " pixels; the limit is 4096 on a side and 2048 × 2048 in all");
    }
    unsigned char* data = stbi_load_from_file(f, &w, &h, &n, 3);
    std::fclose(f);
    if (!data) throw InputError(field, "cannot read \"" + path + "\": " + stbi_failure_reason());
    TextureImage im;
    im.width = w;
    im.height = h;
    im.texels.resize(static_cast<std::size_t>(w) * h);
    for (int row = 0; row < h; ++row)  // the file's first row is the top: v = 1
        for (int i = 0; i < w; ++i) {
            const unsigned char* p = data + (static_cast<std::size_t>(row) * w + i) * 3;
            im.texels[static_cast<std::size_t>(h - 1 - row) * w + i] =
                TexColor(p[0], p[1], p[2]) / 255.0;
        }
    stbi_image_free(data);
    return im;
}

// ---- [textures] -----------------------------------------------------------------------------

void image_source(const Reader& r, Texture& t) {
    const int given = r.has("image") + r.has("grid") + r.has("checker");
    if (given != 1)
        throw InputError(r.path(),
                         "needs exactly one of \"image\" (a file), \"grid\" (texels "
                         "inline) and \"checker\"");
    if (r.has("image")) {
        t.source = r.string("image");
        if (t.source.empty()) throw InputError(r.field("image"), "must name an image file");
        t.image = read_image_file(t.source, r.field("image"));
    } else if (r.has("grid")) {
        const Reader g = r.object("grid");
        g.only({"width", "height", "texels"});
        const int w = whole(g, "width", 1, kMaxTextureSide, "a number of texels");
        const int h = whole(g, "height", 1, kMaxTextureSide, "a number of texels");
        const json& rows = g.get("texels");
        if (!rows.is_array() || rows.size() != static_cast<std::size_t>(h))
            throw InputError(g.field("texels"), "must be " + std::to_string(h) +
                                                    " rows (the height), got " + describe(rows));
        t.source = "grid";
        t.image.width = w;
        t.image.height = h;
        t.image.texels.resize(static_cast<std::size_t>(w) * h);
        for (int row = 0; row < h; ++row) {
            const std::string rf = element(g.field("texels"), row);
            const json& rv = rows[row];
            if (!rv.is_array() || rv.size() != static_cast<std::size_t>(w))
                throw InputError(rf, "must be a row of " + std::to_string(w) +
                                         " colours (the width), got " + describe(rv));
            for (int i = 0; i < w; ++i)  // the first row is the top: v = 1
                t.image.texels[static_cast<std::size_t>(h - 1 - row) * w + i] =
                    colour_value(rv[i], element(rf, i));
        }
    } else {
        const Reader c = r.object("checker");
        c.only({"size", "colors"});
        glm::ivec2 n{8, 8};
        if (c.has("size")) {
            const json& v = c.get("size");
            if (v.is_array()) {
                if (v.size() != 2)
                    throw InputError(c.field("size"),
                                     "must be n or [n_u, n_v], got " + describe(v));
                for (int k = 0; k < 2; ++k) {
                    const double x = as_number(v[k], element(c.field("size"), k));
                    if (x != std::floor(x) || x < 1 || x > kMaxTextureSide)
                        throw InputError(element(c.field("size"), k),
                                         "must be a whole number of squares from 1 to 4096");
                    n[k] = static_cast<int>(x);
                }
            } else {
                n = glm::ivec2(whole(c, "size", 1, kMaxTextureSide, "a number of squares"));
            }
        }
        std::array<TexColor, 2> colors{TexColor(0.1), TexColor(0.9)};
        if (c.has("colors")) {
            const json& v = c.get("colors");
            if (!v.is_array() || v.size() != 2)
                throw InputError(c.field("colors"),
                                 "must be two colours [c0, c1], got " + describe(v));
            for (int k = 0; k < 2; ++k) colors[k] = colour_value(v[k], element(c.field("colors"), k));
        }
        if (static_cast<long long>(n.x) * n.y > kMaxTexels)
            throw InputError(c.field("size"), "makes more than 2048 × 2048 squares");
        t.source = "checker";
        t.checker_size = n;
        t.checker_colors = colors;
        t.image = checker_image(n.x, n.y, colors[0], colors[1]);
    }
    if (r.has("wrap")) {
        const std::string w = r.string("wrap");
        if (w == "repeat")
            t.wrap = TexWrap::Repeat;
        else if (w == "clamp")
            t.wrap = TexWrap::Clamp;
        else
            throw InputError(r.field("wrap"),
                             "must be \"repeat\" or \"clamp\" (got \"" + w + "\")");
    }
}

Texture texture(const Reader& r, std::initializer_list<const char*> extra) {
    for (auto it = r.value().begin(); it != r.value().end(); ++it) {
        static const char* known[] = {"image", "grid", "checker", "filter", "wrap"};
        bool ok =
            std::any_of(std::begin(known), std::end(known),
                        [&](const char* k) { return it.key() == k; }) ||
            std::any_of(extra.begin(), extra.end(), [&](const char* k) { return it.key() == k; });
        if (!ok)
            throw InputError(r.field(it.key().c_str()),
                             "is not a field of a texture (image, grid, checker, filter, wrap)");
    }
    Texture t;
    image_source(r, t);
    if (r.has("filter")) {
        const std::string f = r.string("filter");
        if (f == "nearest")
            t.filter = TexFilter::Nearest;
        else if (f == "bilinear")
            t.filter = TexFilter::Bilinear;
        else if (f == "mipmap")
            t.filter = TexFilter::Mipmap;
        else
            throw InputError(r.field("filter"),
                             "must be \"nearest\", \"bilinear\" or \"mipmap\" (got \"" + f + "\")");
    }
    return t;
}

void image_source_json(const Texture& t, json& j) {
    if (t.source == "checker") {
        j["checker"] =
            json{{"size", {t.checker_size.x, t.checker_size.y}},
                 {"colors", {nice_point(t.checker_colors[0]), nice_point(t.checker_colors[1])}}};
    } else if (t.source == "grid") {
        json rows = json::array();
        for (int row = t.image.height - 1; row >= 0; --row) {
            json rv = json::array();
            for (int i = 0; i < t.image.width; ++i) rv.push_back(nice_point(t.image.at(i, row)));
            rows.push_back(std::move(rv));
        }
        j["grid"] = json{{"width", t.image.width}, {"height", t.image.height}, {"texels", rows}};
    } else {
        j["image"] = t.source;
    }
    j["wrap"] = wrap_id(t.wrap);
}

json texture_json(const Texture& t) {
    json j = json::object();
    image_source_json(t, j);
    j["filter"] = filter_id(t.filter);
    return j;
}

// ---- [heights] ------------------------------------------------------------------------------

namespace {

glm::dvec2 pair_or_number(const Reader& r, const char* key) {
    const json& v = r.get(key);
    if (v.is_number()) return glm::dvec2(as_number(v, r.field(key)));
    if (v.is_array() && v.size() == 2) return as_point2(v, r.field(key));
    throw InputError(r.field(key), "must be a number or a pair [u, v], got " + describe(v));
}

std::uint64_t seed_of(const Reader& r) {
    const long long s = r.integer("seed");
    if (s < 0 || s > (1LL << 53))
        throw InputError(r.field("seed"),
                         "must be a whole number from 0 to 2^53 (got " + std::to_string(s) + ")");
    return static_cast<std::uint64_t>(s);
}

}  // namespace

HeightField height(const Reader& r) {
    HeightField h;
    const std::string type = r.string("type");
    if (type == "sines") {
        r.only({"type", "amplitude", "frequency", "step"});
        h.kind = HeightKind::Sines;
    } else if (type == "noise") {
        r.only({"type", "amplitude", "frequency", "seed", "step"});
        h.kind = HeightKind::Noise;
        if (r.has("seed")) h.seed = seed_of(r);
    } else if (type == "image") {
        r.only({"type", "amplitude", "image", "grid", "checker", "wrap", "step"});
        h.kind = HeightKind::Image;
        image_source(r, h.image);
    } else {
        throw InputError(r.field("type"),
                         "must be \"sines\", \"noise\" or \"image\" (got \"" + type + "\")");
    }
    if (r.has("amplitude")) h.amplitude = r.number("amplitude");
    if (r.has("frequency")) h.frequency = pair_or_number(r, "frequency");
    if (r.has("step")) h.step = r.number("step");
    return h;
}

json height_json(const HeightField& h) {
    json j{{"type", height_kind_id(h.kind)}, {"amplitude", nice_number(h.amplitude)}};
    if (h.kind == HeightKind::Image) {
        image_source_json(h.image, j);
    } else {
        j["frequency"] = nice_point(h.frequency);
        if (h.kind == HeightKind::Noise) j["seed"] = h.seed;
    }
    j["step"] = nice_number(h.step);
    return j;
}

// ---- [solid textures] -----------------------------------------------------------------------

SolidTexture solid(const Reader& r, std::initializer_list<const char*> extra) {
    SolidTexture t;
    const std::string type = r.string("type");
    std::vector<const char*> allowed{"type", "colors"};
    if (type == "checker") {
        t.kind = SolidKind::Checker;
        allowed.push_back("size");
    } else if (type == "stripes" || type == "wood" || type == "marble") {
        t.kind = type == "stripes" ? SolidKind::Stripes
                 : type == "wood"  ? SolidKind::Wood
                                   : SolidKind::Marble;
        allowed.insert(allowed.end(), {"axis", "period"});
        if (t.kind != SolidKind::Stripes)
            allowed.insert(allowed.end(), {"amplitude", "frequency", "seed"});
        if (t.kind == SolidKind::Marble) allowed.push_back("octaves");
    } else {
        throw InputError(r.field("type"),
                         "must be \"checker\", \"stripes\", \"wood\" or "
                         "\"marble\" (got \"" +
                             type + "\")");
    }
    allowed.insert(allowed.end(), extra.begin(), extra.end());
    for (auto it = r.value().begin(); it != r.value().end(); ++it)
        if (std::none_of(allowed.begin(), allowed.end(),
                         [&](const char* k) { return it.key() == k; })) {
            std::string names;
            for (const char* k : allowed) names += (names.empty() ? "" : ", ") + std::string(k);
            throw InputError(r.field(it.key().c_str()),
                             "is not a field of a " + type + " solid texture (" + names + ")");
        }
    if (t.kind == SolidKind::Wood) {  // wood's defaults: brown rings around z
        t.colors = {dvec3(0.72, 0.5, 0.28), dvec3(0.45, 0.27, 0.12)};
        t.period = 0.15;
        t.amplitude = 0.6;
        t.frequency = 2;
    } else if (t.kind == SolidKind::Stripes) {
        t.colors = {dvec3(0.9), dvec3(0.2, 0.3, 0.6)};
        t.period = 0.5;
    } else if (t.kind == SolidKind::Checker) {
        t.colors = {dvec3(0.9), dvec3(0.15)};
    }
    if (r.has("colors")) {
        const json& v = r.get("colors");
        if (!v.is_array() || v.size() != 2)
            throw InputError(r.field("colors"), "must be two colours [c0, c1], got " + describe(v));
        for (int k = 0; k < 2; ++k) t.colors[k] = colour_value(v[k], element(r.field("colors"), k));
    }
    if (r.has("size")) t.size = r.number("size");
    if (r.has("axis")) t.axis = r.point3("axis");
    if (r.has("period")) t.period = r.number("period");
    if (r.has("amplitude")) t.amplitude = r.number("amplitude");
    if (r.has("frequency")) t.frequency = r.number("frequency");
    if (r.has("octaves")) t.octaves = whole(r, "octaves", 1, kMaxOctaves, "a number of octaves");
    if (r.has("seed")) t.seed = seed_of(r);
    return t;
}

json solid_json(const SolidTexture& t) {
    json j{{"type", solid_kind_id(t.kind)},
           {"colors", {nice_point(t.colors[0]), nice_point(t.colors[1])}}};
    if (t.kind == SolidKind::Checker) {
        j["size"] = nice_number(t.size);
        return j;
    }
    j["axis"] = nice_point(t.axis);
    j["period"] = nice_number(t.period);
    if (!uses_noise(t.kind)) return j;
    j["amplitude"] = nice_number(t.amplitude);
    j["frequency"] = nice_number(t.frequency);
    if (t.kind == SolidKind::Marble) j["octaves"] = t.octaves;
    j["seed"] = t.seed;
    return j;
}

// ---- [surfaces] -----------------------------------------------------------------------------

UvSurface surface(const Reader& r) {
    UvSurface s;
    const std::string type = r.string("type");
    if (type == "plane") {
        r.only({"type", "point", "normal", "u_axis", "uv_scale"});
        s.kind = UvKind::Plane;
        s.origin = r.point3("point");
        s.normal = r.point3("normal");
        s.u_axis = r.has("u_axis") ? r.point3("u_axis") : default_u_axis(s.normal);
        if (r.has("uv_scale")) s.scale = r.number("uv_scale");
    } else if (type == "triangle") {
        r.only({"type", "vertices", "uv"});
        s.kind = UvKind::Triangle;
        const std::vector<glm::dvec3> p = r.points3("vertices");
        if (p.size() != 3)
            throw InputError(r.field("vertices"),
                             "must be 3 points, got " + std::to_string(p.size()));
        s.p = {p[0], p[1], p[2]};
        if (r.has("uv")) {
            const std::vector<glm::dvec2> uv = r.points2("uv");
            if (uv.size() != 3)
                throw InputError(r.field("uv"), "must be 3 (u, v) pairs, one per vertex, got " +
                                                    std::to_string(uv.size()));
            s.uv = {uv[0], uv[1], uv[2]};
        }
    } else {
        r.only({"type", "params", "transform", "zmin", "zmax"});
        const bool quadric = type == "sphere" || type == "ellipsoid" || type == "paraboloid" ||
                             type == "hyperboloid" || type == "cone" || type == "cylinder";
        if (!quadric)
            throw InputError(r.field("type"), std::string("must be one of ") +
                                                  rays_json::kQuadricTypes +
                                                  ", plane, triangle (got \"" + type + "\")");
        s.kind = UvKind::Quadric;
        s.quadric = rays_json::quadric(r);
    }
    return s;
}

json surface_json(const UvSurface& s) {
    switch (s.kind) {
        case UvKind::Quadric:
            return rays_json::quadric_json(s.quadric);
        case UvKind::Plane:
            return json{{"type", "plane"},
                        {"point", nice_point(s.origin)},
                        {"normal", nice_point(s.normal)},
                        {"u_axis", nice_point(s.u_axis)},
                        {"uv_scale", nice_number(s.scale)}};
        case UvKind::Triangle:
            return json{{"type", "triangle"},
                        {"vertices", {nice_point(s.p[0]), nice_point(s.p[1]), nice_point(s.p[2])}},
                        {"uv", {nice_point(s.uv[0]), nice_point(s.uv[1]), nice_point(s.uv[2])}}};
    }
    return json::object();
}

}  // namespace cg::texture_json

// ---- [paths] --------------------------------------------------------------------------------

namespace cg {

std::string folder_of(const std::string& path) {
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

void rebase_image_paths(json& j, const std::string& dir) {
    if (dir.empty() || dir == ".") return;
    if (j.is_array()) {
        for (json& v : j) rebase_image_paths(v, dir);
        return;
    }
    if (!j.is_object()) return;
    for (auto it = j.begin(); it != j.end(); ++it) {
        // Texture images, and the ray tracer's OBJ meshes (rays/mesh_json.hpp).
        if ((it.key() == "image" || it.key() == "obj") && it.value().is_string()) {
            const std::string p = it.value().get<std::string>();
            if (!p.empty() && p[0] != '/') it.value() = dir + "/" + p;
        } else {
            rebase_image_paths(it.value(), dir);
        }
    }
}

}  // namespace cg
