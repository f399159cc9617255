// The slab test, JSON:
//   input  {"box": {"min": [x, y, z], "max": [x, y, z]} (min ≤ max on every axis; flat allowed),
//           "origin": [x, y, z] (E), "direction": [x, y, z] (d, not zero; any length)}
//   result {"hit": the half-line t ≥ 0 meets the closed box,
//           "verdict": "hit" | "inside" (E in the box: t_min ≤ 0) | "miss-disjoint" (t_min >
//                      t_max, the early-out) | "miss-behind" (t_max < 0),
//           "t_min", "t_max": max of the t_near and min of the t_far worked (t_min < 0 when E
//                      is inside),
//           "t_hit": where the ray meets the box's surface — t_min, or t_max from inside;
//                      null for a miss,
//           "axes": [{"t_near", "t_far"}, …] for x, y, z in order, only those worked (fewer
//                      than three after an early-out)}
//   An infinite t is the string "inf" or "-inf" (JSON has no infinities): a direction
//   component 0 gives the slab ("-inf", "inf") when E is between its planes and the empty slab
//   ("inf", "-inf") when it is not. Every finite t is a number.
#include "accel/ray_aabb.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

json t_json(double t) {
    if (std::isinf(t)) return t > 0 ? "inf" : "-inf";
    return t;
}

const char* verdict_name(RayAabb::Verdict v) {
    switch (v) {
        case RayAabb::Verdict::Hit:
            return "hit";
        case RayAabb::Verdict::Inside:
            return "inside";
        case RayAabb::Verdict::Disjoint:
            return "miss-disjoint";
        case RayAabb::Verdict::Behind:
            return "miss-behind";
        case RayAabb::Verdict::None:
            break;
    }
    return "none";
}

}  // namespace

template <>
struct JsonIo<RayAabb> {
    static RayAabb::Input input(const json& j) {
        Reader r(j);
        r.only({"box", "origin", "direction"});
        const Reader box = r.object("box");
        box.only({"min", "max"});
        RayAabb::Input in;
        in.min = box.point3("min");
        in.max = box.point3("max");
        in.origin = r.point3("origin");
        in.direction = r.point3("direction");
        return in;
    }

    static json input_json(const RayAabb::Input& in) {
        return json{{"box", {{"min", nice_point(in.min)}, {"max", nice_point(in.max)}}},
                    {"origin", nice_point(in.origin)},
                    {"direction", nice_point(in.direction)}};
    }

    static json result(const RayAabb::Result& r) {
        json axes = json::array();
        for (int i = 0; i < r.count; ++i)
            axes.push_back(
                {{"t_near", t_json(r.axes[i].t_near)}, {"t_far", t_json(r.axes[i].t_far)}});
        return json{{"hit", r.hit},
                    {"verdict", verdict_name(r.verdict)},
                    {"t_min", t_json(r.t_min)},
                    {"t_max", t_json(r.t_max)},
                    {"t_hit", r.hit ? json(r.t_hit) : json(nullptr)},
                    {"axes", std::move(axes)}};
    }

    static json example() {
        // The lesson's first preset: in through the x = 0 face, out through the y = 2 face.
        return json{{"box", {{"min", {0, 0, 0}}, {"max", {4, 2, 2}}}},
                    {"origin", {-2, 0, 0.5}},
                    {"direction", {2, 1, 0.5}}};
    }
};

Algorithm ray_aabb_algorithm() {
    return make_algorithm<RayAabb>([](const RayAabb::Input& in) { return RayAabb::intersect(in); });
}

}  // namespace cg
