// The virtual sphere's and the arcball's JSON (the same for both):
//   input  {"viewport": [width, height] (pixels), "samples": [[x, y], …] (≥ 2, pixels, origin
//           bottom-left), "object": [[x, y, z], …] (optional, ball units)}
//   result {"rotation": [w, x, y, z] (w ≥ 0), "matrix": 3×3 rows,
//           "pairs": [{"axis": [x, y, z], "angle_deg", "rim"}, …],
//           "direct": [w, x, y, z] (one pair from the first sample straight to the last),
//           "path_gap_deg", "closed", "net_angle_deg", "object": [[x, y, z], …] (if given)}
#include "io/registry.hpp"
#include "transforms/trackball_drag.hpp"

namespace cg {

namespace {


template <class A>
typename A::Input drag_input(const json& j) {
    Reader r(j);
    r.only({"viewport", "samples", "object"});
    typename A::Input in;
    const json& vp = r.get("viewport");
    if (!vp.is_array() || vp.size() != 2)
        throw InputError("viewport", "must be [width, height] in pixels, got " + describe(vp));
    in.viewport = {as_number(vp[0], "viewport[0]"), as_number(vp[1], "viewport[1]")};
    in.samples = r.points2("samples");
    if (r.has("object")) in.object = r.points3("object");
    return in;
}

template <class A>
json drag_input_json(const typename A::Input& in) {
    json samples = json::array();
    for (const glm::dvec2& p : in.samples) samples.push_back(nice_point(p));
    json j{{"viewport", {nice_number(in.viewport.x), nice_number(in.viewport.y)}},
           {"samples", std::move(samples)}};
    if (!in.object.empty()) {
        json object = json::array();
        for (const glm::dvec3& p : in.object) object.push_back(nice_point(p));
        j["object"] = std::move(object);
    }
    return j;
}

template <class A>
json drag_result(const typename A::Result& r) {
    json pairs = json::array();
    for (const auto& p : r.pairs)
        pairs.push_back(json{{"axis", to_json(p.axis)}, {"angle_deg", p.angle_deg}, {"rim", p.rim}});
    json j{{"rotation", quat_json(r.rotation)},
           {"matrix", matrix_rows(r.matrix)},
           {"pairs", std::move(pairs)},
           {"direct", quat_json(r.direct)},
           {"path_gap_deg", r.path_gap_deg},
           {"closed", r.closed},
           {"net_angle_deg", r.net_angle_deg}};
    if (!r.object.empty()) {
        json object = json::array();
        for (const glm::dvec3& p : r.object) object.push_back(to_json(p));
        j["object"] = std::move(object);
    }
    return j;
}

}  // namespace

template <>
struct JsonIo<VirtualSphere> {
    static VirtualSphere::Input input(const json& j) { return drag_input<VirtualSphere>(j); }
    static json input_json(const VirtualSphere::Input& in) {
        return drag_input_json<VirtualSphere>(in);
    }
    static json result(const VirtualSphere::Result& r) { return drag_result<VirtualSphere>(r); }
    static json example() {
        // A small closed loop around the ball's centre: the virtual sphere comes back turned.
        return json::parse(R"({"viewport": [400, 300],
            "samples": [[200, 150], [230, 150], [230, 180], [200, 180], [200, 150]]})");
    }
};

template <>
struct JsonIo<Arcball> {
    static Arcball::Input input(const json& j) { return drag_input<Arcball>(j); }
    static json input_json(const Arcball::Input& in) { return drag_input_json<Arcball>(in); }
    static json result(const Arcball::Result& r) { return drag_result<Arcball>(r); }
    static json example() {
        // The same loop: the arcball comes back exactly where it started.
        return json::parse(R"({"viewport": [400, 300],
            "samples": [[200, 150], [230, 150], [230, 180], [200, 180], [200, 150]]})");
    }
};

Algorithm virtual_sphere_algorithm() {
    return make_algorithm<VirtualSphere>(
        [](const VirtualSphere::Input& in) { return VirtualSphere::drag(in); });
}
Algorithm arcball_algorithm() {
    return make_algorithm<Arcball>(
        [](const Arcball::Input& in) { return Arcball::drag(in); });
}

}  // namespace cg
