// Window-to-viewport's JSON:
//   input  {"window": {"xmin", "ymin", "xmax", "ymax"}, "viewport": {"xmin", "ymin", "xmax",
//   "ymax"},
//           "points": [[x, y], …] (optional, may be empty)}
//   result {"ndc": [[x, y], …], "device": [[x, y], …],
//           "matrix": window → device, 3×3 as rows,
//           "window_to_ndc": 3×3 rows, "ndc_to_device": 3×3 rows,
//           "distorted": bool, "aspect_window": Lw/Hw, "aspect_viewport": Lv/Hv}
#include "io/registry.hpp"
#include "viewing/window_viewport.hpp"

namespace cg {

namespace {

WindowViewport::Rect rect(const Reader& r, const char* key) {
    Reader o = r.object(key);
    o.only({"xmin", "ymin", "xmax", "ymax"});
    return {o.number("xmin"), o.number("ymin"), o.number("xmax"), o.number("ymax")};
}

json rect_json(const WindowViewport::Rect& r) {
    return json{{"xmin", nice_number(r.xmin)}, {"ymin", nice_number(r.ymin)},
                {"xmax", nice_number(r.xmax)}, {"ymax", nice_number(r.ymax)}};
}

json rows(const glm::dmat3& m) {  // glm is m[column][row]
    json j = json::array();
    for (int r = 0; r < 3; ++r) j.push_back({m[0][r], m[1][r], m[2][r]});
    return j;
}

json points(const std::vector<glm::dvec2>& ps) {
    json j = json::array();
    for (const glm::dvec2& p : ps) j.push_back(to_json(p));
    return j;
}

}  // namespace

template <>
struct JsonIo<WindowViewport> {
    static WindowViewport::Input input(const json& j) {
        Reader r(j);
        r.only({"window", "viewport", "points"});
        WindowViewport::Input in;
        in.window = rect(r, "window");
        in.viewport = rect(r, "viewport");
        if (r.has("points")) in.points = r.points2("points");
        return in;
    }

    static json input_json(const WindowViewport::Input& in) {
        json ps = json::array();
        for (const glm::dvec2& p : in.points) ps.push_back(nice_point(p));
        return json{{"window", rect_json(in.window)},
                    {"viewport", rect_json(in.viewport)},
                    {"points", std::move(ps)}};
    }

    static json result(const WindowViewport::Result& r) {
        return json{{"ndc", points(r.ndc)},
                    {"device", points(r.device)},
                    {"matrix", rows(r.device_from_window)},
                    {"window_to_ndc", rows(r.ndc_from_window)},
                    {"ndc_to_device", rows(r.device_from_ndc)},
                    {"distorted", r.distorted},
                    {"aspect_window", r.aspect_window},
                    {"aspect_viewport", r.aspect_viewport}};
    }

    static json example() {
        // A 2:1 window shown in a 4:3 viewport: the map stretches y more than x.
        return json{{"window", {{"xmin", 0}, {"ymin", 0}, {"xmax", 8}, {"ymax", 4}}},
                    {"viewport", {{"xmin", 0}, {"ymin", 0}, {"xmax", 640}, {"ymax", 480}}},
                    {"points", {{2, 1}, {6, 1}, {4, 3}}}};
    }
};

Algorithm window_viewport_algorithm() { return make_algorithm<WindowViewport>(); }

}  // namespace cg
