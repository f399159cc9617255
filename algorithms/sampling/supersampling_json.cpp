// Supersampling, JSON:
//   input  {"pattern": "regular" | "random" | "jittered" | "poisson", "samples": N (n² for
//           regular and jittered), "filter": "box" | "tent" | "gaussian" (optional, box),
//           "radius": r (optional, poisson only; default 0.7/√N), "pixel": [i, j] (integers),
//           "scene": {"type": "edge", "point": [x, y], "angle": degrees}
//                  | {"type": "polygon", "points": [[x, y], …]},
//           "seed": integer ≥ 0 (optional, 1)}
//        | {"study": {"patterns": [names, distinct] (optional, all four),
//                     "samples": [N, …] (optional, [1, 4, 16, 64, 256]; 2 to 8 increasing
//                                counts of at most 256, at least two of them ≥ 4, squares when
//                                regular or jittered is studied),
//                     "edges": trials per point (optional, 400; at most 1000),
//                     "angles": "any" | "near-axis" (optional, any; near-axis: within 1° of x),
//                     "filter": as above (optional, box), "seed": as above (optional, 1)}}
//           a convergence study; the pixel's fields cannot be given beside it.
//   result {"samples": [[x, y, value, weight], …], "estimate", "exact", "error",
//           "weight_sum", "covered": the covered polygon, "radius" (poisson)}
//        | a study: {"study": [{"pattern", "samples", "rms_error"}, …] pattern by pattern,
//                    "slopes": {pattern: least-squares slope of log error against log N, …}}
#include <cmath>

#include "io/registry.hpp"
#include "sampling/pattern_json.hpp"
#include "sampling/supersampling.hpp"

namespace cg {

template <>
struct JsonIo<Supersampling> {
    static Supersampling::Input study(const Reader& r) {
        r.only({"patterns", "samples", "edges", "angles", "filter", "seed"});
        Supersampling::Input in;
        in.is_study = true;
        Supersampling::Study& st = in.study;
        if (r.has("patterns")) {
            const json& v = r.get("patterns");
            if (!v.is_array())
                throw InputError(r.field("patterns"),
                                 "must be a list of pattern names, got " + describe(v));
            for (std::size_t k = 0; k < v.size(); ++k) {
                sampling::Pattern p;
                if (!v[k].is_string() || !sampling::parse_pattern(v[k].get<std::string>(), p))
                    throw InputError(r.field("patterns") + "[" + std::to_string(k) + "]",
                                     "must be \"regular\", \"random\", \"jittered\" or "
                                     "\"poisson\", got " +
                                         describe(v[k]));
                st.patterns.push_back(p);
            }
        } else {
            st.patterns = {sampling::Pattern::Regular, sampling::Pattern::Random,
                           sampling::Pattern::Jittered, sampling::Pattern::Poisson};
        }
        if (r.has("samples")) {
            const json& v = r.get("samples");
            if (!v.is_array())
                throw InputError(r.field("samples"),
                                 "must be a list of sample counts, got " + describe(v));
            for (std::size_t k = 0; k < v.size(); ++k) {
                const std::string f = r.field("samples") + "[" + std::to_string(k) + "]";
                const double d = as_number(v[k], f);
                if (d != std::floor(d))
                    throw InputError(f, "must be an integer, got " + describe(v[k]));
                if (d < 1 || d > Supersampling::kMaxStudySamples)
                    throw InputError(f, "must be between 1 and " +
                                            std::to_string(Supersampling::kMaxStudySamples) +
                                            " (got " + describe(v[k]) + ")");
                st.samples.push_back(static_cast<int>(d));
            }
        } else {
            st.samples = {1, 4, 16, 64, 256};
        }
        if (r.has("edges"))
            st.edges = sampling_json::count(r, "edges", Supersampling::kMaxStudyEdges);
        if (r.has("angles")) {
            const std::string a = r.string("angles");
            if (a != "any" && a != "near-axis")
                throw InputError(r.field("angles"), "must be \"any\" or \"near-axis\", got " +
                                                        describe(r.get("angles")));
            st.near_axis = a == "near-axis";
        }
        if (r.has("filter")) in.filter = sampling_json::filter(r, "filter");
        if (r.has("seed")) in.seed = sampling_json::seed(r, "seed");
        return in;
    }

    static Supersampling::Input input(const json& j) {
        Reader r(j);
        if (r.has("study")) {
            for (const char* k :
                 {"pattern", "samples", "filter", "radius", "pixel", "scene", "seed"})
                if (r.has(k))
                    throw InputError(r.field(k),
                                     "cannot be given beside \"study\": a study draws its own "
                                     "edges and patterns (its filter and seed go inside it)");
            r.only({"study"});
            return study(r.object("study"));
        }
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
        if (in.is_study) {
            json patterns = json::array();
            for (auto p : in.study.patterns) patterns.push_back(sampling::pattern_id(p));
            return json{{"study",
                         {{"patterns", std::move(patterns)},
                          {"samples", in.study.samples},
                          {"edges", in.study.edges},
                          {"angles", in.study.near_axis ? "near-axis" : "any"},
                          {"filter", sampling::filter_id(in.filter)},
                          {"seed", in.seed}}}};
        }
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
        if (r.is_study) {
            json points = json::array(), slopes = json::object();
            for (const auto& q : r.study)
                points.push_back({{"pattern", sampling::pattern_id(q.pattern)},
                                  {"samples", q.samples},
                                  {"rms_error", q.rms_error}});
            for (const auto& sl : r.slopes) slopes[sampling::pattern_id(sl.pattern)] = sl.slope;
            return json{{"study", std::move(points)}, {"slopes", std::move(slopes)}};
        }
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
    return make_algorithm<Supersampling>([](const Supersampling::Input& in) {
        return in.is_study ? Supersampling::run_study(in) : Supersampling::supersample(in);
    });
}

}  // namespace cg
