// Orientation interpolation, JSON:
//   input  {"keys": [2 to 32 keys, each one of
//                    {"euler": [θ1, θ2, θ3]} (degrees, in "order"),
//                    {"axis": [x, y, z], "angle": θ} (degrees, right-handed about the axis),
//                    {"quaternion": [w, x, y, z]} (any length ≠ 0)],
//           "order": "xyz" (default) | "xzy" | "yxz" | "yzx" | "zxy" | "zyx",
//           "frames": frames per segment (default 8, 1 to 240; 4000 frames in all at most),
//           "segment_time": seconds from one key to the next (default 1)}
//   result {"keys": the unit quaternions after the sign choice, "key_euler": their Euler
//           angles in the order, "omega_deg", "flipped": per segment,
//           "dt", "t": per frame, and per frame by each method: "euler" (angles), "euler_q",
//           "matrix" (rows), "matrix_det", "matrix_orthogonality" (max |MᵀM − I|), "slerp",
//           "squad" ([w, x, y, z]), "speed_euler", "speed_slerp", "speed_squad" (°/s from the
//           frame before, 0 at frame 0); "min_det", "max_orthogonality_error",
//           "speed_range": {"euler", "slerp", "squad"}: [slowest, fastest] over frames 1 on}
#include "animation/orientation_interpolation.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<OrientationInterpolation> {
    using OI = OrientationInterpolation;

    static OI::Key key(const Reader& k) {
        k.only({"euler", "axis", "angle", "quaternion"});
        const int forms = int(k.has("euler")) + int(k.has("axis") || k.has("angle")) +
                          int(k.has("quaternion"));
        if (forms != 1)
            throw InputError(k.path(),
                             forms == 0 ? "must give \"euler\", \"axis\" and \"angle\", or "
                                          "\"quaternion\""
                                        : "must give one form only: \"euler\", \"axis\" and "
                                          "\"angle\", or \"quaternion\"");
        OI::Key out;
        if (k.has("euler")) {
            out.form = OI::Form::Euler;
            out.euler_deg = k.point3("euler");
        } else if (k.has("quaternion")) {
            out.form = OI::Form::Quaternion;
            out.q = k.quat("quaternion");
        } else {
            out.form = OI::Form::AxisAngle;
            if (!k.has("axis")) throw InputError(k.field("axis"), "is missing (with \"angle\")");
            if (!k.has("angle")) throw InputError(k.field("angle"), "is missing (with \"axis\")");
            out.axis = k.point3("axis");
            out.angle_deg = k.number("angle");
        }
        return out;
    }

    static OI::Input input(const json& j) {
        Reader r(j);
        r.only({"keys", "order", "frames", "segment_time"});
        OI::Input in;
        const json& ks = r.get("keys");
        const std::string kf = r.field("keys");
        if (!ks.is_array()) throw InputError(kf, "must be a list of key orientations, got " + describe(ks));
        if (ks.size() > std::size_t(OI::kMaxKeys))
            throw InputError(kf, "has " + std::to_string(ks.size()) + " keys; at most " +
                                     std::to_string(OI::kMaxKeys));
        for (std::size_t i = 0; i < ks.size(); ++i) in.keys.push_back(key(Reader(ks[i], element(kf, i))));
        if (r.has("order")) in.order = r.string("order");
        if (r.has("frames"))
            in.frames = int(r.integer("frames", 1, OI::kMaxFrames,
                                      "1 to " + std::to_string(OI::kMaxFrames)));
        if (r.has("segment_time")) in.segment_time = r.number("segment_time");
        return in;
    }

    static json input_json(const OI::Input& in) {
        json keys = json::array();
        for (const OI::Key& k : in.keys) {
            switch (k.form) {
                case OI::Form::Euler:
                    keys.push_back({{"euler", nice_point(k.euler_deg)}});
                    break;
                case OI::Form::AxisAngle:
                    keys.push_back(
                        {{"axis", nice_point(k.axis)}, {"angle", nice_number(k.angle_deg)}});
                    break;
                case OI::Form::Quaternion:
                    keys.push_back({{"quaternion", nice_quat(k.q)}});
                    break;
            }
        }
        return {{"keys", keys},
                {"order", in.order},
                {"frames", in.frames},
                {"segment_time", nice_number(in.segment_time)}};
    }

    static json result(const OI::Result& r) {
        json j;
        json keys = json::array(), euler = json::array();
        for (const auto& q : r.keys.q) keys.push_back(quat_json(q));
        for (const auto& e : r.keys.e) euler.push_back(to_json(e));
        j["keys"] = keys;
        j["key_euler"] = euler;
        j["omega_deg"] = r.keys.omega_deg;
        json flipped = json::array();
        for (char f : r.keys.flipped) flipped.push_back(f != 0);
        j["flipped"] = flipped;
        j["dt"] = r.dt;
        json t = json::array(), e = json::array(), eq = json::array(), m = json::array(),
             det = json::array(), orth = json::array(), sl = json::array(), sq = json::array(),
             ve = json::array(), vs = json::array(), vq = json::array();
        for (const auto& f : r.frames) {
            t.push_back(f.t);
            e.push_back(to_json(f.euler_deg));
            eq.push_back(quat_json(f.euler_q));
            m.push_back(matrix_rows(f.matrix));
            det.push_back(f.det);
            orth.push_back(f.orth_error);
            sl.push_back(quat_json(f.slerp));
            sq.push_back(quat_json(f.squad));
            ve.push_back(f.speed_euler);
            vs.push_back(f.speed_slerp);
            vq.push_back(f.speed_squad);
        }
        j["t"] = t;
        j["euler"] = e;
        j["euler_q"] = eq;
        j["matrix"] = m;
        j["matrix_det"] = det;
        j["matrix_orthogonality"] = orth;
        j["slerp"] = sl;
        j["squad"] = sq;
        j["speed_euler"] = ve;
        j["speed_slerp"] = vs;
        j["speed_squad"] = vq;
        j["min_det"] = r.min_det;
        j["max_orthogonality_error"] = r.max_orth_error;
        j["speed_range"] = {{"euler", {r.speed_min[0], r.speed_max[0]}},
                            {"slerp", {r.speed_min[1], r.speed_max[1]}},
                            {"squad", {r.speed_min[2], r.speed_max[2]}}};
        return j;
    }

    static json example() {
        // The identity to a quarter turn about z, given as quaternions: slerp at u = 1/4, 1/2, 3/4.
        return parse_json(R"({
            "keys": [{"quaternion": [1, 0, 0, 0]},
                     {"quaternion": [0.7071067811865476, 0, 0, 0.7071067811865476]}],
            "order": "xyz", "frames": 4, "segment_time": 1})");
    }
};

Algorithm orientation_interpolation_algorithm() {
    return make_algorithm<OrientationInterpolation>(
        [](const OrientationInterpolation::Input& in) { return OrientationInterpolation::compute(in); });
}

}  // namespace cg
