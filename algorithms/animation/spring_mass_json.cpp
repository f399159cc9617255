// Spring-mass, JSON:
//   input  {"masses": [{"position": [x, y] or [x, y, z] (z = 0 when left out),
//                       "mass": m (> 0, default 1), "pinned": false, "velocity": [..] (default
//                       0)}],
//           "springs": [{"i": a, "j": b, "stiffness": k, "rest_length": L (default: the initial
//                        distance), "damping": c (default 0)}],
//           or instead of both a generated cloth patch, pinned at its two far corners of row 0:
//           "cloth": {"rows": r, "cols": c (2 to 32), "spacing": h, "mass": per mass,
//                     "stiffness": k, "damping": c, "shear": true (diagonal springs too)}
//           (lying in the x-z plane at y = 0, row 0 along x at z = 0; mass (r, c) is r·cols + c),
//           "gravity": [0, -9.81, 0] (default), "drag": 0, "dt": 0.01, "steps": 200 (1 to 100000,
//           and steps × (masses + springs) ≤ 2·10⁷),
//           "integrator": "explicit-euler" | "symplectic-euler" (default) | "rk4",
//           "watch": the mass narrated and drawn in detail (default: the first free one)}
//   result {"dt", "steps": steps taken, "t", "positions", "velocities" (final, every mass),
//           "x", "v": the watched mass at the end, "energy": the total after 0, 1, …, steps steps,
//           "kinetic", "spring", "gravity", "total": the final energies, "energy_scale",
//           "max_drift": max |E_k − E_0| / E_scale, "blew_up", "blow_up_step" (−1: none)}
#include "animation/spring_mass.hpp"
#include "io/registry.hpp"

namespace cg {

namespace spring_mass_json {

glm::dvec3 point(const json& v, const std::string& field) {
    if (!v.is_array() || (v.size() != 2 && v.size() != 3))
        throw InputError(field, "must be a point [x, y] or [x, y, z], got " + describe(v));
    return {as_number(v[0], field + "[0]"), as_number(v[1], field + "[1]"),
            v.size() == 3 ? as_number(v[2], field + "[2]") : 0.0};
}

int index(const Reader& r, const char* key) {
    return int(r.integer(key, -1000000, 1000000, "a mass index"));
}

void cloth(const Reader& c, SpringMass::Input& in) {
    c.only({"rows", "cols", "spacing", "mass", "stiffness", "damping", "shear"});
    const int rows = int(c.integer("rows", 2, 32, "2 to 32 masses"));
    const int cols = int(c.integer("cols", 2, 32, "2 to 32 masses"));
    const double h = c.has("spacing") ? c.number("spacing") : 0.1;
    if (!(h > 0) || h > 1000)
        throw InputError(c.field("spacing"),
                         "must be > 0 and at most 1000 (got " + std::to_string(h) + ")");
    const double m = c.has("mass") ? c.number("mass") : 0.01;
    const double k = c.has("stiffness") ? c.number("stiffness") : 50;
    const double damping = c.has("damping") ? c.number("damping") : 0.02;
    const bool shear = c.has("shear") ? c.boolean("shear") : true;
    for (int r = 0; r < rows; ++r)
        for (int q = 0; q < cols; ++q) {
            SpringMass::Mass mass;
            mass.position = {q * h, 0, r * h};
            mass.mass = m;
            mass.pinned = r == 0 && (q == 0 || q == cols - 1);
            in.masses.push_back(mass);
        }
    auto spring = [&](int a, int b) {
        SpringMass::Spring s;
        s.i = a;
        s.j = b;
        s.stiffness = k;
        s.damping = damping;
        in.springs.push_back(s);
    };
    for (int r = 0; r < rows; ++r)
        for (int q = 0; q < cols; ++q) {
            const int id = r * cols + q;
            if (q + 1 < cols) spring(id, id + 1);  // structural
            if (r + 1 < rows) spring(id, id + cols);
            if (shear && q + 1 < cols && r + 1 < rows) {
                spring(id, id + cols + 1);
                spring(id + 1, id + cols);
            }
        }
}

}  // namespace spring_mass_json

template <>
struct JsonIo<SpringMass> {
    using Integrator = SpringMass::Integrator;
    static SpringMass::Input input(const json& j) {
        Reader r(j);
        r.only({"masses", "springs", "cloth", "gravity", "drag", "dt", "steps", "integrator",
                "watch"});
        SpringMass::Input in;
        if (r.has("cloth")) {
            if (r.has("masses") || r.has("springs"))
                throw InputError(r.field("cloth"),
                                 "give either a \"cloth\" or \"masses\" and \"springs\", not both");
            spring_mass_json::cloth(r.object("cloth"), in);
        } else {
            if (!r.has("masses"))
                throw InputError("masses",
                                 "is missing: give \"masses\" (a list of "
                                 "{\"position\", \"mass\"}) or a \"cloth\"");
            const json& ms = r.get("masses");
            const std::string mf = r.field("masses");
            if (!ms.is_array())
                throw InputError(mf, "must be a list of masses, got " + describe(ms));
            if (ms.size() > std::size_t(SpringMass::kMaxMasses))
                throw InputError(mf, "has " + std::to_string(ms.size()) + " masses; at most " +
                                         std::to_string(SpringMass::kMaxMasses) + " are simulated");
            for (std::size_t i = 0; i < ms.size(); ++i) {
                const Reader m(ms[i], element(mf, i));
                m.only({"position", "mass", "pinned", "velocity"});
                SpringMass::Mass mass;
                mass.position = spring_mass_json::point(m.get("position"), m.field("position"));
                if (m.has("velocity"))
                    mass.velocity = spring_mass_json::point(m.get("velocity"), m.field("velocity"));
                if (m.has("mass")) mass.mass = m.number("mass");
                if (m.has("pinned")) mass.pinned = m.boolean("pinned");
                in.masses.push_back(mass);
            }
            if (r.has("springs")) {
                const json& ss = r.get("springs");
                const std::string sf = r.field("springs");
                if (!ss.is_array())
                    throw InputError(sf, "must be a list of springs, got " + describe(ss));
                if (ss.size() > std::size_t(SpringMass::kMaxSprings))
                    throw InputError(sf, "has " + std::to_string(ss.size()) + " springs; at most " +
                                             std::to_string(SpringMass::kMaxSprings));
                for (std::size_t k = 0; k < ss.size(); ++k) {
                    const Reader s(ss[k], element(sf, k));
                    s.only({"i", "j", "stiffness", "rest_length", "damping"});
                    SpringMass::Spring spring;
                    spring.i = spring_mass_json::index(s, "i");
                    spring.j = spring_mass_json::index(s, "j");
                    spring.stiffness = s.number("stiffness");
                    if (s.has("rest_length")) {
                        spring.rest = s.number("rest_length");
                        spring.has_rest = true;
                    }
                    if (s.has("damping")) spring.damping = s.number("damping");
                    in.springs.push_back(spring);
                }
            }
        }
        if (r.has("gravity"))
            in.gravity = spring_mass_json::point(r.get("gravity"), r.field("gravity"));
        if (r.has("drag")) in.drag = r.number("drag");
        if (r.has("dt")) in.dt = r.number("dt");
        if (r.has("steps"))
            in.steps = int(r.integer("steps", 1, SpringMass::kMaxSteps,
                                     "1 to " + std::to_string(SpringMass::kMaxSteps)));
        if (r.has("integrator")) {
            const std::string name = r.string("integrator");
            if (name == "explicit-euler")
                in.integrator = Integrator::ExplicitEuler;
            else if (name == "symplectic-euler")
                in.integrator = Integrator::SymplecticEuler;
            else if (name == "rk4")
                in.integrator = Integrator::RK4;
            else
                throw InputError(r.field("integrator"),
                                 "must be \"explicit-euler\", \"symplectic-euler\" or \"rk4\", "
                                 "got \"" +
                                     name + "\"");
        }
        if (r.has("watch")) in.watch = spring_mass_json::index(r, "watch");
        return in;
    }

    static json input_json(const SpringMass::Input& in) {
        json j;
        json ms = json::array();
        for (const auto& m : in.masses) {
            json o = {{"position", nice_point(m.position)}, {"mass", nice_number(m.mass)}};
            if (m.pinned) o["pinned"] = true;
            if (m.velocity != glm::dvec3(0)) o["velocity"] = nice_point(m.velocity);
            ms.push_back(o);
        }
        j["masses"] = ms;
        json ss = json::array();
        for (const auto& s : in.springs) {
            json o = {{"i", s.i}, {"j", s.j}, {"stiffness", nice_number(s.stiffness)}};
            if (s.has_rest) o["rest_length"] = nice_number(s.rest);
            if (s.damping != 0) o["damping"] = nice_number(s.damping);
            ss.push_back(o);
        }
        j["springs"] = ss;
        j["gravity"] = nice_point(in.gravity);
        if (in.drag != 0) j["drag"] = nice_number(in.drag);
        j["dt"] = nice_number(in.dt);
        j["steps"] = in.steps;
        j["integrator"] = SpringMass::integrator_name(in.integrator);
        if (in.watch >= 0) j["watch"] = in.watch;
        return j;
    }

    static json result(const SpringMass::Result& r) {
        json j;
        j["dt"] = r.dt;
        j["steps"] = r.steps;
        j["t"] = r.t;
        json p = json::array(), v = json::array();
        for (const auto& x : r.positions) p.push_back(to_json(x));
        for (const auto& x : r.velocities) v.push_back(to_json(x));
        j["positions"] = p;
        j["velocities"] = v;
        j["x"] = to_json(r.x);
        j["v"] = to_json(r.v);
        j["energy"] = r.energy;
        j["kinetic"] = r.final_energy.kinetic;
        j["spring"] = r.final_energy.spring;
        j["gravity"] = r.final_energy.gravity;
        j["total"] = r.final_energy.total();
        j["energy_scale"] = r.energy_scale;
        j["max_drift"] = r.max_drift;
        j["blew_up"] = r.blew_up;
        j["blow_up_step"] = r.blow_up_step;
        return j;
    }

    static json example() {
        // One mass on a spring hanging from a pinned one, released from above its rest point.
        return parse_json(R"({
            "masses": [{"position": [0, 0], "pinned": true},
                       {"position": [0, -0.5], "mass": 1}],
            "springs": [{"i": 0, "j": 1, "stiffness": 40, "rest_length": 1}],
            "gravity": [0, -9.81], "dt": 0.02, "steps": 150, "integrator": "symplectic-euler"})");
    }
};

Algorithm spring_mass_algorithm() {
    return make_algorithm<SpringMass>(
        [](const SpringMass::Input& in) { return SpringMass::compute(in); });
}

}  // namespace cg
