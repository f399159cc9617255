// Quaternion algebra, JSON. One operation per input, named by "op"; each takes only its own
// fields (any other is refused, naming it):
//   {"op": "multiply", "q1": [w, x, y, z], "q2": [w, x, y, z]}        any quaternions
//   {"op": "conjugate", "q": [w, x, y, z]}                            any quaternion
//   {"op": "inverse", "q": [w, x, y, z]}                              q ≠ 0
//   {"op": "rotate", "q": [w, x, y, z], "point": [x, y, z]}           q ≠ 0, normalised first
//   {"op": "from_axis_angle", "axis": [x, y, z], "angle_deg": θ}      axis ≠ 0, any length
//   {"op": "to_matrix", "q": [w, x, y, z]}                            q ≠ 0, normalised first
//   {"op": "from_matrix", "matrix": [[r11, r12, r13], [r21, …], […]]}  a rotation (rows), ±1e-3
// Result: every field always present, null where the op does not produce it:
//   {"op", "q": the op's quaternion (q1 q2; q̄; q⁻¹; q/|q| for rotate and to_matrix; the one
//    built), "q2q1", "commute" (multiply), "norm": |q| of the input (multiply: |q1 q2|),
//    "point": P′ (rotate), "matrix": 3×3 rows (to_matrix), "angle_deg", "axis": the turn of the
//    unit quaternion (rotate, from_axis_angle, to_matrix, from_matrix; axis null for no turn)}
#include "io/registry.hpp"
#include "transforms/quaternion.hpp"
#include "transforms/rotation_common.hpp"

namespace cg {

namespace {

using Op = Quaternion::Op;

glm::dmat3 matrix3(const Reader& r, const char* key) {
    const json& v = r.get(key);
    const std::string field = r.field(key);
    if (!v.is_array() || v.size() != 3)
        throw InputError(field,
                         "must be a 3×3 matrix as three rows [[r11, r12, r13], [r21, r22, "
                         "r23], [r31, r32, r33]], got " +
                             describe(v));
    glm::dmat3 m;
    for (int row = 0; row < 3; ++row) {
        const glm::dvec3 p = as_point3(v[row], field + "[" + std::to_string(row) + "]");
        for (int c = 0; c < 3; ++c) m[c][row] = p[c];
    }
    return m;
}


template <class T, class F>
json or_null(const std::optional<T>& v, F&& f) {
    return v ? f(*v) : json(nullptr);
}

}  // namespace

template <>
struct JsonIo<Quaternion> {
    static Quaternion::Input input(const json& j) {
        Reader r(j);
        Quaternion::Input in;
        const std::string op = r.string("op");
        if (op == "multiply") {
            r.only({"op", "q1", "q2"});
            in.op = Op::Multiply;
            in.q1 = r.quat("q1");
            in.q2 = r.quat("q2");
        } else if (op == "conjugate" || op == "inverse" || op == "to_matrix") {
            r.only({"op", "q"});
            in.op = op == "conjugate" ? Op::Conjugate
                    : op == "inverse" ? Op::Inverse
                                      : Op::ToMatrix;
            in.q = r.quat("q");
        } else if (op == "rotate") {
            r.only({"op", "q", "point"});
            in.op = Op::Rotate;
            in.q = r.quat("q");
            in.point = r.point3("point");
        } else if (op == "from_axis_angle") {
            r.only({"op", "axis", "angle_deg"});
            in.op = Op::FromAxisAngle;
            in.axis = r.point3("axis");
            in.angle_deg = r.number("angle_deg");
        } else if (op == "from_matrix") {
            r.only({"op", "matrix"});
            in.op = Op::FromMatrix;
            in.matrix = matrix3(r, "matrix");
        } else {
            throw InputError(r.field("op"),
                             "must be one of multiply, conjugate, inverse, rotate, "
                             "from_axis_angle, to_matrix, from_matrix (got \"" +
                                 op + "\")");
        }
        return in;
    }

    static json input_json(const Quaternion::Input& in) {
        json j{{"op", Quaternion::op_name(in.op)}};
        switch (in.op) {
            case Op::Multiply:
                j["q1"] = nice_quat(in.q1);
                j["q2"] = nice_quat(in.q2);
                break;
            case Op::Conjugate:
            case Op::Inverse:
            case Op::ToMatrix:
                j["q"] = nice_quat(in.q);
                break;
            case Op::Rotate:
                j["q"] = nice_quat(in.q);
                j["point"] = nice_point(in.point);
                break;
            case Op::FromAxisAngle:
                j["axis"] = nice_point(in.axis);
                j["angle_deg"] = nice_number(in.angle_deg);
                break;
            case Op::FromMatrix:
                j["matrix"] = matrix_rows(in.matrix, true);
                break;
        }
        return j;
    }

    static json result(const Quaternion::Result& r) {
        return json{
            {"op", Quaternion::op_name(r.op)},
            {"q", quat_json(r.q)},
            {"q2q1", or_null(r.q2q1, quat_json)},
            {"commute", or_null(r.commute, [](bool b) { return json(b); })},
            {"norm", or_null(r.norm, [](double d) { return json(d); })},
            {"point", or_null(r.point, [](glm::dvec3 p) { return to_json(p); })},
            {"matrix",
             or_null(r.matrix, [](const glm::dmat3& m) { return to_json(Value(rot::rows3(m))); })},
            {"angle_deg", or_null(r.angle_deg, [](double d) { return json(d); })},
            {"axis", or_null(r.axis, [](glm::dvec3 p) { return to_json(p); })},
        };
    }

    static json example() {
        // Quarter turns about x and about y (not normalised): q1 q2 = [1, 1, 1, 1], q2 q1 =
        // [1, 1, 1, -1] — they differ in the sign of v1 × v2.
        return json{{"op", "multiply"}, {"q1", {1, 1, 0, 0}}, {"q2", {1, 0, 1, 0}}};
    }
};

Algorithm quaternion_algorithm() {
    return make_algorithm<Quaternion>(
        [](const Quaternion::Input& in) { return Quaternion::compute(in); });
}

}  // namespace cg
