// Particle systems, JSON:
//   input  {"emitter": {"shape": "point" (default) | "disc" | "line",
//                       "position": [x, y] or [x, y, z] (the point, the disc's centre, the
//                       line's start), "end": the line's end, "radius": the disc's (0.5),
//                       "velocity": v̄, the mean initial velocity (its length the speed),
//                       "spread": the cone's half-angle in degrees (15), "jitter": speed share
//                       (0), "lifetime": L or [min, max] seconds (2), "rate": per second (20)}
//                       (no "emitter": none, rate 0),
//           "start": [{"position", "velocity", "lifetime" (default: the whole run)}]: particles
//                    alive at t = 0, numbered 0.. before the emitted ones,
//           "plane": {"point": [0, 0, 0], "normal": [0, 1, 0], "restitution": e (0.5),
//                     "friction": μ (0)} (no "plane": no collisions),
//           "gravity": [0, -9.81, 0], "drag": c (0), "dt": 1/30, "frames": 90 (1 to 100000),
//           "seed": 1 (an integer ≥ 0), "focus": the particle narrated (0)}
//   result {"dt", "frames", "t", "emitted": N(t), "killed", "alive", "bounces",
//           "alive_per_frame", "emitted_per_frame", "killed_per_frame",
//           "ids", "positions", "velocities", "ages": the particles alive at the end,
//           "focus", "focus_born", "focus_alive", "x", "v": the focus particle's last state}
#include <cmath>

#include "animation/particles.hpp"
#include "io/registry.hpp"

namespace cg {

namespace particles_json {

glm::dvec3 point(const json& v, const std::string& field) {
    if (!v.is_array() || (v.size() != 2 && v.size() != 3))
        throw InputError(field, "must be a point [x, y] or [x, y, z], got " + describe(v));
    return {as_number(v[0], field + "[0]"), as_number(v[1], field + "[1]"),
            v.size() == 3 ? as_number(v[2], field + "[2]") : 0.0};
}

void emitter(const Reader& r, Particles::Emitter& e) {
    r.only(
        {"shape", "position", "end", "radius", "velocity", "spread", "jitter", "lifetime", "rate"});
    if (r.has("shape")) {
        const std::string s = r.string("shape");
        if (s == "point")
            e.shape = Particles::Shape::Point;
        else if (s == "disc")
            e.shape = Particles::Shape::Disc;
        else if (s == "line")
            e.shape = Particles::Shape::Line;
        else
            throw InputError(r.field("shape"),
                             "must be \"point\", \"disc\" or \"line\", got \"" + s + "\"");
    }
    if (r.has("position")) e.position = point(r.get("position"), r.field("position"));
    if (r.has("end")) e.end = point(r.get("end"), r.field("end"));
    if (e.shape == Particles::Shape::Line && !r.has("end"))
        throw InputError(r.field("end"), "is missing: a line emitter needs its \"end\"");
    if (r.has("radius")) e.radius = r.number("radius");
    if (r.has("velocity")) e.velocity = point(r.get("velocity"), r.field("velocity"));
    if (r.has("spread")) e.spread = r.number("spread");
    if (r.has("jitter")) e.jitter = r.number("jitter");
    if (r.has("rate")) e.rate = r.number("rate");
    if (r.has("lifetime")) {
        const json& l = r.get("lifetime");
        const std::string f = r.field("lifetime");
        if (l.is_array()) {
            if (l.size() != 2)
                throw InputError(f, "must be a number or [min, max], got " + describe(l));
            e.life_min = as_number(l[0], f + "[0]");
            e.life_max = as_number(l[1], f + "[1]");
        } else {
            e.life_min = e.life_max = as_number(l, f);
        }
    }
}

}  // namespace particles_json

template <>
struct JsonIo<Particles> {
    static Particles::Input input(const json& j) {
        Reader r(j);
        r.only({"emitter", "start", "plane", "gravity", "drag", "dt", "frames", "seed", "focus"});
        Particles::Input in;
        if (r.has("emitter"))
            particles_json::emitter(r.object("emitter"), in.emitter);
        else
            in.emitter.rate = 0;
        if (r.has("start")) {
            const json& ss = r.get("start");
            const std::string sf = r.field("start");
            if (!ss.is_array())
                throw InputError(sf, "must be a list of particles, got " + describe(ss));
            if (ss.size() > std::size_t(Particles::kMaxStart))
                throw InputError(sf, "has " + std::to_string(ss.size()) + " particles; at most " +
                                         std::to_string(Particles::kMaxStart));
            for (std::size_t i = 0; i < ss.size(); ++i) {
                const Reader p(ss[i], element(sf, i));
                p.only({"position", "velocity", "lifetime"});
                Particles::Start st;
                st.position = particles_json::point(p.get("position"), p.field("position"));
                if (p.has("velocity"))
                    st.velocity = particles_json::point(p.get("velocity"), p.field("velocity"));
                if (p.has("lifetime")) st.lifetime = p.number("lifetime");
                in.start.push_back(st);
            }
        }
        if (r.has("plane")) {
            const Reader p = r.object("plane");
            p.only({"point", "normal", "restitution", "friction"});
            in.plane.on = true;
            if (p.has("point"))
                in.plane.point = particles_json::point(p.get("point"), p.field("point"));
            if (p.has("normal"))
                in.plane.normal = particles_json::point(p.get("normal"), p.field("normal"));
            if (p.has("restitution")) in.plane.restitution = p.number("restitution");
            if (p.has("friction")) in.plane.friction = p.number("friction");
        }
        if (r.has("gravity"))
            in.gravity = particles_json::point(r.get("gravity"), r.field("gravity"));
        if (r.has("drag")) in.drag = r.number("drag");
        if (r.has("dt")) in.dt = r.number("dt");
        if (r.has("frames"))
            in.frames = int(r.integer("frames", 1, Particles::kMaxFrames,
                                      "1 to " + std::to_string(Particles::kMaxFrames)));
        if (r.has("seed"))
            in.seed = std::uint64_t(r.integer("seed", 0, 9007199254740991LL, "an integer ≥ 0"));
        if (r.has("focus"))
            in.focus = int(r.integer("focus", 0, Particles::kMaxStart + Particles::kMaxEmitted,
                                     "a particle number ≥ 0"));
        return in;
    }

    static json input_json(const Particles::Input& in) {
        json j;
        const Particles::Emitter& e = in.emitter;
        json em = {{"shape", Particles::shape_name(e.shape)},
                   {"position", nice_point(e.position)},
                   {"velocity", nice_point(e.velocity)},
                   {"spread", nice_number(e.spread)},
                   {"rate", nice_number(e.rate)}};
        if (e.shape == Particles::Shape::Line) em["end"] = nice_point(e.end);
        if (e.shape == Particles::Shape::Disc) em["radius"] = nice_number(e.radius);
        if (e.jitter != 0) em["jitter"] = nice_number(e.jitter);
        em["lifetime"] = e.life_min == e.life_max
                             ? nice_number(e.life_min)
                             : json::array({nice_number(e.life_min), nice_number(e.life_max)});
        j["emitter"] = em;
        if (!in.start.empty()) {
            json ss = json::array();
            for (const auto& s : in.start) {
                json o = {{"position", nice_point(s.position)},
                          {"velocity", nice_point(s.velocity)}};
                if (s.lifetime != Particles::kForever) o["lifetime"] = nice_number(s.lifetime);
                ss.push_back(o);
            }
            j["start"] = ss;
        }
        if (in.plane.on)
            j["plane"] = {{"point", nice_point(in.plane.point)},
                          {"normal", nice_point(in.plane.normal)},
                          {"restitution", nice_number(in.plane.restitution)},
                          {"friction", nice_number(in.plane.friction)}};
        j["gravity"] = nice_point(in.gravity);
        if (in.drag != 0) j["drag"] = nice_number(in.drag);
        j["dt"] = nice_number(in.dt);
        j["frames"] = in.frames;
        j["seed"] = in.seed;
        if (in.focus != 0) j["focus"] = in.focus;
        return j;
    }

    static json result(const Particles::Result& r) {
        json j;
        j["dt"] = r.dt;
        j["frames"] = r.frames;
        j["t"] = r.t;
        j["emitted"] = r.emitted;
        j["killed"] = r.killed;
        j["alive"] = r.alive;
        j["bounces"] = r.bounces;
        j["alive_per_frame"] = r.alive_per_frame;
        j["emitted_per_frame"] = r.emitted_per_frame;
        j["killed_per_frame"] = r.killed_per_frame;
        j["ids"] = r.ids;
        json p = json::array(), v = json::array();
        for (const auto& x : r.positions) p.push_back(to_json(x));
        for (const auto& x : r.velocities) v.push_back(to_json(x));
        j["positions"] = p;
        j["velocities"] = v;
        j["ages"] = r.ages;
        j["focus"] = r.focus;
        j["focus_born"] = r.focus_born;
        j["focus_alive"] = r.focus_alive;
        j["x"] = to_json(r.x);
        j["v"] = to_json(r.v);
        return j;
    }

    static json example() {
        // A small fountain over the ground: 20 particles a second for 2 s, bouncing.
        return parse_json(R"({
            "emitter": {"shape": "point", "position": [0, 0.5], "velocity": [0, 5],
                        "spread": 20, "lifetime": [1.5, 2], "rate": 20},
            "plane": {"point": [0, 0], "normal": [0, 1], "restitution": 0.5, "friction": 0.2},
            "gravity": [0, -9.81], "dt": 0.05, "frames": 40, "seed": 7})");
    }
};

Algorithm particles_algorithm() {
    return make_algorithm<Particles>(
        [](const Particles::Input& in) { return Particles::compute(in); });
}

}  // namespace cg
