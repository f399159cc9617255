// Marching squares, JSON:
//   input  {"field": "grid" | "circle" | "blobs" | "noise" (optional, "grid"),
//           "values": [[f(0,0), f(1,0), …], [f(0,1), …], …] (grid: rows from the bottom, at
//                     least 2 × 2, at most 257 × 257, every row the same length),
//           "cells": n (named fields: cells a side on [−1, 1]², 1 to 256; optional, 16),
//           "radius": r (circle radius, blob radius; optional, 0.7),
//           "seed": the noise seed (noise only; optional, 1),
//           "iso": the threshold (a point is inside when f < iso)}
//   result {"cases": rows of case indices from the bottom, "segments": [[a, b], …] (inside on
//           the left), "crossings": one point per grid edge where the sign changes,
//           "segment_count", "length", "inside": grid points with f < iso, "saddles",
//           "joined": saddles whose inside corners were joined, "loops": closed contours,
//           "chains": open contours ending on the border}
#include "io/registry.hpp"
#include "modelling/marching_squares.hpp"

namespace cg {

namespace marching_squares_json {

const char* field_id(MarchingSquares::Field f) {
    switch (f) {
        case MarchingSquares::Field::Grid: return "grid";
        case MarchingSquares::Field::Circle: return "circle";
        case MarchingSquares::Field::Blobs: return "blobs";
        case MarchingSquares::Field::Noise: return "noise";
    }
    return "grid";
}

}  // namespace marching_squares_json

template <>
struct JsonIo<MarchingSquares> {
    using MS = MarchingSquares;
    static MS::Input input(const json& j) {
        Reader r(j);
        r.only({"field", "values", "cells", "radius", "seed", "iso"});
        MS::Input in;
        const std::string f = r.has("field") ? r.string("field") : "grid";
        if (f == "grid")
            in.field = MS::Field::Grid;
        else if (f == "circle")
            in.field = MS::Field::Circle;
        else if (f == "blobs")
            in.field = MS::Field::Blobs;
        else if (f == "noise")
            in.field = MS::Field::Noise;
        else
            throw InputError(r.field("field"), "must be \"grid\", \"circle\", \"blobs\" or "
                                               "\"noise\", got \"" + f + "\"");
        const bool grid = in.field == MS::Field::Grid;
        if (grid) {
            for (const char* k : {"cells", "radius", "seed"})
                if (r.has(k))
                    throw InputError(r.field(k), "is for a named field; a grid gives its values");
            const json& v = r.get("values");
            if (!v.is_array())
                throw InputError(r.field("values"),
                                 "must be a list of rows of numbers, got " + describe(v));
            if (v.size() > std::size_t(MS::kMaxCells) + 1)
                throw InputError(r.field("values"), "has " + std::to_string(v.size()) +
                                                        " rows; at most " +
                                                        std::to_string(MS::kMaxCells + 1));
            for (std::size_t jj = 0; jj < v.size(); ++jj) {
                const std::string row = element(r.field("values"), jj);
                if (!v[jj].is_array())
                    throw InputError(row, "must be a list of numbers, got " + describe(v[jj]));
                if (v[jj].size() > std::size_t(MS::kMaxCells) + 1)
                    throw InputError(row, "has " + std::to_string(v[jj].size()) +
                                              " values; at most " +
                                              std::to_string(MS::kMaxCells + 1));
                std::vector<double> values;
                for (std::size_t i = 0; i < v[jj].size(); ++i)
                    values.push_back(as_number(v[jj][i], element(row, i)));
                in.values.push_back(std::move(values));
            }
        } else {
            if (r.has("values"))
                throw InputError(r.field("values"), "only with \"field\": \"grid\"");
            if (r.has("cells"))
                in.cells = int(r.integer("cells", 1, MS::kMaxCells,
                                         "1 to " + std::to_string(MS::kMaxCells)));
            if (r.has("radius")) in.radius = r.number("radius");
            if (r.has("seed")) {
                if (in.field != MS::Field::Noise)
                    throw InputError(r.field("seed"), "only with \"field\": \"noise\"");
                in.seed = std::uint64_t(r.integer("seed", 0, 1LL << 53, "0 to 2^53"));
            }
        }
        in.iso = r.number("iso");
        return in;
    }

    static json input_json(const MS::Input& in) {
        json j;
        j["field"] = marching_squares_json::field_id(in.field);
        if (in.field == MS::Field::Grid) {
            json rows = json::array();
            for (const auto& row : in.values) {
                json jr = json::array();
                for (double v : row) jr.push_back(nice_number(v));
                rows.push_back(jr);
            }
            j["values"] = rows;
        } else {
            j["cells"] = in.cells;
            j["radius"] = nice_number(in.radius);
            if (in.field == MS::Field::Noise) j["seed"] = in.seed;
        }
        j["iso"] = nice_number(in.iso);
        return j;
    }

    static json result(const MS::Result& r) {
        json j;
        json cases = json::array();
        for (int jj = 0; jj < r.ny; ++jj) {
            json row = json::array();
            for (int i = 0; i < r.nx; ++i) row.push_back(int(r.cases[std::size_t(jj * r.nx + i)]));
            cases.push_back(row);
        }
        j["cases"] = cases;
        json segs = json::array();
        for (const auto& s : r.segments) segs.push_back({to_json(s.a), to_json(s.b)});
        j["segments"] = segs;
        json cross = json::array();
        for (const auto& p : r.crossings) cross.push_back(to_json(p));
        j["crossings"] = cross;
        j["segment_count"] = r.segments.size();
        j["length"] = r.length;
        j["inside"] = r.inside;
        j["saddles"] = r.saddles;
        j["joined"] = r.joined;
        j["loops"] = r.loops;
        j["chains"] = r.chains;
        return j;
    }

    static json example() {
        // A 3 × 3 grid of values around a hill of low values; one saddle cell.
        return parse_json(R"({"field": "grid", "values": [[3, 2, 3, 4], [1, -2, 1, 3],
                              [2, 1, -1, 2], [4, 3, 2, 3]], "iso": 0})");
    }
};

Algorithm marching_squares_algorithm() {
    return make_algorithm<MarchingSquares>(
        [](const MarchingSquares::Input& in) { return MarchingSquares::compute(in); });
}

}  // namespace cg
