// The uniform grid, JSON:
//   input  {"primitives": [sphere | triangle | box, …] (1 to 64; accel/primitive_json.hpp),
//           "cells": [n_x, n_y, n_z] (whole numbers 1 to 16, at most 512 cells in all),
//           "bounds": {"min": [x, y, z], "max": [x, y, z]} (optional: the grid's box, min < max
//                     on every axis, holding every primitive; default: the scene's bounds, a
//                     flat axis padded),
//           "origin": [x, y, z] (E), "direction": [x, y, z] (d, not zero; any length)}
//   result {"hit": the ray meets a primitive,
//           "primitive": its index (null for a miss), "t", "point": the hit (null for a miss),
//           "cell": [i, j, k] where the walk accepted it (null for a miss),
//           "cells_visited": [[i, j, k], …] in the order the walk visited them,
//           "counts": {"cells_visited", "primitive_tests", "mailbox_skips"},
//           "brute_force": {"primitive_tests": n},
//           "entered": the ray meets the grid's box, "t_start", "t_end": where it is in the
//                     box (null when it misses it),
//           "grid": {"bounds", "cells", "cell_size", "non_empty": [{"cell": [i, j, k],
//                     "primitives": [indices]}, …] in index order (x fastest)}}
#include <string>

#include "accel/primitive_json.hpp"
#include "accel/uniform_grid.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

json grid_cell_json(const UniformGrid::Cell& c) {
    return json::array({c[0], c[1], c[2]});
}

UniformGrid::Cell grid_cells_read(const Reader& r) {
    const json& v = r.get("cells");
    if (!v.is_array() || v.size() != 3)
        throw InputError(r.field("cells"),
                         "must be [n_x, n_y, n_z], three whole numbers, got " + describe(v));
    UniformGrid::Cell c{};
    for (std::size_t i = 0; i < 3; ++i) {
        const std::string f = element(r.field("cells"), i);
        const double x = as_number(v[i], f);
        if (x != std::floor(x) || x < 1 || x > UniformGrid::kMaxAxisCells)
            throw InputError(f, "must be a whole number from 1 to " +
                                    std::to_string(UniformGrid::kMaxAxisCells) + ", got " +
                                    describe(v[i]));
        c[i] = static_cast<int>(x);
    }
    return c;
}

}  // namespace

template <>
struct JsonIo<UniformGrid> {
    static UniformGrid::Input input(const json& j) {
        Reader r(j);
        r.only({"primitives", "cells", "bounds", "origin", "direction"});
        UniformGrid::Input in;
        in.primitives = accel_json::primitives(r, "primitives", UniformGrid::kMaxPrimitives);
        in.cells = grid_cells_read(r);
        if (r.has("bounds")) {
            const Reader b = r.object("bounds");
            b.only({"min", "max"});
            in.has_bounds = true;
            in.bounds.min = b.point3("min");
            in.bounds.max = b.point3("max");
        }
        in.origin = r.point3("origin");
        in.direction = r.point3("direction");
        return in;
    }

    static json input_json(const UniformGrid::Input& in) {
        json j{{"primitives", accel_json::primitives_json(in.primitives)},
               {"cells", grid_cell_json(in.cells)}};
        if (in.has_bounds)
            j["bounds"] = {{"min", nice_point(in.bounds.min)}, {"max", nice_point(in.bounds.max)}};
        j["origin"] = nice_point(in.origin);
        j["direction"] = nice_point(in.direction);
        return j;
    }

    static json result(const UniformGrid::Result& r) {
        json visited = json::array();
        for (const auto& c : r.cells_visited) visited.push_back(grid_cell_json(c));
        const UniformGrid::Grid& g = *r.grid;
        json non_empty = json::array();
        for (std::size_t i = 0; i < g.cells.size(); ++i) {
            if (g.cells[i].empty()) continue;
            const int ci = static_cast<int>(i);
            const UniformGrid::Cell c{ci % g.n[0], (ci / g.n[0]) % g.n[1], ci / (g.n[0] * g.n[1])};
            non_empty.push_back({{"cell", grid_cell_json(c)}, {"primitives", g.cells[i]}});
        }
        const json none(nullptr);
        return json{
            {"hit", r.hit},
            {"primitive", r.hit ? json(r.primitive) : none},
            {"t", r.hit ? json(r.t) : none},
            {"point", r.hit ? to_json(r.point) : none},
            {"cell", r.hit ? grid_cell_json(r.cell) : none},
            {"cells_visited", std::move(visited)},
            {"counts",
             {{"cells_visited", r.cells_visited.size()},
              {"primitive_tests", r.primitive_tests},
              {"mailbox_skips", r.mailbox_skips}}},
            {"brute_force", {{"primitive_tests", r.brute_force_tests}}},
            {"entered", r.entered},
            {"t_start", r.entered ? json(r.t_start) : none},
            {"t_end", r.entered ? json(r.t_end) : none},
            {"grid",
             {{"bounds", {{"min", to_json(g.box.min)}, {"max", to_json(g.box.max)}}},
              {"cells", grid_cell_json(g.n)},
              {"cell_size", to_json(g.size)},
              {"non_empty", std::move(non_empty)}}},
        };
    }

    static json example() {
        // The lesson's first preset: a 4 × 4 × 1 grid of unit cells; the big sphere 0 reaches
        // into cell [0, 1, 0] but the ray meets it only at t = 2.56, beyond that cell's exit
        // t = 2, and the small sphere 1 in the next cell is nearer (t = 2.3).
        return json{{"primitives",
                     {{{"type", "sphere"}, {"center", {2, 2.7, 0.5}}, {"radius", 1.25}},
                      {{"type", "sphere"}, {"center", {1.5, 1.25, 0.5}}, {"radius", 0.25}},
                      {{"type", "box"}, {"min", {2.5, 0.25, 0.25}}, {"max", {3.5, 0.75, 0.75}}}}},
                    {"cells", {4, 4, 1}},
                    {"bounds", {{"min", {0, 0, -1}}, {"max", {4, 4, 2}}}},
                    {"origin", {-1, 0.25, 0.5}},
                    {"direction", {1, 0.5, 0}}};
    }
};

Algorithm uniform_grid_algorithm() {
    return make_algorithm<UniformGrid>(
        [](const UniformGrid::Input& in) { return UniformGrid::trace(in); });
}

}  // namespace cg
