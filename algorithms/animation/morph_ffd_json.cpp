// Free-form deformation, JSON:
//   input  {"box": {"min": [x, y], "max": [x, y]} (default [0, 0] to [1, 1]),
//           "degree": [l, m] (each 1 to 8; default [2, 2]),
//           "moves": [{"point": [i, j], "by": [dx, dy]} or {"point": [i, j], "to": [x, y]}]
//                    (applied in order; at most 1000),
//           "shape": [[x, y], …] (1 to 5000 points), "closed": false (a polygon when true)}
//          In space the box's dimension decides: a box of 3D points makes the lattice spatial,
//          and then "degree" is [l, m, n] (each 1 to 8; default [2, 2, 2]), a move's "point" is
//          [i, j, k] and its "by"/"to" 3D, the shape's points are [x, y, z], and "edges":
//          [[a, b], …] (optional, at most 10000) draws the shape as a wireframe of those pairs
//          of point indices instead of a polyline.
//   result {"lattice": the moved control points [x, y], P_ij at i·(m+1) + j,
//           "local": (s, t) of every point, "inside": 0 ≤ s, t ≤ 1 for every point,
//           "deformed": where every point goes (itself when outside),
//           "inside_count", "outside_count"}
//          (in space [x, y, z] points, P_ijk at (i·(m+1) + j)·(n+1) + k, "local" (s, t, u))
#include <cmath>

#include "animation/morph_ffd.hpp"
#include "core/format.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<MorphFfd> {
    static MorphFfd::Input input(const json& j) {
        Reader r(j);
        r.only({"box", "degree", "moves", "shape", "closed", "edges"});
        if (r.has("box")) {  // the box's dimension decides: 3D points make a spatial lattice
            const json& b = r.get("box");
            if (b.is_object() && b.contains("min") && b["min"].is_array() && b["min"].size() == 3)
                return input3(r);
        }
        if (r.has("edges"))
            throw InputError(r.field("edges"), "is for a 3D shape: give a box of 3D points "
                                               "({\"min\": [x, y, z], …})");
        MorphFfd::Input in;
        if (r.has("box")) {
            const Reader b = r.object("box");
            b.only({"min", "max"});
            in.box_min = b.point2("min");
            in.box_max = b.point2("max");
        }
        if (r.has("degree")) {
            const json& d = r.get("degree");
            const std::string f = r.field("degree");
            if (!d.is_array() || d.size() != 2)
                throw InputError(f, "must be [l, m], the lattice's degrees along x and y, got " +
                                        describe(d));
            for (std::size_t c = 0; c < 2; ++c) {
                const double v = as_number(d[c], element(f, c));
                if (v != std::floor(v) || v < 1 || v > MorphFfd::kMaxDegree)
                    throw InputError(element(f, c), "must be a whole degree 1 to " +
                                                        std::to_string(MorphFfd::kMaxDegree) +
                                                        " (got " + given(v) + ")");
                (c == 0 ? in.l : in.m) = int(v);
            }
        }
        if (r.has("moves")) {
            const json& ms = r.get("moves");
            const std::string mf = r.field("moves");
            if (!ms.is_array()) throw InputError(mf, "must be a list of moves, got " + describe(ms));
            if (ms.size() > std::size_t(MorphFfd::kMaxMoves))
                throw InputError(mf, "has " + std::to_string(ms.size()) + " moves; at most " +
                                         std::to_string(MorphFfd::kMaxMoves));
            for (std::size_t q = 0; q < ms.size(); ++q) {
                const Reader m(ms[q], element(mf, q));
                m.only({"point", "by", "to"});
                MorphFfd::Move mv;
                const json& p = m.get("point");
                const std::string pf = m.field("point");
                if (!p.is_array() || p.size() != 2)
                    throw InputError(pf, "must be a control point [i, j], got " + describe(p));
                for (std::size_t c = 0; c < 2; ++c) {
                    const double v = as_number(p[c], element(pf, c));
                    if (v != std::floor(v) || std::fabs(v) > 1e6)
                        throw InputError(element(pf, c), "must be a whole index (got " + given(v) + ")");
                    (c == 0 ? mv.i : mv.j) = int(v);
                }
                if (m.has("by") == m.has("to"))
                    throw InputError(m.path(), "needs exactly one of \"by\" (a displacement) and "
                                               "\"to\" (a position)");
                mv.absolute = m.has("to");
                mv.value = m.point2(mv.absolute ? "to" : "by");
                in.moves.push_back(mv);
            }
        }
        if (!r.has("shape"))
            throw InputError("shape", "is missing: give the points to deform, [[x, y], …]");
        {
            const json& sh = r.get("shape");
            if (sh.is_array() && sh.size() > std::size_t(MorphFfd::kMaxPoints))
                throw InputError(r.field("shape"), "has " + std::to_string(sh.size()) +
                                                       " points; at most " +
                                                       std::to_string(MorphFfd::kMaxPoints));
            in.shape = r.points2("shape");
        }
        if (r.has("closed")) in.closed = r.boolean("closed");
        return in;
    }

    // The spatial input: the box's min has 3 components.
    static MorphFfd::Input input3(const Reader& r) {
        MorphFfd::Input in;
        in.n = 2;
        {
            const Reader b = r.object("box");
            b.only({"min", "max"});
            in.box3_min = b.point3("min");
            in.box3_max = b.point3("max");
        }
        if (r.has("degree")) {
            const json& d = r.get("degree");
            const std::string f = r.field("degree");
            if (!d.is_array() || d.size() != 3)
                throw InputError(f, "must be [l, m, n] for a 3D box, the lattice's degrees along "
                                    "x, y and z, got " + describe(d));
            for (std::size_t c = 0; c < 3; ++c) {
                const double v = as_number(d[c], element(f, c));
                if (v != std::floor(v) || v < 1 || v > MorphFfd::kMaxDegree)
                    throw InputError(element(f, c), "must be a whole degree 1 to " +
                                                        std::to_string(MorphFfd::kMaxDegree) +
                                                        " (got " + given(v) + ")");
                (c == 0 ? in.l : c == 1 ? in.m : in.n) = int(v);
            }
        } else {
            in.l = in.m = 2;
        }
        if (r.has("moves")) {
            const json& ms = r.get("moves");
            const std::string mf = r.field("moves");
            if (!ms.is_array()) throw InputError(mf, "must be a list of moves, got " + describe(ms));
            if (ms.size() > std::size_t(MorphFfd::kMaxMoves))
                throw InputError(mf, "has " + std::to_string(ms.size()) + " moves; at most " +
                                         std::to_string(MorphFfd::kMaxMoves));
            for (std::size_t q = 0; q < ms.size(); ++q) {
                const Reader m(ms[q], element(mf, q));
                m.only({"point", "by", "to"});
                MorphFfd::Move3 mv;
                const json& p = m.get("point");
                const std::string pf = m.field("point");
                if (!p.is_array() || p.size() != 3)
                    throw InputError(pf, "must be a control point [i, j, k] of the 3D lattice, got " +
                                             describe(p));
                for (std::size_t c = 0; c < 3; ++c) {
                    const double v = as_number(p[c], element(pf, c));
                    if (v != std::floor(v) || std::fabs(v) > 1e6)
                        throw InputError(element(pf, c), "must be a whole index (got " + given(v) + ")");
                    (c == 0 ? mv.i : c == 1 ? mv.j : mv.k) = int(v);
                }
                if (m.has("by") == m.has("to"))
                    throw InputError(m.path(), "needs exactly one of \"by\" (a displacement) and "
                                               "\"to\" (a position)");
                mv.absolute = m.has("to");
                mv.value = m.point3(mv.absolute ? "to" : "by");
                in.moves3.push_back(mv);
            }
        }
        if (!r.has("shape"))
            throw InputError("shape", "is missing: give the points to deform, [[x, y, z], …]");
        {
            const json& sh = r.get("shape");
            if (sh.is_array() && sh.size() > std::size_t(MorphFfd::kMaxPoints))
                throw InputError(r.field("shape"), "has " + std::to_string(sh.size()) +
                                                       " points; at most " +
                                                       std::to_string(MorphFfd::kMaxPoints));
            in.shape3 = r.points3("shape");
        }
        if (r.has("closed")) in.closed = r.boolean("closed");
        if (r.has("edges")) {
            const json& es = r.get("edges");
            const std::string ef = r.field("edges");
            if (!es.is_array()) throw InputError(ef, "must be a list of [a, b] index pairs, got " + describe(es));
            if (es.size() > std::size_t(MorphFfd::kMaxEdges))
                throw InputError(ef, "has " + std::to_string(es.size()) + " edges; at most " +
                                         std::to_string(MorphFfd::kMaxEdges));
            for (std::size_t e = 0; e < es.size(); ++e) {
                const std::string f = element(ef, e);
                if (!es[e].is_array() || es[e].size() != 2)
                    throw InputError(f, "must be a pair [a, b] of shape point indices, got " +
                                            describe(es[e]));
                std::array<int, 2> pair{};
                for (std::size_t c = 0; c < 2; ++c) {
                    const double v = as_number(es[e][c], element(f, c));
                    if (v != std::floor(v) || std::fabs(v) > 1e6)
                        throw InputError(element(f, c), "must be a whole index (got " + given(v) + ")");
                    pair[c] = int(v);
                }
                in.edges.push_back(pair);
            }
        }
        return in;
    }

    static json input_json3(const MorphFfd::Input& in) {
        json j;
        j["box"] = {{"min", nice_point(in.box3_min)}, {"max", nice_point(in.box3_max)}};
        j["degree"] = {in.l, in.m, in.n};
        json ms = json::array();
        for (const auto& mv : in.moves3) {
            json o = {{"point", {mv.i, mv.j, mv.k}}};
            o[mv.absolute ? "to" : "by"] = nice_point(mv.value);
            ms.push_back(o);
        }
        j["moves"] = ms;
        json sh = json::array();
        for (const auto& p : in.shape3) sh.push_back(nice_point(p));
        j["shape"] = sh;
        j["closed"] = in.closed;
        if (!in.edges.empty()) {
            json es = json::array();
            for (const auto& e : in.edges) es.push_back({e[0], e[1]});
            j["edges"] = es;
        }
        return j;
    }

    static json input_json(const MorphFfd::Input& in) {
        if (in.spatial()) return input_json3(in);
        json j;
        j["box"] = {{"min", nice_point(in.box_min)}, {"max", nice_point(in.box_max)}};
        j["degree"] = {in.l, in.m};
        json ms = json::array();
        for (const auto& mv : in.moves) {
            json o = {{"point", {mv.i, mv.j}}};
            o[mv.absolute ? "to" : "by"] = nice_point(mv.value);
            ms.push_back(o);
        }
        j["moves"] = ms;
        json sh = json::array();
        for (const auto& p : in.shape) sh.push_back(nice_point(p));
        j["shape"] = sh;
        j["closed"] = in.closed;
        return j;
    }

    static json result(const MorphFfd::Result& r) {
        json j;
        json lat = json::array(), loc = json::array(), def = json::array(), ins = json::array();
        for (const auto& p : r.lattice) lat.push_back(to_json(p));
        for (const auto& p : r.local) loc.push_back(to_json(p));
        for (const auto& p : r.deformed) def.push_back(to_json(p));
        for (const auto& p : r.lattice3) lat.push_back(to_json(p));  // in space (the 2D ones empty)
        for (const auto& p : r.local3) loc.push_back(to_json(p));
        for (const auto& p : r.deformed3) def.push_back(to_json(p));
        for (char c : r.inside) ins.push_back(bool(c));
        j["lattice"] = lat;
        j["local"] = loc;
        j["inside"] = ins;
        j["deformed"] = def;
        j["inside_count"] = r.inside_count;
        j["outside_count"] = int(r.inside.size()) - r.inside_count;
        return j;
    }

    static json example() {
        // A bilinear lattice over [0, 4]², its top-right corner pulled out: the exam-style case.
        return parse_json(R"({
            "box": {"min": [0, 0], "max": [4, 4]}, "degree": [1, 1],
            "moves": [{"point": [1, 1], "by": [2, 1]}],
            "shape": [[1, 1], [3, 1], [3, 3], [1, 3], [2, 2], [5, 2]], "closed": false})");
    }
};

Algorithm morph_ffd_algorithm() {
    return make_algorithm<MorphFfd>([](const MorphFfd::Input& in) { return MorphFfd::compute(in); });
}

}  // namespace cg
