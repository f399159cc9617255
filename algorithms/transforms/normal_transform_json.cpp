// Transforming normals, JSON:
//   input  {"matrix": 3×3 rows, or 4×4 rows of an affine map (its upper 3×3 is used),
//           "normal": [x, y, z], "tangents": [[x, y, z], [x, y, z]] (optional, ⊥ normal)}
//   result {"det", "tangents", "transformed_tangents", "naive_normal" (L n), "naive_cos",
//           "naive_ok", "inverse_transpose": 3×3 rows, "normal" (N n), "unit_normal", "cos"}
#include "io/registry.hpp"
#include "transforms/normal_transform.hpp"

namespace cg {

namespace {

glm::dmat3 read_linear(const json& v) {
    if (!v.is_array() || (v.size() != 3 && v.size() != 4))
        throw InputError("matrix", "must be a 3×3 matrix (3 rows) or an affine 4×4 (4 rows), got " +
                                       describe(v));
    const std::size_t n = v.size();
    glm::dmat3 m(1.0);
    for (std::size_t r = 0; r < n; ++r) {
        const std::string f = "matrix[" + std::to_string(r) + "]";
        if (!v[r].is_array() || v[r].size() != n)
            throw InputError(f, "must be a row of " + std::to_string(n) + " numbers, got " + describe(v[r]));
        for (std::size_t c = 0; c < n; ++c) {
            const double x = as_number(v[r][c], f + "[" + std::to_string(c) + "]");
            if (r < 3 && c < 3) m[static_cast<int>(c)][static_cast<int>(r)] = x;
            if (r == 3 && x != (c == 3 ? 1.0 : 0.0))
                throw InputError("matrix[3]", "must be [0, 0, 0, 1]: the 4×4 matrix must be affine");
        }
    }
    return m;
}

}  // namespace

template <>
struct JsonIo<NormalTransform> {
    static NormalTransform::Input input(const json& j) {
        Reader r(j);
        r.only({"matrix", "normal", "tangents"});
        NormalTransform::Input in;
        in.linear = read_linear(r.get("matrix"));
        in.normal = r.point3("normal");
        if (r.has("tangents")) {
            const auto t = r.points3("tangents");
            if (t.size() != 2)
                throw InputError("tangents", "must be two vectors [[x, y, z], [x, y, z]], got " +
                                                 std::to_string(t.size()));
            in.has_tangents = true;
            in.tangents = {t[0], t[1]};
        }
        return in;
    }

    static json input_json(const NormalTransform::Input& in) {
        json m = json::array();
        for (int r = 0; r < 3; ++r)
            m.push_back({nice_number(in.linear[0][r]), nice_number(in.linear[1][r]), nice_number(in.linear[2][r])});
        json j{{"matrix", std::move(m)}, {"normal", nice_point(in.normal)}};
        if (in.has_tangents) j["tangents"] = {nice_point(in.tangents[0]), nice_point(in.tangents[1])};
        return j;
    }

    static json result(const NormalTransform::Result& r) {
        return json{{"det", r.det},
                    {"tangents", {to_json(r.tangents[0]), to_json(r.tangents[1])}},
                    {"transformed_tangents", {to_json(r.images[0]), to_json(r.images[1])}},
                    {"naive_normal", to_json(r.naive)},
                    {"naive_cos", {r.naive_cos[0], r.naive_cos[1]}},
                    {"naive_ok", r.naive_ok},
                    {"inverse_transpose", matrix_rows(r.inverse_transpose)},
                    {"normal", to_json(r.normal)},
                    {"unit_normal", to_json(r.unit_normal)},
                    {"cos", {r.cos[0], r.cos[1]}}};
    }

    static json example() {
        // Squash y by 2: the 45° normal (1, 1, 0) must tilt towards y, not away from it.
        return json::parse(R"({"matrix": [[1, 0, 0], [0, 0.5, 0], [0, 0, 1]], "normal": [1, 1, 0]})");
    }
};

Algorithm normal_transform_algorithm() {
    return make_algorithm<NormalTransform>(
        [](const NormalTransform::Input& in) { return NormalTransform::transform(in); });
}

}  // namespace cg
