// Liang-Barsky's JSON:
//   input  {"window": {"xmin", "ymin", "xmax", "ymax"}, "p0": [x, y], "p1": [x, y]}
//   result {"visible", "t_enter", "t_leave", "q0": [x, y] | null, "q1": [x, y] | null,
//           "edges": {"left" | "right" | "bottom" | "top": {"p", "q", "r": number | null (p = 0),
//                     "crossing": "enters" | "leaves" | "parallel inside" | "parallel outside"}}
//                    (the edges tested, in order, up to a rejection)}
#include "clipping/liang_barsky.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<LiangBarsky> {
    static LiangBarsky::Input input(const json& j) {
        Reader r(j);
        r.only({"window", "p0", "p1"});
        Reader w = r.object("window");
        w.only({"xmin", "ymin", "xmax", "ymax"});
        LiangBarsky::Input in;
        in.window = {w.number("xmin"), w.number("ymin"), w.number("xmax"), w.number("ymax")};
        in.p0 = r.point2("p0");
        in.p1 = r.point2("p1");
        return in;
    }

    static json input_json(const LiangBarsky::Input& in) {
        const auto& w = in.window;
        return json{{"window",
                     {{"xmin", nice_number(w.xmin)}, {"ymin", nice_number(w.ymin)},
                      {"xmax", nice_number(w.xmax)}, {"ymax", nice_number(w.ymax)}}},
                    {"p0", nice_point(in.p0)},
                    {"p1", nice_point(in.p1)}};
    }

    static json result(const LiangBarsky::Result& r) {
        // The table a student writes, one row an edge tested: p, q, r (null where p = 0) and
        // what the line does there.
        json edges = json::object();
        for (const LiangBarsky::EdgeTest& e : r.edges) {
            using V = LiangBarsky::Verdict;
            const char* crossing = e.verdict == V::Entering  ? "enters"
                                   : e.verdict == V::Leaving ? "leaves"
                                   : e.verdict == V::ParallelInside ? "parallel inside"
                                                                    : "parallel outside";
            // + 0.0: −dy of a horizontal segment is −0, which a person writes 0.
            edges[LiangBarsky::kEdgeName[e.k]] = {{"p", e.p + 0.0},
                                                  {"q", e.q + 0.0},
                                                  {"r", e.p != 0 ? json(e.r) : json(nullptr)},
                                                  {"crossing", crossing}};
        }
        return json{{"visible", r.visible},
                    {"t_enter", r.t_enter},
                    {"t_leave", r.t_leave},
                    {"q0", r.q0 ? to_json(*r.q0) : json(nullptr)},
                    {"q1", r.q1 ? to_json(*r.q1) : json(nullptr)},
                    {"edges", std::move(edges)}};
    }

    static json example() {
        // The segment enters through the left edge and leaves through the top one.
        return json{{"window", {{"xmin", 1}, {"ymin", 1}, {"xmax", 5}, {"ymax", 4}}},
                    {"p0", {0, 2}},
                    {"p1", {4, 6}}};
    }
};

Algorithm liang_barsky_algorithm() {
    return make_algorithm<LiangBarsky>(
        [](const LiangBarsky::Input& in) { return LiangBarsky::clip(in); });
}

}  // namespace cg
