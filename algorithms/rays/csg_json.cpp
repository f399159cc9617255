#include "rays/csg_json.hpp"

#include "rays/rays_json.hpp"

namespace cg::csg_json {

namespace {

struct Builder {
    CsgTree t;

    // Appends the node at `r` after its operands (post-order) and returns its index.
    int node(const Reader& r, int depth) {
        if (depth > kMaxCsgDepth)
            throw InputError(r.path(), "is " + std::to_string(depth) +
                                           " levels below the root; the limit is " +
                                           std::to_string(kMaxCsgDepth));
        CsgNode n;
        n.path = r.path();
        n.depth = depth;
        if (r.has("transform")) {
            n.has_transform = true;
            n.transform = rays_json::matrix4(r, "transform");
        }
        if (r.has("name")) n.name = r.string("name");
        if (r.has("op")) {
            r.only({"op", "left", "right", "transform", "name"});
            const std::string op = r.string("op");
            if (op == "union")
                n.op = CsgOp::Union;
            else if (op == "intersection")
                n.op = CsgOp::Intersection;
            else if (op == "difference")
                n.op = CsgOp::Difference;
            else
                throw InputError(r.field("op"), "unknown op \"" + op +
                                                    "\" (union, intersection, difference)");
            n.leaf = false;
            n.left = node(r.object("left"), depth + 1);
            n.right = node(r.object("right"), depth + 1);
        } else if (r.has("primitive")) {
            r.only({"primitive", "transform", "name"});
            const Reader p = r.object("primitive");
            if (p.has("type") && p.get("type") == "box") {
                p.only({"type", "min", "max"});
                n.kind = CsgPrimitive::Box;
                n.box.min = p.point3("min");
                n.box.max = p.point3("max");
            } else {
                p.only({"type", "params", "transform", "zmin", "zmax"});
                if (p.has("type") && p.get("type").is_string()) {
                    const std::string type = p.string("type");
                    bool known = false;
                    for (const char* k : {"sphere", "ellipsoid", "paraboloid", "hyperboloid",
                                          "cone", "cylinder"})
                        known = known || type == k;
                    if (!known)
                        throw InputError(p.field("type"), std::string("must be one of ") +
                                                              rays_json::kQuadricTypes +
                                                              ", box (got \"" + type + "\")");
                }
                n.kind = CsgPrimitive::Quadric;
                n.quadric = rays_json::quadric(p);
            }
            n.leaf_index = t.leaves++;
            if (t.leaves > kMaxCsgLeaves)
                throw InputError(r.path(), "is primitive number " + std::to_string(t.leaves) +
                                               " of the tree; the limit is " +
                                               std::to_string(kMaxCsgLeaves));
        } else {
            r.only({"op", "left", "right", "primitive", "transform", "name"});
            throw InputError(r.path(),
                             "must be a boolean node {\"op\", \"left\", \"right\"} or a leaf "
                             "{\"primitive\"}");
        }
        t.nodes.push_back(n);
        return static_cast<int>(t.nodes.size()) - 1;
    }
};

json node_json(const CsgTree& t, int k) {
    const CsgNode& n = t.nodes[k];
    json j = json::object();
    if (!n.name.empty()) j["name"] = n.name;
    if (n.leaf) {
        if (n.kind == CsgPrimitive::Box)
            j["primitive"] = json{{"type", "box"},
                                  {"min", nice_point(n.box.min)},
                                  {"max", nice_point(n.box.max)}};
        else
            j["primitive"] = rays_json::quadric_json(n.quadric);
    } else {
        j["op"] = csg_op_id(n.op);
        j["left"] = node_json(t, n.left);
        j["right"] = node_json(t, n.right);
    }
    if (n.has_transform) j["transform"] = rays_json::matrix4_json(n.transform);
    return j;
}

}  // namespace

CsgTree tree(const json& j, const std::string& path) {
    Builder b;
    b.node(Reader(j, path), 0);
    return std::move(b.t);
}

json tree_json(const CsgTree& t) {
    return t.nodes.empty() ? json(nullptr) : node_json(t, static_cast<int>(t.nodes.size()) - 1);
}

}  // namespace cg::csg_json
