// Supersampling, JSON:
//   input  {"pattern": "regular" | "random" | "jittered" | "poisson", "samples": N (n² for
//           regular and jittered), "filter": "box" | "tent" | "gaussian" (optional, box),
//           "radius": r (optional, poisson only; default 0.7/√N), "pixel": [i, j] (integers),
//           "scene": {"type": "edge", "point": [x, y], "angle": degrees}
//                  | {"type": "polygon", "points": [[x, y], …]},
//           "seed": integer ≥ 0 (optional, 1)}
//   result {"samples": [[x, y, value, weight], …], "estimate", "exact", "error",
//           "weight_sum", "covered": the covered polygon, "radius" (poisson)}
#include "io/registry.hpp"
#include "sampling/pattern_json.hpp"
#include "sampling/supersampling.hpp"

namespace cg {

template <>
struct JsonIo<Supersampling> {
    static Supersampling::Input input(const json& j) {
        Reader r(j);
        r.only({"pattern", "samples", "filter", "radius", "pixel", "scene", "seed"});
        Supersampling::Input in;
        in.pattern = sampling_json::pattern(r, "pattern");
        in.samples = sampling_json::count(r, "samples", Supersampling::kMaxSamples);
        if (r.has("filter")) in.filter = sampling_json::filter(r, "filter");
        if (r.has("radius")) {
            if (in.pattern != sampling::Pattern::Poisson)
                throw InputError(r.field("radius"),
                                 "only the poisson pattern has a radius (the pattern is " +
                                     std::string(sampling::pattern_id(in.pattern)) + ")");
            in.radius = r.number("radius");
        }
        const glm::ivec2 px = sampling_json::pixel(r, "pixel", Supersampling::kMaxCoordinate);
        in.i = px.x, in.j = px.y;
        in.scene = sampling_json::region(r.object("scene"));
        if (r.has("seed")) in.seed = sampling_json::seed(r, "seed");
        return in;
    }

    static json input_json(const Supersampling::Input& in) {
        json j{{"pattern", sampling::pattern_id(in.pattern)},
               {"samples", in.samples},
               {"filter", sampling::filter_id(in.filter)}};
        if (in.pattern == sampling::Pattern::Poisson && in.radius > 0) j["radius"] = in.radius;
        j["pixel"] = json::array({in.i, in.j});
        j["scene"] = sampling_json::region_json(in.scene);
        j["seed"] = in.seed;
        return j;
    }

    static json result(const Supersampling::Result& r) {
        json samples = json::array();
        for (const auto& s : r.samples)
            samples.push_back(json::array({s.p.x, s.p.y, s.value, s.weight}));
        json covered = json::array();
        for (const auto& p : r.covered) covered.push_back(to_json(p));
        json j{{"samples", std::move(samples)},
               {"estimate", r.estimate},
               {"exact", r.exact},
               {"error", r.error},
               {"weight_sum", r.weight_sum},
               {"covered", std::move(covered)}};
        if (r.radius > 0) j["radius"] = r.radius;
        return j;
    }

    static json example() {
        // An edge at 30° through the pixel, 16 jittered samples.
        return json{{"pattern", "jittered"},
                    {"samples", 16},
                    {"filter", "box"},
                    {"pixel", {2, 1}},
                    {"scene", {{"type", "edge"}, {"point", {2.3, 1.2}}, {"angle", 30}}},
                    {"seed", 7}};
    }
};

Algorithm supersampling_algorithm() {
    return make_algorithm<Supersampling>();
}

}  // namespace cg
