// Slerp, JSON:
//   input  {"q0": [w, x, y, z], "q1": [w, x, y, z] (any length ≠ 0, normalised on input),
//           "u": u in [0, 1] (outside is refused: no extrapolation),
//           "method": "slerp" (default) | "matrix-lerp" | "euler-lerp" (the orientation at u)}
//   result {"q": [w, x, y, z] (unit: slerp's), "omega_deg": ω (after the flip, [0, 90]),
//           "matrix": 3×3 rows (q's, or the method's blend), "flipped": q1 was negated,
//           "fallback": normalised lerp used}
#include <algorithm>
#include <iterator>

#include "io/registry.hpp"
#include "transforms/slerp.hpp"

namespace cg {

namespace {

constexpr const char* kMethods[] = {"slerp", "matrix-lerp", "euler-lerp"};

}  // namespace

template <>
struct JsonIo<Slerp> {
    static Slerp::Input input(const json& j) {
        Reader r(j);
        r.only({"q0", "q1", "u", "method"});
        Slerp::Input in;
        in.q0 = r.quat("q0");
        in.q1 = r.quat("q1");
        in.u = r.number("u");
        if (r.has("method")) {
            const std::string m = r.string("method");
            const auto* at = std::find(std::begin(kMethods), std::end(kMethods), m);
            if (at == std::end(kMethods))
                throw InputError(r.field("method"), "must be \"slerp\", \"matrix-lerp\" or \"euler-lerp\", got \"" + m + "\"");
            in.method = static_cast<Slerp::Method>(at - std::begin(kMethods));
        }
        return in;
    }

    static json input_json(const Slerp::Input& in) {
        json j{{"q0", nice_quat(in.q0)}, {"q1", nice_quat(in.q1)}, {"u", in.u}};
        if (in.method != Slerp::Method::Slerp) j["method"] = kMethods[static_cast<int>(in.method)];
        return j;
    }

    static json result(const Slerp::Result& r) {
        return json{{"q", quat_json(r.q)},
                    {"omega_deg", r.omega_deg},
                    {"matrix", to_json(Value(rot::rows3(r.matrix)))},
                    {"flipped", r.flipped},
                    {"fallback", r.fallback}};
    }

    static json example() {
        // A quarter turn about z to a quarter turn about x (unnormalised), a third of the way.
        return json{{"q0", {1, 0, 0, 1}}, {"q1", {1, 1, 0, 0}}, {"u", 1.0 / 3}};
    }
};

Algorithm slerp_algorithm() {
    return make_algorithm<Slerp>([](const Slerp::Input& in) { return Slerp::interpolate(in); });
}

}  // namespace cg
