#include "sampling/pattern_json.hpp"

#include <cmath>

namespace cg::sampling_json {

sampling::Pattern pattern(const Reader& r, const char* key) {
    const json& v = r.get(key);
    sampling::Pattern p;
    if (!v.is_string() || !sampling::parse_pattern(v.get<std::string>(), p))
        throw InputError(
            r.field(key),
            "must be \"regular\", \"random\", \"jittered\" or \"poisson\", got " + describe(v));
    return p;
}

sampling::Filter filter(const Reader& r, const char* key) {
    const json& v = r.get(key);
    sampling::Filter f;
    if (!v.is_string() || !sampling::parse_filter(v.get<std::string>(), f))
        throw InputError(r.field(key),
                         "must be \"box\", \"tent\" or \"gaussian\", got " + describe(v));
    return f;
}

int count(const Reader& r, const char* key, int max) {
    const long long n = r.integer(key);
    if (n < 1 || n > max)
        throw InputError(r.field(key), "must be between 1 and " + std::to_string(max) + " (got " +
                                           std::to_string(n) + ")");
    return static_cast<int>(n);
}

glm::ivec2 pixel(const Reader& r, const char* key, double max_abs) {
    const json& v = r.get(key);
    const std::string field = r.field(key);
    if (!v.is_array() || v.size() != 2)
        throw InputError(field, "must be a pixel [i, j] of two integers, got " + describe(v));
    int c[2];
    for (int k = 0; k < 2; ++k) {
        const std::string f = field + "[" + std::to_string(k) + "]";
        const double d = as_number(v[k], f);
        if (d != std::floor(d))
            throw InputError(f, "must be an integer pixel index, got " + describe(v[k]));
        if (std::fabs(d) > max_abs)
            throw InputError(f, "must be within ±10⁶, got " + describe(v[k]));
        c[k] = static_cast<int>(d);
    }
    return {c[0], c[1]};
}

std::uint64_t seed(const Reader& r, const char* key) {
    const long long s = r.integer(key);
    if (s < 0 || s > (1LL << 53))
        throw InputError(r.field(key),
                         "must be an integer between 0 and 2^53 (got " + std::to_string(s) + ")");
    return static_cast<std::uint64_t>(s);
}

sampling::Region region(const Reader& r) {
    sampling::Region g;
    const std::string type = r.string("type");
    if (type == "edge") {
        r.only({"type", "point", "angle"});
        g.kind = sampling::RegionKind::Edge;
        g.point = r.point2("point");
        g.angle_deg = r.number("angle");
    } else if (type == "polygon") {
        r.only({"type", "points"});
        g.kind = sampling::RegionKind::Polygon;
        g.points = r.points2("points");
    } else {
        throw InputError(r.field("type"), "must be \"edge\" or \"polygon\", got \"" + type + "\"");
    }
    return g;
}

json region_json(const sampling::Region& g) {
    if (g.kind == sampling::RegionKind::Edge)
        return json{
            {"type", "edge"}, {"point", nice_point(g.point)}, {"angle", nice_number(g.angle_deg)}};
    json pts = json::array();
    for (const auto& p : g.points) pts.push_back(nice_point(p));
    return json{{"type", "polygon"}, {"points", std::move(pts)}};
}

}  // namespace cg::sampling_json
