// Arc length's JSON:
//   input  {"control_points": [[x, y], …] or [[x, y, z], …], "samples": N (default 10),
//           "distances": [s, …] | "fractions": [f, …]  (optional, not both)}
//   result {"table": [[u, s], …], "length": L, "length_exact": L*, "length_error": L − L*,
//           "queries": [{"s", "u", "point"}, …]}
#include "curves/arc_length.hpp"
#include "curves/curves_json.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<ArcLength> {
    static ArcLength::Input input(const json& j) {
        Reader r(j);
        r.only({"control_points", "samples", "distances", "fractions"});
        ArcLength::Input in;
        in.control_points = curves::read_points(r, "control_points", in.dim);
        if (r.has("samples")) {
            const long long n = r.integer("samples");
            if (n < 1 || n > ArcLength::kMaxSamples)
                throw InputError("samples",
                                 "must be between 1 and 10000 (got " + std::to_string(n) + ")");
            in.samples = static_cast<int>(n);
        }
        if (r.has("distances")) in.distances = curves::read_numbers(r, "distances");
        if (r.has("fractions")) in.fractions = curves::read_numbers(r, "fractions");
        if (r.has("distances") && r.has("fractions"))
            throw InputError("fractions", "give distances or fractions, not both");
        return in;
    }

    static json input_json(const ArcLength::Input& in) {
        json j{{"control_points", curves::nice_points(in.control_points, in.dim)},
               {"samples", in.samples}};
        auto list = [](const std::vector<double>& v) {
            json out = json::array();
            for (double x : v) out.push_back(nice_number(x));
            return out;
        };
        if (!in.distances.empty()) j["distances"] = list(in.distances);
        if (!in.fractions.empty()) j["fractions"] = list(in.fractions);
        return j;
    }

    static json result(const ArcLength::Result& r) {
        json table = json::array(), queries = json::array();
        for (std::size_t j = 0; j < r.u.size(); ++j) table.push_back(json::array({r.u[j], r.s[j]}));
        for (const auto& q : r.queries)
            queries.push_back(
                json{{"s", q.s}, {"u", q.u}, {"point", curves::point_json(q.point, r.dim)}});
        return json{{"table", std::move(table)},
                    {"length", r.length},
                    {"length_exact", r.length_exact},
                    {"length_error", r.length_error},
                    {"queries", std::move(queries)}};
    }

    static json example() {
        // The course's motion-path problem: equal steps of u bunch up where the curve is slow.
        return json{{"control_points", {{0, 0}, {1, 4}, {2, 4}, {8, 0}}},
                    {"samples", 10},
                    {"fractions", {0.25, 0.5, 0.75}}};
    }
};

Algorithm arc_length_algorithm() {
    return make_algorithm<ArcLength>(NoPlain{
        "the stepped table is the only implementation; the tests hold it to the closed-form "
        "length of quadratics and to exactly parameterised lines"});
}

}  // namespace cg
