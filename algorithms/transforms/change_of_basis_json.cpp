// Change of basis, JSON:
//   input  {"from": {"origin": [x, y, z], "axes": [[x, y, z] ×3]}   F1, world coordinates
//           "to":   {"origin": [x, y, z], "axes": [[x, y, z] ×3]}   F2, world coordinates
//           "points": [[p1, p2, p3], …] (relative to "from"; may be empty),
//           "vectors": [[u1, u2, u3], …] (optional, relative to "from", w = 0)}
//   result {"matrix": M₁,₂ as 4×4 rows (F1 coordinates → F2 coordinates, column vectors),
//           "points": [[…], …] (relative to "to"), "vectors": [[…], …] (relative to "to"),
//           "world": [[…], …] (the points in world coordinates), "orthonormal_to",
//           "world_from_f1", "world_from_f2", "f2_from_world" (4×4 rows)}
#include "io/registry.hpp"
#include "transforms/change_of_basis.hpp"

namespace cg {

namespace {

// The matrix's rows with −0 written as 0 (the frames' zeros come out of products as −0).
json rows_signless_zero(const glm::dmat4& m) {
    json j = json::array();
    for (int r = 0; r < 4; ++r)
        j.push_back({m[0][r] + 0.0, m[1][r] + 0.0, m[2][r] + 0.0, m[3][r] + 0.0});
    return j;
}

json points(const std::vector<glm::dvec3>& ps) {
    json j = json::array();
    for (const glm::dvec3& p : ps) j.push_back(to_json(p));
    return j;
}

ChangeOfBasis::Frame read_frame(const Reader& parent, const char* key) {
    const Reader r = parent.object(key);
    r.only({"origin", "axes"});
    ChangeOfBasis::Frame f;
    f.origin = r.point3("origin");
    const auto axes = r.points3("axes");
    if (axes.size() != 3)
        throw InputError(r.field("axes"),
                         "must be three axes [[x, y, z], [x, y, z], [x, y, z]], got " +
                             std::to_string(axes.size()));
    f.axes = {axes[0], axes[1], axes[2]};
    return f;
}

json frame_json(const ChangeOfBasis::Frame& f) {
    return json{{"origin", nice_point(f.origin)},
                {"axes", {nice_point(f.axes[0]), nice_point(f.axes[1]), nice_point(f.axes[2])}}};
}

}  // namespace

template <>
struct JsonIo<ChangeOfBasis> {
    static ChangeOfBasis::Input input(const json& j) {
        Reader r(j);
        r.only({"from", "to", "points", "vectors"});
        ChangeOfBasis::Input in;
        in.from = read_frame(r, "from");
        in.to = read_frame(r, "to");
        in.points = r.points3("points");
        if (r.has("vectors")) in.vectors = r.points3("vectors");
        return in;
    }

    static json input_json(const ChangeOfBasis::Input& in) {
        json ps = json::array();
        for (const glm::dvec3& p : in.points) ps.push_back(nice_point(p));
        json j{{"from", frame_json(in.from)}, {"to", frame_json(in.to)}, {"points", std::move(ps)}};
        if (!in.vectors.empty()) {
            json vs = json::array();
            for (const glm::dvec3& u : in.vectors) vs.push_back(nice_point(u));
            j["vectors"] = std::move(vs);
        }
        return j;
    }

    static json result(const ChangeOfBasis::Result& r) {
        return json{{"matrix", rows_signless_zero(r.matrix)},
                    {"points", points(r.points)},
                    {"vectors", points(r.vectors)},
                    {"world", points(r.world)},
                    {"orthonormal_to", r.orthonormal_to},
                    {"world_from_f1", rows_signless_zero(r.world_from_f1)},
                    {"world_from_f2", rows_signless_zero(r.world_from_f2)},
                    {"f2_from_world", rows_signless_zero(r.f2_from_world)}};
    }

    static json example() {
        // The 2D classic: F1 is the world frame, F2 is turned by 90° and moved to (2, 1).
        // P = (3, 2) is 1 along w₁ = y and −1 along w₂ = −x from O_w: (1, −1, 0) relative to F2.
        return json::parse(R"({
            "from": {"origin": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
            "to": {"origin": [2, 1, 0], "axes": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]},
            "points": [[3, 2, 0]],
            "vectors": [[1, 0, 0]]})");
    }
};

Algorithm change_of_basis_algorithm() {
    return make_algorithm<ChangeOfBasis>(
        [](const ChangeOfBasis::Input& in) { return ChangeOfBasis::transform(in); });
}

}  // namespace cg
