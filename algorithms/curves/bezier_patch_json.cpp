// Bézier patch JSON:
//   input  {"control_points": [[[x, y, z], …], …] ((m + 1) rows of n + 1 points), "s": s, "t": t,
//           "tessellation": N (default 8), "extrapolate": false}
//   result {"point", "ds", "dt", "normal" ([0, 0, 0] when undefined), "normal_defined",
//           "column_points": [Q_0, …, Q_n], "triangles": 2N², "vertices": (N + 1)² points,
//           row-major: vertex a (N + 1) + b = P(a/N, b/N)}
#include "curves/bezier_patch.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<BezierPatch> {
    static BezierPatch::Input input(const json& j) {
        Reader r(j);
        r.only({"control_points", "s", "t", "tessellation", "extrapolate"});
        BezierPatch::Input in;
        const json& grid = r.get("control_points");
        const std::string field = r.field("control_points");
        if (!grid.is_array())
            throw InputError(field, "must be a list of rows of points [x, y, z], got " +
                                        describe(grid));
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const std::string row_field = field + "[" + std::to_string(i) + "]";
            if (!grid[i].is_array())
                throw InputError(row_field,
                                 "must be a row: a list of points [x, y, z], got " + describe(grid[i]));
            std::vector<glm::dvec3> row;
            for (std::size_t k = 0; k < grid[i].size(); ++k)
                row.push_back(as_point3(grid[i][k], row_field + "[" + std::to_string(k) + "]"));
            in.control_points.push_back(std::move(row));
        }
        in.s = r.number("s");
        in.t = r.number("t");
        if (r.has("tessellation")) {
            const long long N = r.integer("tessellation");
            if (N < 1 || N > BezierPatch::kMaxTessellation)
                throw InputError(r.field("tessellation"),
                                 "must be an integer from 1 to " +
                                     std::to_string(BezierPatch::kMaxTessellation) + " (got " +
                                     std::to_string(N) + ")");
            in.tessellation = static_cast<int>(N);
        }
        if (r.has("extrapolate")) in.extrapolate = r.boolean("extrapolate");
        return in;
    }

    static json input_json(const BezierPatch::Input& in) {
        json grid = json::array();
        for (const auto& row : in.control_points) {
            json out = json::array();
            for (const glm::dvec3& p : row) out.push_back(nice_point(p));
            grid.push_back(std::move(out));
        }
        json j{{"control_points", std::move(grid)}, {"s", nice_number(in.s)}, {"t", nice_number(in.t)}};
        if (in.tessellation != 8) j["tessellation"] = in.tessellation;
        if (in.extrapolate) j["extrapolate"] = true;
        return j;
    }

    static json result(const BezierPatch::Result& r) {
        json q = json::array(), v = json::array();
        for (const glm::dvec3& p : r.column_points) q.push_back(to_json(p));
        for (const glm::dvec3& p : r.vertices) v.push_back(to_json(p));
        return json{{"point", to_json(r.point)},
                    {"ds", to_json(r.ds)},
                    {"dt", to_json(r.dt)},
                    {"normal", to_json(r.normal)},
                    {"normal_defined", r.normal_defined},
                    {"column_points", std::move(q)},
                    {"triangles", r.triangle_count()},
                    {"vertices", std::move(v)}};
    }

    static json example() {
        // A bicubic hill over the square [0, 3]² of the xz-plane, heights in y (the 3D canvas's
        // up): rows run along z, columns along x, so ∂P/∂s × ∂P/∂t points up. Off-centre.
        return json{{"control_points",
                     {{{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}},
                      {{0, 1, 1}, {1, 3, 1}, {2, 3, 1}, {3, 1, 1}},
                      {{0, 1, 2}, {1, 3, 2}, {2, 2, 2}, {3, 1, 2}},
                      {{0, 0, 3}, {1, 1, 3}, {2, 1, 3}, {3, 0, 3}}}},
                    {"s", 0.4},
                    {"t", 0.7}};
    }
};

Algorithm bezier_patch_algorithm() {
    return make_algorithm<BezierPatch>(
        [](const BezierPatch::Input& in) { return BezierPatch::evaluate(in); });
}

}  // namespace cg
