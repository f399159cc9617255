// Free-form deformation, JSON:
//   input  {"box": {"min": [x, y], "max": [x, y]} (default [0, 0] to [1, 1]),
//           "degree": [l, m] (each 1 to 8; default [2, 2]),
//           "moves": [{"point": [i, j], "by": [dx, dy]} or {"point": [i, j], "to": [x, y]}]
//                    (applied in order; at most 1000),
//           "shape": [[x, y], …] (1 to 5000 points), "closed": false (a polygon when true)}
//   result {"lattice": the moved control points [x, y], P_ij at i·(m+1) + j,
//           "local": (s, t) of every point, "inside": 0 ≤ s, t ≤ 1 for every point,
//           "deformed": where every point goes (itself when outside),
//           "inside_count", "outside_count"}
#include <cmath>

#include "animation/morph_ffd.hpp"
#include "core/format.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<MorphFfd> {
    static MorphFfd::Input input(const json& j) {
        Reader r(j);
        r.only({"box", "degree", "moves", "shape", "closed"});
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
                                                        " (got " + num(v) + ")");
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
                        throw InputError(element(pf, c), "must be a whole index (got " + num(v) + ")");
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

    static json input_json(const MorphFfd::Input& in) {
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
        for (char c : r.inside) ins.push_back(bool(c));
        j["lattice"] = lat;
        j["local"] = loc;
        j["inside"] = ins;
        j["deformed"] = def;
        j["inside_count"] = r.inside_count;
        j["outside_count"] = int(r.deformed.size()) - r.inside_count;
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
