// Triangle scan conversion's JSON:
//   input  {"width": W, "height": H, "triangle": [[x, y], [x, y], [x, y]],
//           "colors": [[r, g, b], [r, g, b], [r, g, b]] (optional, RGB in [0, 1])}
//   result {"pixels": [[i, j], …] (sorted by j then i),
//           "colors": [[r, g, b], …] (parallel to pixels; only when colours were given),
//           "spans": [[j, i_first, i_last], …] (scanlines with pixels),
//           "split": [x_split, y1] | null (null when collinear),
//           "inverse_slopes": [m_long, m_lower, m_upper] (dx/dy of v0→v2, v0→v1, v1→v2; null
//                             for a horizontal edge) | null (collinear)}
#include "io/registry.hpp"
#include "raster/scan_triangle.hpp"

namespace cg {

template <>
struct JsonIo<ScanTriangle> {
    static ScanTriangle::Input input(const json& j) {
        Reader r(j);
        r.only({"width", "height", "triangle", "colors"});
        ScanTriangle::Input in;
        in.width = r.integer("width");
        in.height = r.integer("height");
        in.triangle = r.points2("triangle");
        if (r.has("colors")) in.colors = r.points3("colors");
        return in;
    }

    static json input_json(const ScanTriangle::Input& in) {
        json j{{"width", in.width}, {"height", in.height}, {"triangle", json::array()}};
        for (const glm::dvec2& p : in.triangle) j["triangle"].push_back(nice_point(p));
        if (!in.colors.empty()) {
            j["colors"] = json::array();
            for (const glm::dvec3& c : in.colors) j["colors"].push_back(nice_point(c));
        }
        return j;
    }

    static json result(const ScanTriangle::Result& r) {
        json pixels = json::array();
        for (const glm::ivec2 p : r.pixels) pixels.push_back({p.x, p.y});
        json j{{"pixels", std::move(pixels)}};
        if (!r.colors.empty()) {
            json colors = json::array();
            for (const glm::dvec3& c : r.colors) colors.push_back(to_json(c));
            j["colors"] = std::move(colors);
        }
        json spans = json::array();
        for (const auto& s : r.spans) spans.push_back({s[0], s[1], s[2]});
        j["spans"] = std::move(spans);
        j["split"] = r.split ? to_json(*r.split) : json(nullptr);
        if (r.split) {
            json slopes = json::array();
            for (const auto& m : r.inverse_slopes) slopes.push_back(m ? json(*m) : json(nullptr));
            j["inverse_slopes"] = std::move(slopes);
        } else {
            j["inverse_slopes"] = nullptr;
        }
        return j;
    }

    static json example() {
        // A general triangle: a flat-top lower part and a flat-bottom upper part, with the
        // middle vertex on the right.
        return json{{"width", 10}, {"height", 8}, {"triangle", {{1.5, 0.5}, {8, 3}, {3, 7.5}}}};
    }
};

Algorithm scan_triangle_algorithm() {
    return make_algorithm<ScanTriangle>(
        [](const ScanTriangle::Input& in) { return ScanTriangle::scan(in); });
}

}  // namespace cg
