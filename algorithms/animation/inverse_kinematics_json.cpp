// Inverse kinematics, JSON:
//   input  {"lengths": [l_1, …] (1 to 32 links, each > 0),
//           "angles": [θ_1, …] degrees, the start pose (default all 0),
//           "axes": [[x, y, z], …] each joint's hinge axis in the frame of the link before it
//                   (default [0, 0, 1] for all: a planar arm),
//           "base": [x, y] or [x, y, z] (default the origin), "target": [x, y] or [x, y, z]
//           (z = 0 when left out; needed by every method but forward),
//           "method": "forward" | "analytic" | "ccd" (default) | "jacobian-transpose" | "dls",
//           "elbow": "up" (default) | "down" (analytic: the pose taken),
//           "damping": λ (dls, default 0.2), "iterations": at most this many (CCD: sweeps;
//           1 to 10000, default 100), "tolerance": |e| that counts as reached (default 1e-9)}
//   result {"method", "angles" (degrees), "positions": p_0..p_n, "end", "error", "reached",
//           "reachable", "planar", "iterations", "updates", "errors": |e| before the first and
//           after every update, "stop": "reached" | "stalled" | "iterations" | "forward" |
//           "analytic"; analytic also "elbow_up", "elbow_down": [θ_1, θ_2], "d", "cos_theta2";
//           CCD also "first_update": {"joint" (1-based), "delta" (degrees)}}
#include "animation/inverse_kinematics.hpp"
#include "io/registry.hpp"

namespace cg {

namespace inverse_kinematics_json {

glm::dvec3 point(const json& v, const std::string& field) {
    if (!v.is_array() || (v.size() != 2 && v.size() != 3))
        throw InputError(field, "must be a point [x, y] or [x, y, z], got " + describe(v));
    return {as_number(v[0], field + "[0]"), as_number(v[1], field + "[1]"),
            v.size() == 3 ? as_number(v[2], field + "[2]") : 0.0};
}

std::vector<double> numbers(const Reader& r, const char* key) {
    const json& v = r.get(key);
    const std::string f = r.field(key);
    if (!v.is_array()) throw InputError(f, "must be a list of numbers, got " + describe(v));
    if (v.size() > std::size_t(InverseKinematics::kMaxLinks))
        throw InputError(f, "has " + std::to_string(v.size()) + " entries; at most " +
                                std::to_string(InverseKinematics::kMaxLinks) + " links");
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(as_number(v[i], element(f, i)));
    return out;
}

}  // namespace inverse_kinematics_json

template <>
struct JsonIo<InverseKinematics> {
    using IK = InverseKinematics;
    using Method = IK::Method;
    static IK::Input input(const json& j) {
        Reader r(j);
        r.only({"lengths", "angles", "axes", "base", "target", "method", "elbow", "damping",
                "iterations", "tolerance"});
        IK::Input in;
        in.lengths = inverse_kinematics_json::numbers(r, "lengths");
        if (r.has("angles")) in.angles = inverse_kinematics_json::numbers(r, "angles");
        if (r.has("axes")) {
            const json& v = r.get("axes");
            const std::string f = r.field("axes");
            if (!v.is_array()) throw InputError(f, "must be a list of axes, got " + describe(v));
            if (v.size() > std::size_t(IK::kMaxLinks))
                throw InputError(f, "has " + std::to_string(v.size()) + " axes; at most " +
                                        std::to_string(IK::kMaxLinks) + " links");
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (!v[i].is_array() || v[i].size() != 3)
                    throw InputError(element(f, i),
                                     "must be an axis [x, y, z], got " + describe(v[i]));
                in.axes.push_back(inverse_kinematics_json::point(v[i], element(f, i)));
            }
        }
        if (r.has("base")) in.base = inverse_kinematics_json::point(r.get("base"), r.field("base"));
        if (r.has("target")) {
            in.target = inverse_kinematics_json::point(r.get("target"), r.field("target"));
            in.has_target = true;
        }
        if (r.has("method")) {
            const std::string m = r.string("method");
            if (m == "forward")
                in.method = Method::Forward;
            else if (m == "analytic")
                in.method = Method::Analytic;
            else if (m == "ccd")
                in.method = Method::CCD;
            else if (m == "jacobian-transpose")
                in.method = Method::JacobianTranspose;
            else if (m == "dls")
                in.method = Method::DLS;
            else
                throw InputError(r.field("method"),
                                 "must be \"forward\", \"analytic\", \"ccd\", "
                                 "\"jacobian-transpose\" or \"dls\", got \"" +
                                     m + "\"");
        }
        if (r.has("elbow")) {
            const std::string e = r.string("elbow");
            if (e != "up" && e != "down")
                throw InputError(r.field("elbow"), "must be \"up\" or \"down\", got \"" + e + "\"");
            in.elbow_up = e == "up";
        }
        if (r.has("damping")) in.damping = r.number("damping");
        if (r.has("iterations"))
            in.iterations = int(r.integer("iterations", 1, IK::kMaxIterations,
                                          "1 to " + std::to_string(IK::kMaxIterations)));
        if (r.has("tolerance")) in.tolerance = r.number("tolerance");
        return in;
    }

    static json input_json(const IK::Input& in) {
        json j;
        json ls = json::array(), as = json::array();
        for (double l : in.lengths) ls.push_back(nice_number(l));
        j["lengths"] = ls;
        if (!in.angles.empty()) {
            for (double a : in.angles) as.push_back(nice_number(a));
            j["angles"] = as;
        }
        if (!in.axes.empty()) {
            json ax = json::array();
            for (const auto& a : in.axes) ax.push_back(nice_point(a));
            j["axes"] = ax;
        }
        if (in.base != glm::dvec3(0)) j["base"] = nice_point(in.base);
        if (in.has_target)
            j["target"] =
                in.target.z == 0 ? nice_point(glm::dvec2(in.target)) : nice_point(in.target);
        j["method"] = IK::method_name(in.method);
        if (in.method == Method::Analytic) j["elbow"] = in.elbow_up ? "up" : "down";
        if (in.method == Method::DLS) j["damping"] = nice_number(in.damping);
        if (in.method != Method::Forward && in.method != Method::Analytic)
            j["iterations"] = in.iterations;
        if (in.tolerance != 1e-9) j["tolerance"] = nice_number(in.tolerance);
        return j;
    }

    static json result(const IK::Result& r) {
        json j;
        j["method"] = IK::method_name(r.method);
        j["angles"] = r.angles;
        json p = json::array();
        for (const auto& x : r.positions)
            p.push_back(r.planar ? to_json(glm::dvec2(x)) : to_json(x));
        j["positions"] = p;
        j["end"] = r.planar ? to_json(glm::dvec2(r.end)) : to_json(r.end);
        j["error"] = r.error;
        j["reached"] = r.reached;
        j["reachable"] = r.reachable;
        j["planar"] = r.planar;
        j["iterations"] = r.iterations;
        j["updates"] = r.updates;
        j["errors"] = r.errors;
        j["stop"] = r.stop;
        if (r.method == Method::Analytic) {
            j["elbow_up"] = {r.two_link.up[0], r.two_link.up[1]};
            j["elbow_down"] = {r.two_link.down[0], r.two_link.down[1]};
            j["d"] = r.two_link.d;
            j["cos_theta2"] = r.two_link.cos_theta2;
        }
        if (r.method == Method::CCD && r.first_joint >= 0)
            j["first_update"] = {{"joint", r.first_joint + 1}, {"delta", r.first_delta}};
        return j;
    }

    static json example() {
        // A three-link planar arm reaching up and to the left by CCD.
        return parse_json(R"({"lengths": [2, 1.5, 1], "angles": [0, 0, 0],
                              "target": [1.5, 2.5], "method": "ccd", "iterations": 50})");
    }
};

Algorithm inverse_kinematics_algorithm() {
    return make_algorithm<InverseKinematics>(
        [](const InverseKinematics::Input& in) { return InverseKinematics::compute(in); });
}

}  // namespace cg
