// Keyframes, JSON:
//   input  {"keys": [{"t": seconds, "value": v | [x, y] | [x, y, z] (every key the same kind),
//                     "tension", "continuity", "bias": (Kochanek–Bartels, in [−1, 1])}],
//           "interpolation": "linear" | "catmull-rom" (default) | "kochanek-bartels",
//           "tension", "continuity", "bias": defaults for every key (0),
//           "dt": seconds per frame (1/30), "constant_speed": false (a path: also move along it
//           at constant speed by the arc-length table), "samples": N of the table (64),
//           "query": a time at which to report every interpolation's value (the exam's)}
//   result {"dim", "times", "values", "velocities": every frame, "tangents_in", "tangents_out"
//           (m⁻, m⁺ at every key), "jumps" (p'(t_i⁺) − p'(t_i⁻)), "max_jump", "c1",
//           "c1_at_keys": {"linear", "catmull_rom", "kochanek_bartels"}, "speed_min",
//           "speed_max"; with constant_speed "length", "length_exact", "even" (the point at
//           constant speed every frame); with a query "at": {"linear", "catmull_rom",
//           "kochanek_bartels", and each "_velocity"}}
//   Values are numbers for a scalar channel, points for a path.
#include "animation/keyframes.hpp"
#include "io/registry.hpp"

namespace cg {

namespace keyframes_json {

json value(glm::dvec3 v, int dim) {
    if (dim == 1) return v.x;
    if (dim == 2) return to_json(glm::dvec2(v));
    return to_json(v);
}

json values(const std::vector<glm::dvec3>& v, int dim) {
    json a = json::array();
    for (const auto& x : v) a.push_back(value(x, dim));
    return a;
}

double tcb(const Reader& r, const char* key, double fallback) {
    return r.has(key) ? r.number(key) : fallback;
}

}  // namespace keyframes_json

template <>
struct JsonIo<Keyframes> {
    using Interpolation = Keyframes::Interpolation;
    static Keyframes::Input input(const json& j) {
        Reader r(j);
        r.only({"keys", "interpolation", "tension", "continuity", "bias", "dt", "constant_speed",
                "samples", "query"});
        Keyframes::Input in;
        const double T = keyframes_json::tcb(r, "tension", 0);
        const double C = keyframes_json::tcb(r, "continuity", 0);
        const double B = keyframes_json::tcb(r, "bias", 0);
        const json& ks = r.get("keys");
        const std::string kf = r.field("keys");
        if (!ks.is_array()) throw InputError(kf, "must be a list of keys, got " + describe(ks));
        if (ks.size() > std::size_t(Keyframes::kMaxKeys))
            throw InputError(kf, "has " + std::to_string(ks.size()) + " keys; at most " +
                                     std::to_string(Keyframes::kMaxKeys));
        for (std::size_t i = 0; i < ks.size(); ++i) {
            const Reader k(ks[i], element(kf, i));
            k.only({"t", "value", "tension", "continuity", "bias"});
            Keyframes::Key key;
            key.t = k.number("t");
            const json& v = k.get("value");
            const std::string vf = k.field("value");
            int dim = 0;
            if (v.is_number()) {
                key.value.x = as_number(v, vf);
                dim = 1;
            } else if (v.is_array() && (v.size() == 2 || v.size() == 3)) {
                key.value = v.size() == 2 ? glm::dvec3(as_point2(v, vf), 0) : as_point3(v, vf);
                dim = int(v.size());
            } else {
                throw InputError(
                    vf, "must be a number or a point [x, y] or [x, y, z], got " + describe(v));
            }
            if (i == 0)
                in.dim = dim;
            else if (dim != in.dim)
                throw InputError(
                    vf, std::string("must be ") +
                            (in.dim == 1 ? "a number" : std::to_string(in.dim) + " numbers") +
                            " like keys[0].value: one kind of channel");
            key.tension = keyframes_json::tcb(k, "tension", T);
            key.continuity = keyframes_json::tcb(k, "continuity", C);
            key.bias = keyframes_json::tcb(k, "bias", B);
            in.keys.push_back(key);
        }
        if (r.has("interpolation")) {
            const std::string name = r.string("interpolation");
            if (name == "linear")
                in.interpolation = Interpolation::Linear;
            else if (name == "catmull-rom")
                in.interpolation = Interpolation::CatmullRom;
            else if (name == "kochanek-bartels")
                in.interpolation = Interpolation::KochanekBartels;
            else
                throw InputError(
                    r.field("interpolation"),
                    "must be \"linear\", \"catmull-rom\" or \"kochanek-bartels\", got \"" + name +
                        "\"");
        }
        if (r.has("dt")) in.dt = r.number("dt");
        if (r.has("constant_speed")) in.constant_speed = r.boolean("constant_speed");
        if (r.has("samples"))
            in.samples = int(r.integer("samples", 1, Keyframes::kMaxSamples,
                                       "1 to " + std::to_string(Keyframes::kMaxSamples)));
        if (r.has("query")) {
            in.has_query = true;
            in.query = r.number("query");
        }
        return in;
    }

    static json input_json(const Keyframes::Input& in) {
        json j;
        json ks = json::array();
        for (const auto& k : in.keys) {
            json o = {{"t", nice_number(k.t)}};
            o["value"] = in.dim == 1   ? nice_number(k.value.x)
                         : in.dim == 2 ? nice_point(glm::dvec2(k.value))
                                       : nice_point(k.value);
            if (k.tension != 0) o["tension"] = nice_number(k.tension);
            if (k.continuity != 0) o["continuity"] = nice_number(k.continuity);
            if (k.bias != 0) o["bias"] = nice_number(k.bias);
            ks.push_back(o);
        }
        j["keys"] = ks;
        j["interpolation"] = Keyframes::interpolation_name(in.interpolation);
        j["dt"] = nice_number(in.dt);
        if (in.constant_speed) j["constant_speed"] = true;
        if (in.samples != 64) j["samples"] = in.samples;
        if (in.has_query) j["query"] = nice_number(in.query);
        return j;
    }

    static json result(const Keyframes::Result& r) {
        using keyframes_json::value;
        using keyframes_json::values;
        json j;
        j["dim"] = r.dim;
        j["times"] = r.times;
        j["values"] = values(r.values, r.dim);
        j["velocities"] = values(r.velocities, r.dim);
        j["tangents_in"] = values(r.m_in, r.dim);
        j["tangents_out"] = values(r.m_out, r.dim);
        j["jumps"] = values(r.jumps, r.dim);
        j["max_jump"] = r.max_jump;
        j["c1"] = r.c1;
        j["c1_at_keys"] = {{"linear", r.c1_linear},
                           {"catmull_rom", r.c1_catmull_rom},
                           {"kochanek_bartels", r.c1_kochanek_bartels}};
        j["speed_min"] = r.speed_min;
        j["speed_max"] = r.speed_max;
        if (!r.even.empty()) {
            j["length"] = r.length;
            j["length_exact"] = r.length_exact;
            j["even"] = values(r.even, r.dim);
        }
        if (r.has_query) {
            const auto& a = r.at;
            j["at"] = {{"linear", value(a.linear, r.dim)},
                       {"catmull_rom", value(a.catmull_rom, r.dim)},
                       {"kochanek_bartels", value(a.kochanek_bartels, r.dim)},
                       {"linear_velocity", value(a.linear_velocity, r.dim)},
                       {"catmull_rom_velocity", value(a.catmull_rom_velocity, r.dim)},
                       {"kochanek_bartels_velocity", value(a.kochanek_bartels_velocity, r.dim)}};
        }
        return j;
    }

    static json example() {
        // The exam's kind of channel: four keys one second apart, Catmull–Rom.
        return parse_json(R"({
            "keys": [{"t": 0, "value": 0}, {"t": 1, "value": 2}, {"t": 2, "value": 6},
                     {"t": 3, "value": 4}],
            "interpolation": "catmull-rom", "dt": 0.25, "query": 1.5})");
    }
};

Algorithm keyframes_algorithm() {
    return make_algorithm<Keyframes>(
        [](const Keyframes::Input& in) { return Keyframes::compute(in); });
}

}  // namespace cg
