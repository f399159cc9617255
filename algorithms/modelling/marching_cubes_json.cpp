// Marching cubes, JSON:
//   input  {"field": "grid" | "sphere" | "torus" | "blobs" | "gyroid" (optional, "grid"),
//           "values": [[[f(0,0,0), f(1,0,0), …], [f(0,1,0), …], …], [[f(0,0,1), …], …], …]
//                     (grid: layers from the bottom, each rows from the front; at least
//                     2 × 2 × 2, at most 65 a side, every layer and row the same size),
//           "cells": n (named fields: cells a side on [−1, 1]³, 1 to 64; optional, 16),
//           "radius": r (sphere radius, optional 0.7; torus tube radius, optional 0.25, the
//                     ring's radius is 0.6; blob radius, optional 0.35; not for the gyroid),
//           "iso": the threshold (a point is inside when f < iso)}
//   result {"cases": [k][j][i] case indices, "vertices": one point per grid edge where the sign
//           changes, "triangles": [[a, b, c], …] vertex indices counter-clockwise seen from
//           outside, "vertex_count", "triangle_count", "area", "volume" (enclosed, signed),
//           "inside": grid points with f < iso, "ambiguous": saddle faces met, "joined": those
//           joined, "edges", "boundary": edges on one triangle, "nonmanifold": edges on more
//           than two, "euler": V − E + F, "closed": no boundary and no non-manifold edge}
#include "io/registry.hpp"
#include "modelling/marching_cubes.hpp"

namespace cg {

namespace marching_cubes_json {

const char* field_id(MarchingCubes::Field f) {
    switch (f) {
        case MarchingCubes::Field::Grid: return "grid";
        case MarchingCubes::Field::Sphere: return "sphere";
        case MarchingCubes::Field::Torus: return "torus";
        case MarchingCubes::Field::Blobs: return "blobs";
        case MarchingCubes::Field::Gyroid: return "gyroid";
    }
    return "grid";
}

}  // namespace marching_cubes_json

template <>
struct JsonIo<MarchingCubes> {
    using MC = MarchingCubes;
    static MC::Input input(const json& j) {
        Reader r(j);
        r.only({"field", "values", "cells", "radius", "iso"});
        MC::Input in;
        const std::string f = r.has("field") ? r.string("field") : "grid";
        if (f == "grid")
            in.field = MC::Field::Grid;
        else if (f == "sphere")
            in.field = MC::Field::Sphere;
        else if (f == "torus")
            in.field = MC::Field::Torus, in.radius = 0.25;
        else if (f == "blobs")
            in.field = MC::Field::Blobs, in.radius = 0.35;
        else if (f == "gyroid")
            in.field = MC::Field::Gyroid;
        else
            throw InputError(r.field("field"), "must be \"grid\", \"sphere\", \"torus\", "
                                               "\"blobs\" or \"gyroid\", got \"" + f + "\"");
        if (in.field == MC::Field::Grid) {
            for (const char* k : {"cells", "radius"})
                if (r.has(k))
                    throw InputError(r.field(k), "is for a named field; a grid gives its values");
            const json& v = r.get("values");
            const std::size_t most = std::size_t(MC::kMaxCells) + 1;
            auto list = [&](const json& x, const std::string& name, const char* what) {
                if (!x.is_array())
                    throw InputError(name, std::string("must be a list of ") + what + ", got " +
                                               describe(x));
                if (x.size() > most)
                    throw InputError(name, "has " + std::to_string(x.size()) +
                                               " entries; at most " + std::to_string(most));
            };
            list(v, r.field("values"), "layers (lists of rows of numbers)");
            for (std::size_t k = 0; k < v.size(); ++k) {
                const std::string layer = element(r.field("values"), k);
                list(v[k], layer, "rows of numbers");
                std::vector<std::vector<double>> rows;
                for (std::size_t jj = 0; jj < v[k].size(); ++jj) {
                    const std::string row = element(layer, jj);
                    list(v[k][jj], row, "numbers");
                    std::vector<double> values;
                    for (std::size_t i = 0; i < v[k][jj].size(); ++i)
                        values.push_back(as_number(v[k][jj][i], element(row, i)));
                    rows.push_back(std::move(values));
                }
                in.values.push_back(std::move(rows));
            }
        } else {
            if (r.has("values")) throw InputError(r.field("values"), "only with \"field\": \"grid\"");
            if (r.has("cells"))
                in.cells = int(r.integer("cells", 1, MC::kMaxCells,
                                         "1 to " + std::to_string(MC::kMaxCells)));
            if (r.has("radius")) {
                if (in.field == MC::Field::Gyroid)
                    throw InputError(r.field("radius"), "is not used by the gyroid");
                in.radius = r.number("radius");
            }
        }
        in.iso = r.number("iso");
        return in;
    }

    static json input_json(const MC::Input& in) {
        json j;
        j["field"] = marching_cubes_json::field_id(in.field);
        if (in.field == MC::Field::Grid) {
            json layers = json::array();
            for (const auto& layer : in.values) {
                json jl = json::array();
                for (const auto& row : layer) {
                    json jr = json::array();
                    for (double v : row) jr.push_back(nice_number(v));
                    jl.push_back(jr);
                }
                layers.push_back(jl);
            }
            j["values"] = layers;
        } else {
            j["cells"] = in.cells;
            if (in.field != MC::Field::Gyroid) j["radius"] = nice_number(in.radius);
        }
        j["iso"] = nice_number(in.iso);
        return j;
    }

    static json result(const MC::Result& r) {
        json j;
        json cases = json::array();
        for (int k = 0; k < r.nz; ++k) {
            json layer = json::array();
            for (int jj = 0; jj < r.ny; ++jj) {
                json row = json::array();
                for (int i = 0; i < r.nx; ++i)
                    row.push_back(int(r.cases[std::size_t((k * r.ny + jj) * r.nx + i)]));
                layer.push_back(row);
            }
            cases.push_back(layer);
        }
        j["cases"] = cases;
        json verts = json::array();
        for (const auto& p : r.vertices) verts.push_back(to_json(p));
        j["vertices"] = verts;
        json tris = json::array();
        for (const auto& t : r.triangles) tris.push_back({t[0], t[1], t[2]});
        j["triangles"] = tris;
        j["vertex_count"] = r.vertices.size();
        j["triangle_count"] = r.triangles.size();
        j["area"] = r.area;
        j["volume"] = r.volume;
        j["inside"] = r.inside;
        j["ambiguous"] = r.ambiguous;
        j["joined"] = r.joined;
        j["edges"] = r.edges;
        j["boundary"] = r.boundary;
        j["nonmanifold"] = r.nonmanifold;
        j["euler"] = r.euler;
        j["closed"] = r.boundary == 0 && r.nonmanifold == 0;
        return j;
    }

    static json example() {
        // One cube: corner 0 deep inside, corner 1 just inside, the rest outside (case 3).
        return parse_json(R"({"field": "grid", "values": [[[-2, -1], [2, 3]], [[1, 2], [3, 4]]],
                              "iso": 0})");
    }
};

Algorithm marching_cubes_algorithm() {
    return make_algorithm<MarchingCubes>(
        [](const MarchingCubes::Input& in) { return MarchingCubes::compute(in); });
}

}  // namespace cg
