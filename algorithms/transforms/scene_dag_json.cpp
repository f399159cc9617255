// Hierarchical models (scene DAG), JSON:
//   input  {"nodes": [{"name": "torso",
//                      "transform": {"translate": [x, y, z], "rotate": {"axis": [x, y, z],
//                                    "angle_deg": θ}, "scale": [sx, sy, sz]}  (each optional;
//                                    M = T R S)
//                        or "matrix": 4×4 affine rows,
//                      "shape": "box" | "none" (optional, default none: a unit cube [−½, ½]³),
//                      "children": ["upper_arm", …] (optional)}, …],
//           "root": "torso"}
//   result {"draws": [{"path": "torso/arm", "matrix": 4×4 rows}, …] (one per box drawn, in
//           traversal order), "corners": [[8 corners of each drawn box], …], "max_depth": d,
//           "steps": n}
#include "io/registry.hpp"
#include "transforms/scene_dag.hpp"

namespace cg {

namespace {

json rows_json(const glm::dmat4& m, bool nice) {
    json j = json::array();
    for (int r = 0; r < 4; ++r) {
        json row = json::array();
        for (int c = 0; c < 4; ++c) row.push_back(nice ? nice_number(m[c][r]) : json(m[c][r]));
        j.push_back(std::move(row));
    }
    return j;
}

glm::dmat4 read_matrix(const json& v, const std::string& f) {
    if (!v.is_array() || v.size() != 4)
        throw InputError(f, "must be a 4×4 matrix (4 rows of 4 numbers), got " + describe(v));
    glm::dmat4 m(1.0);
    for (std::size_t r = 0; r < 4; ++r) {
        const std::string fr = f + "[" + std::to_string(r) + "]";
        if (!v[r].is_array() || v[r].size() != 4)
            throw InputError(fr, "must be a row of 4 numbers, got " + describe(v[r]));
        for (std::size_t c = 0; c < 4; ++c)
            m[static_cast<int>(c)][static_cast<int>(r)] =
                as_number(v[r][c], fr + "[" + std::to_string(c) + "]");
    }
    return m;
}

SceneDag::Node read_node(const json& v, const std::string& f) {
    Reader r(v, f);
    r.only({"name", "transform", "matrix", "shape", "children"});
    SceneDag::Node n;
    n.name = r.string("name");
    if (r.has("transform") && r.has("matrix"))
        throw InputError(f, "gives both \"transform\" and \"matrix\"; give one");
    if (r.has("matrix")) {
        n.has_matrix = true;
        n.matrix = read_matrix(r.get("matrix"), r.field("matrix"));
    }
    if (r.has("transform")) {
        const Reader t = r.object("transform");
        t.only({"translate", "rotate", "scale"});
        if (t.has("translate")) n.translate = t.point3("translate");
        if (t.has("scale")) n.scale = t.point3("scale");
        if (t.has("rotate")) {
            const Reader q = t.object("rotate");
            q.only({"axis", "angle_deg"});
            n.has_rotate = true;
            n.axis = q.point3("axis");
            n.angle_deg = q.number("angle_deg");
        }
    }
    if (r.has("shape")) {
        const std::string s = r.string("shape");
        if (s != "box" && s != "none")
            throw InputError(r.field("shape"), "must be \"box\" or \"none\", got \"" + s + "\"");
        n.box = s == "box";
    }
    if (r.has("children")) {
        const json& c = r.get("children");
        if (!c.is_array())
            throw InputError(r.field("children"), "must be a list of node names, got " + describe(c));
        for (std::size_t i = 0; i < c.size(); ++i) {
            if (!c[i].is_string())
                throw InputError(r.field("children") + "[" + std::to_string(i) + "]",
                                 "must be a node's name (a string), got " + describe(c[i]));
            n.children.push_back(c[i].get<std::string>());
        }
    }
    return n;
}

}  // namespace

template <>
struct JsonIo<SceneDag> {
    static SceneDag::Input input(const json& j) {
        Reader r(j);
        r.only({"nodes", "root"});
        SceneDag::Input in;
        const json& ns = r.get("nodes");
        if (!ns.is_array()) throw InputError("nodes", "must be a list of nodes, got " + describe(ns));
        if (ns.size() > static_cast<std::size_t>(SceneDag::kMaxNodes))
            throw InputError("nodes", "has " + std::to_string(ns.size()) +
                                          " nodes; the limit is " +
                                          std::to_string(SceneDag::kMaxNodes));
        for (std::size_t i = 0; i < ns.size(); ++i)
            in.nodes.push_back(read_node(ns[i], "nodes[" + std::to_string(i) + "]"));
        in.root = r.string("root");
        return in;
    }

    static json input_json(const SceneDag::Input& in) {
        json ns = json::array();
        for (const SceneDag::Node& n : in.nodes) {
            json o{{"name", n.name}};
            if (n.has_matrix) {
                o["matrix"] = rows_json(n.matrix, true);
            } else {
                json t = json::object();
                if (n.translate != glm::dvec3(0)) t["translate"] = nice_point(n.translate);
                if (n.has_rotate)
                    t["rotate"] = {{"axis", nice_point(n.axis)},
                                   {"angle_deg", nice_number(n.angle_deg)}};
                if (n.scale != glm::dvec3(1)) t["scale"] = nice_point(n.scale);
                if (!t.empty()) o["transform"] = std::move(t);
            }
            o["shape"] = n.box ? "box" : "none";
            if (!n.children.empty()) o["children"] = n.children;
            ns.push_back(std::move(o));
        }
        return json{{"nodes", std::move(ns)}, {"root", in.root}};
    }

    static json result(const SceneDag::Result& r) {
        json draws = json::array(), corners = json::array();
        for (const SceneDag::Draw& d : r.draws) {
            draws.push_back({{"path", d.path}, {"matrix", rows_json(d.matrix, false)}});
            json c = json::array();
            for (const glm::dvec3& p : SceneDag::corners(d.matrix)) c.push_back(to_json(p));
            corners.push_back(std::move(c));
        }
        return json{{"draws", std::move(draws)},
                    {"corners", std::move(corners)},
                    {"max_depth", r.max_depth},
                    {"steps", r.steps}};
    }

    static json example() {
        // The course's puppet, cut down: a torso (its box scaled in a leaf of its own, so the
        // scale does not reach the arms) with two shoulders sharing one arm node, so the
        // arm is drawn twice, once per path, each with its own world matrix.
        return json::parse(R"({
  "nodes": [
    {"name": "torso", "transform": {"translate": [0, 1, 0]},
     "children": ["torso_box", "left_shoulder", "right_shoulder"]},
    {"name": "torso_box", "transform": {"scale": [1, 2, 0.5]}, "shape": "box"},
    {"name": "left_shoulder", "transform": {"translate": [-0.75, 0.8, 0],
     "rotate": {"axis": [0, 0, 1], "angle_deg": -30}}, "children": ["arm"]},
    {"name": "right_shoulder", "transform": {"translate": [0.75, 0.8, 0],
     "rotate": {"axis": [0, 0, 1], "angle_deg": 30}}, "children": ["arm"]},
    {"name": "arm", "transform": {"translate": [0, -0.6, 0], "scale": [0.3, 1.2, 0.3]},
     "shape": "box"}
  ],
  "root": "torso"
})");
    }
};

Algorithm scene_dag_algorithm() {
    return make_algorithm<SceneDag>(
        [](const SceneDag::Input& in) { return SceneDag::traverse(in); });
}

}  // namespace cg
