// The projection pipeline's JSON:
//   input  {"convention": "course" | "opengl", "fov_y_deg", "aspect", "near", "far"
//           or instead of those four "frustum": {"left", "right", "bottom", "top", "near", "far"}
//           (glFrustum's off-axis form; exactly one of the two forms),
//           "eye", "center", "up" (optional, eye and center together; up defaults to [0, 1, 0]),
//           "model": 4×4 rows (optional, affine), "points": [[x, y, z], …],
//           "segments": [[[x, y, z], [x, y, z]], …] (optional), "viewport": [W, H] (optional)}
//   result {"matrix": the perspective matrix, 4×4 rows, "view_matrix", "model_matrix", "mvp",
//           "world": [[x, y, z], …], "view": [[x, y, z], …], "clip": [[x, y, z, w], …],
//           "ndc": [[x, y, z] or null (w ≤ 0), …], "inside": [bool, …],
//           "device": [[x, y] or null, …] (with a viewport),
//           "segments": [{"status": "kept" | "clipped" | "rejected", "t": [t0, t1] or null,
//                         "clip": [[x, y, z, w] ×2] (after clipping) or null,
//                         "ndc": [[x, y, z] ×2] or null}, …] (with segments)}
#include "io/registry.hpp"
#include "transforms/perspective.hpp"

namespace cg {

namespace {

json vec4_json(const glm::dvec4& v) { return json{v.x, v.y, v.z, v.w}; }

glm::dmat4 read_matrix4(const json& v, const std::string& field) {
    if (!v.is_array() || v.size() != 4)
        throw InputError(field, "must be a 4×4 matrix as 4 rows of 4 numbers, got " + describe(v));
    glm::dmat4 m(1.0);
    for (int r = 0; r < 4; ++r) {
        const std::string f = field + "[" + std::to_string(r) + "]";
        if (!v[r].is_array() || v[r].size() != 4)
            throw InputError(f, "must be a row of 4 numbers, got " + describe(v[r]));
        for (int c = 0; c < 4; ++c) m[c][r] = as_number(v[r][c], f + "[" + std::to_string(c) + "]");
    }
    return m;
}

}  // namespace

template <>
struct JsonIo<Perspective> {
    static Perspective::Input input(const json& j) {
        Reader r(j);
        r.only({"convention", "fov_y_deg", "aspect", "near", "far", "frustum", "eye", "center",
                "up", "model", "points", "segments", "viewport"});
        Perspective::Input in;
        const std::string convention = r.string("convention");
        if (convention == "course")
            in.convention = Perspective::Convention::Course;
        else if (convention == "opengl")
            in.convention = Perspective::Convention::OpenGL;
        else
            throw InputError("convention", "must be \"course\" (the view looks down +z) or "
                                           "\"opengl\" (down −z), got \"" + convention + "\"");
        if (r.has("frustum")) {  // the off-axis form: exactly one of the two
            for (const char* key : {"fov_y_deg", "aspect", "near", "far"})
                if (r.has(key))
                    throw InputError(r.field(key),
                                     "cannot be given with \"frustum\": give either fov_y_deg, "
                                     "aspect, near and far, or a frustum {left, right, bottom, "
                                     "top, near, far}");
            const Reader f = r.object("frustum");
            f.only({"left", "right", "bottom", "top", "near", "far"});
            in.has_frustum = true;
            in.left = f.number("left");
            in.right = f.number("right");
            in.bottom = f.number("bottom");
            in.top = f.number("top");
            in.near = f.number("near");
            in.far = f.number("far");
        } else {
            in.fov_y_deg = r.number("fov_y_deg");
            in.aspect = r.number("aspect");
            in.near = r.number("near");
            in.far = r.number("far");
        }
        if (r.has("eye") != r.has("center"))
            throw InputError(r.has("eye") ? "center" : "eye",
                             "is missing: a look-at needs both eye and center");
        if (r.has("up") && !r.has("eye"))
            throw InputError("up", "needs eye and center: without a look-at the view matrix is I");
        if (r.has("eye")) {
            in.look_at = true;
            in.eye = r.point3("eye");
            in.center = r.point3("center");
            if (r.has("up")) in.up = r.point3("up");
        }
        if (r.has("model")) {
            in.has_model = true;
            in.model = read_matrix4(r.get("model"), r.field("model"));
        }
        in.points = r.points3("points");
        if (r.has("segments")) {
            const json& segs = r.get("segments");
            if (!segs.is_array())
                throw InputError("segments", "must be a list of segments [[x, y, z], [x, y, z]], got " +
                                                 describe(segs));
            for (std::size_t k = 0; k < segs.size(); ++k) {
                const std::string f = "segments[" + std::to_string(k) + "]";
                if (!segs[k].is_array() || segs[k].size() != 2)
                    throw InputError(f, "must be a segment [[x, y, z], [x, y, z]], got " + describe(segs[k]));
                in.segments.push_back({as_point3(segs[k][0], f + "[0]"), as_point3(segs[k][1], f + "[1]")});
            }
        }
        if (r.has("viewport")) {
            const json& vp = r.get("viewport");
            if (!vp.is_array() || vp.size() != 2)
                throw InputError("viewport", "must be [width, height] in pixels, got " + describe(vp));
            in.has_viewport = true;
            in.viewport = {as_number(vp[0], "viewport[0]"), as_number(vp[1], "viewport[1]")};
        }
        return in;
    }

    static json input_json(const Perspective::Input& in) {
        json j{{"convention", in.convention == Perspective::Convention::Course ? "course" : "opengl"}};
        if (in.has_frustum) {
            j["frustum"] = json{{"left", nice_number(in.left)},     {"right", nice_number(in.right)},
                                {"bottom", nice_number(in.bottom)}, {"top", nice_number(in.top)},
                                {"near", nice_number(in.near)},     {"far", nice_number(in.far)}};
        } else {
            j["fov_y_deg"] = nice_number(in.fov_y_deg);
            j["aspect"] = nice_number(in.aspect);
            j["near"] = nice_number(in.near);
            j["far"] = nice_number(in.far);
        }
        if (in.look_at) {
            j["eye"] = nice_point(in.eye);
            j["center"] = nice_point(in.center);
            j["up"] = nice_point(in.up);
        }
        if (in.has_model) {
            json m = json::array();
            for (int r = 0; r < 4; ++r) {
                json row = json::array();
                for (int c = 0; c < 4; ++c) row.push_back(nice_number(in.model[c][r]));
                m.push_back(std::move(row));
            }
            j["model"] = std::move(m);
        }
        json ps = json::array();
        for (const glm::dvec3& p : in.points) ps.push_back(nice_point(p));
        j["points"] = std::move(ps);
        if (!in.segments.empty()) {
            json segs = json::array();
            for (const auto& s : in.segments) segs.push_back({nice_point(s[0]), nice_point(s[1])});
            j["segments"] = std::move(segs);
        }
        if (in.has_viewport) j["viewport"] = {nice_number(in.viewport.x), nice_number(in.viewport.y)};
        return j;
    }

    static json result(const Perspective::Result& r) {
        json world = json::array(), view = json::array(), clip = json::array(), ndc = json::array(),
             inside = json::array(), device = json::array();
        for (const auto& p : r.world) world.push_back(to_json(p));
        for (const auto& p : r.eye_coords) view.push_back(to_json(p));
        for (const auto& c : r.clip) clip.push_back(vec4_json(c));
        for (const auto& q : r.ndc) ndc.push_back(q ? to_json(*q) : json(nullptr));
        for (bool b : r.inside) inside.push_back(b);
        bool any_device = false;
        for (const auto& d : r.device) {
            device.push_back(d ? to_json(*d) : json(nullptr));
            any_device = any_device || d.has_value();
        }
        json j{{"matrix", matrix_rows(r.projection)}, {"view_matrix", matrix_rows(r.view)},
               {"model_matrix", matrix_rows(r.model)}, {"mvp", matrix_rows(r.mvp)},
               {"world", std::move(world)},     {"view", std::move(view)},
               {"clip", std::move(clip)},       {"ndc", std::move(ndc)},
               {"inside", std::move(inside)}};
        if (any_device) j["device"] = std::move(device);
        if (!r.segments.empty()) {
            json segs = json::array();
            for (const auto& g : r.segments) {
                using S = Perspective::SegmentStatus;
                const bool gone = g.status == S::Rejected;
                segs.push_back(json{
                    {"status", g.status == S::Inside ? "kept" : g.status == S::Clipped ? "clipped" : "rejected"},
                    {"t", gone ? json(nullptr) : json{g.t0, g.t1}},
                    {"clip", gone ? json(nullptr) : json{vec4_json(g.kept[0]), vec4_json(g.kept[1])}},
                    {"ndc", gone ? json(nullptr) : json{to_json(g.ndc[0]), to_json(g.ndc[1])}}});
            }
            j["segments"] = std::move(segs);
        }
        return j;
    }

    static json example() {
        // The course's matrix with a 90° field of view (cot 45° = 1), near 1 and far 3; a point
        // inside, one beyond the far plane, one between the eye and the near plane, one behind
        // the eye, and a segment crossing the near plane from behind the eye.
        return json::parse(R"({"convention": "course", "fov_y_deg": 90, "aspect": 1,
            "near": 1, "far": 3,
            "points": [[1, 0.5, 2], [-1, 1, 4], [0.2, 0, 0.5], [1, 1, -1]],
            "segments": [[[0.5, 0.5, -1], [0.5, -0.5, 2]]],
            "viewport": [640, 640]})");
    }
};

Algorithm perspective_algorithm() {
    return make_algorithm<Perspective>(
        [](const Perspective::Input& in) { return Perspective::project(in); });
}

}  // namespace cg
