// Affine combinations, JSON:
//   input  {"points": ["P", "Q", …], "vectors": ["v", …] (optional), "scalars": ["t", …]
//           (optional: when given, any other name is refused; when left out, every name that is
//           not a point or vector is a scalar), "expressions": ["(P + Q)/2", …]}
//   result {"results": [{"expression", "kind": "point" | "vector" | "scalar" | "invalid",
//           "coefficient_sum": number, formula (a string in the scalars) or null (no points or
//           vectors), "depends_on_scalars": the sum is 1 or 0 only for some values,
//           "coefficients": {name: number or formula}, "reason"}, …],
//           "kinds": [the kinds in order]}
#include "affine/affine_combination.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

std::vector<std::string> affine_names(const Reader& r, const char* key) {
    if (!r.has(key)) return {};
    const json& v = r.get(key);
    const std::string f = r.field(key);
    if (!v.is_array()) throw InputError(f, "must be a list of names, got " + describe(v));
    std::vector<std::string> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!v[i].is_string())
            throw InputError(element(f, i), "must be a string, got " + describe(v[i]));
        out.push_back(v[i].get<std::string>());
    }
    return out;
}

}  // namespace

template <>
struct JsonIo<AffineCombination> {
    static AffineCombination::Input input(const json& j) {
        Reader r(j);
        r.only({"points", "vectors", "scalars", "expressions"});
        AffineCombination::Input in;
        if (!r.has("points"))
            throw InputError("points", "missing (the names of the points, possibly [])");
        in.points = affine_names(r, "points");
        in.vectors = affine_names(r, "vectors");
        in.scalars_declared = r.has("scalars");
        in.scalars = affine_names(r, "scalars");
        r.get("expressions");  // required
        in.expressions = affine_names(r, "expressions");
        return in;
    }

    static json input_json(const AffineCombination::Input& in) {
        json j{{"points", in.points}};
        if (!in.vectors.empty()) j["vectors"] = in.vectors;
        if (in.scalars_declared) j["scalars"] = in.scalars;
        j["expressions"] = in.expressions;
        return j;
    }

    static json result(const AffineCombination::Result& r) {
        json rows = json::array(), kinds = json::array();
        for (const auto& row : r.rows) {
            json sum = nullptr;
            if (row.has_sum) sum = row.sum_constant ? json(row.sum) : json(row.sum_formula);
            json coefficients = json::object();
            for (const auto& t : row.coefficients)
                coefficients[t.name] = t.constant ? json(t.value) : json(t.formula);
            rows.push_back({{"expression", row.expression},
                            {"kind", affine::kind_name(row.kind)},
                            {"coefficient_sum", sum},
                            {"depends_on_scalars", row.depends},
                            {"coefficients", coefficients},
                            {"reason", row.reason}});
            kinds.push_back(affine::kind_name(row.kind));
        }
        return json{{"results", rows}, {"kinds", kinds}};
    }

    static json example() {
        return json{{"points", {"P", "Q", "R"}},
                    {"vectors", {"v"}},
                    {"expressions",
                     {"(P + Q + R)/3", "3P − 2Q", "P − Q + 2v", "P + Q", "(1 − t)P + t Q",
                      "sum_{i=0}^{3} B(3,i,t) P_i", "P · Q", "(P − Q) × v"}}};
    }
};

Algorithm affine_combination_algorithm() {
    return make_algorithm<AffineCombination>(
        [](const AffineCombination::Input& in) { return AffineCombination::classify(in); });
}

}  // namespace cg
