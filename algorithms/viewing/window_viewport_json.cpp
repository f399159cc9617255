// Window-to-viewport's JSON:
//   input  {"window": {"xmin", "ymin", "xmax", "ymax"}, "viewport": VIEWPORT,
//           "points": [[x, y], …] (optional, may be empty)}
//   VIEWPORT is one of
//     {"xmin", "ymin", "xmax", "ymax"}                 a rectangle on a y-up device (min < max)
//     {"xmin", "ymin", "xmax", "ymax", "y_down": true} the same rectangle on a device whose rows
//                                                      run downward: the window's bottom edge
//                                                      lands on row ymax, its top on row ymin
//     {"corners": [[x, y], [x, y]]}                    the images of the window's (xmin, ymin)
//                                                      and (xmax, ymax) corners, in any order on
//                                                      either axis (a flip is a negative scale)
//   result {"ndc": [[x, y], …], "device": [[x, y], …],
//           "matrix": window → device, 3×3 as rows,
//           "window_to_ndc": 3×3 rows, "ndc_to_device": 3×3 rows,
//           "distorted": bool, "aspect_window": Lw/Hw, "aspect_viewport": Lv/Hv}
#include "core/format.hpp"
#include "io/registry.hpp"
#include "viewing/window_viewport.hpp"

namespace cg {

namespace {

WindowViewport::Rect rect(const Reader& r, const char* key) {
    Reader o = r.object(key);
    o.only({"xmin", "ymin", "xmax", "ymax"});
    return {o.number("xmin"), o.number("ymin"), o.number("xmax"), o.number("ymax")};
}

// The viewport as the input gives it, into the images of the window's two corners.
WindowViewport::Rect viewport(const Reader& r, WindowViewport::Form& form) {
    using Form = WindowViewport::Form;
    Reader o = r.object("viewport");
    if (o.has("corners")) {
        o.only({"corners"});
        const std::vector<glm::dvec2> c = o.points2("corners");
        if (c.size() != 2)
            throw InputError("viewport.corners",
                             "must be two points (the images of the window's corners (xmin, "
                             "ymin) and (xmax, ymax)), got " + std::to_string(c.size()));
        form = Form::Corners;
        return {c[0].x, c[0].y, c[1].x, c[1].y};
    }
    o.only({"xmin", "ymin", "xmax", "ymax", "y_down"});
    const bool y_down = o.has("y_down") && o.boolean("y_down");
    const double xmin = o.number("xmin"), ymin = o.number("ymin"), xmax = o.number("xmax"),
                 ymax = o.number("ymax");
    if (!y_down) {
        form = Form::Rect;
        return {xmin, ymin, xmax, ymax};
    }
    // Rows run downward: the window's bottom (its ymin) goes to the larger row number.
    form = Form::YDown;
    if (xmax < xmin)
        throw InputError("viewport.xmax", "must be greater than viewport.xmin (" + given(xmax) +
                                              " < " + given(xmin) + "): the rectangle is inverted");
    if (ymax < ymin)
        throw InputError("viewport.ymax",
                         "must be greater than viewport.ymin (" + given(ymax) + " < " + given(ymin) +
                             "): with \"y_down\" the rectangle is still given by its smallest "
                             "and largest row");
    return {xmin, ymax, xmax, ymin};
}

json viewport_json(const WindowViewport::Rect& v, WindowViewport::Form form) {
    using Form = WindowViewport::Form;
    switch (form) {
        case Form::Corners:
            return json{{"corners", {nice_point({v.xmin, v.ymin}), nice_point({v.xmax, v.ymax})}}};
        case Form::YDown:
            return json{{"xmin", nice_number(v.xmin)}, {"ymin", nice_number(v.ymax)},
                        {"xmax", nice_number(v.xmax)}, {"ymax", nice_number(v.ymin)},
                        {"y_down", true}};
        case Form::Rect:
            break;
    }
    return json{{"xmin", nice_number(v.xmin)}, {"ymin", nice_number(v.ymin)},
                {"xmax", nice_number(v.xmax)}, {"ymax", nice_number(v.ymax)}};
}

json rect_json(const WindowViewport::Rect& r) {
    return json{{"xmin", nice_number(r.xmin)}, {"ymin", nice_number(r.ymin)},
                {"xmax", nice_number(r.xmax)}, {"ymax", nice_number(r.ymax)}};
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
        in.viewport = viewport(r, in.form);
        if (r.has("points")) in.points = r.points2("points");
        return in;
    }

    static json input_json(const WindowViewport::Input& in) {
        json ps = json::array();
        for (const glm::dvec2& p : in.points) ps.push_back(nice_point(p));
        return json{{"window", rect_json(in.window)},
                    {"viewport", viewport_json(in.viewport, in.form)},
                    {"points", std::move(ps)}};
    }

    static json result(const WindowViewport::Result& r) {
        return json{{"ndc", points(r.ndc)},
                    {"device", points(r.device)},
                    {"matrix", matrix_rows(r.device_from_window)},
                    {"window_to_ndc", matrix_rows(r.ndc_from_window)},
                    {"ndc_to_device", matrix_rows(r.device_from_ndc)},
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

Algorithm window_viewport_algorithm() {
    return make_algorithm<WindowViewport>(
        [](const WindowViewport::Input& in) { return WindowViewport::map(in); });
}

}  // namespace cg
