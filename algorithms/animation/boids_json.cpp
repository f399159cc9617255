// Boids, JSON:
//   input  {"boids": [{"position": [x, y], "velocity": [vx, vy] (default 0)}]
//           or instead "random": {"count": n (1 to 1000), "seed": s} (uniform in the world,
//           outside the obstacles, any heading, speeds from max_speed/2 to max_speed),
//           "world": {"min": [x, y], "max": [x, y]} (default [-10, -10] to [10, 10]),
//           "edges": "wrap" (default) | "steer", "margin": the steer band (default 1/10 side),
//           "obstacles": [{"center": [x, y], "radius": R}],
//           "radius": r (3), "separation_radius": r_sep (default r), "fov": degrees (360),
//           "weights": {"separation": 1.5, "alignment": 1, "cohesion": 1, "avoidance": 2,
//                       "bounds": 2},
//           "max_speed": 2, "min_speed": 0, "max_force": 4, "dt": 0.05, "steps": 200 (1 to
//           100000, steps × boids² ≤ 5·10⁷), "focus": the boid narrated and drawn (0)}
//   result {"dt", "steps", "t", "positions", "velocities" (final, every boid),
//           "focus": {"index", "x", "v" (at the end), "neighbours", "separation", "alignment",
//                     "cohesion", "avoidance", "bounds", "steering" (its rules in the last step)},
//           "polarisation", "nearest": after 0, 1, …, steps steps,
//           "final_polarisation", "final_nearest"}
#include "animation/boids.hpp"
#include "core/format.hpp"
#include "io/registry.hpp"

namespace cg {

namespace boids_json {

glm::dvec2 point(const json& v, const std::string& field) {
    if (!v.is_array() || v.size() != 2)
        throw InputError(field, "must be a point [x, y], got " + describe(v));
    return {as_number(v[0], field + "[0]"), as_number(v[1], field + "[1]")};
}

}  // namespace boids_json

template <>
struct JsonIo<Boids> {
    using Edges = Boids::Edges;

    static Boids::Input input(const json& j) {
        Reader r(j);
        r.only({"boids", "random", "world", "edges", "margin", "obstacles", "radius",
                "separation_radius", "fov", "weights", "max_speed", "min_speed", "max_force", "dt",
                "steps", "focus"});
        Boids::Input in;
        if (r.has("random")) {
            if (r.has("boids"))
                throw InputError(r.field("random"), "give either \"boids\" or \"random\", not both");
            const Reader g = r.object("random");
            g.only({"count", "seed"});
            in.random.count = int(g.integer("count", 1, Boids::kMaxBoids,
                                            "1 to " + std::to_string(Boids::kMaxBoids) + " boids"));
            in.random.seed = std::uint64_t(
                g.has("seed") ? g.integer("seed", 0, 9007199254740992LL, "0 to 2^53") : 0);
        } else {
            if (!r.has("boids"))
                throw InputError("boids",
                                 "is missing: give \"boids\" (a list of {\"position\", "
                                 "\"velocity\"}) or \"random\": {\"count\", \"seed\"}");
            const json& bs = r.get("boids");
            const std::string bf = r.field("boids");
            if (!bs.is_array()) throw InputError(bf, "must be a list of boids, got " + describe(bs));
            if (bs.size() > std::size_t(Boids::kMaxBoids))
                throw InputError(bf, "has " + std::to_string(bs.size()) + " boids; at most " +
                                         std::to_string(Boids::kMaxBoids) + " are simulated");
            for (std::size_t i = 0; i < bs.size(); ++i) {
                const Reader b(bs[i], element(bf, i));
                b.only({"position", "velocity"});
                Boids::Boid boid;
                boid.position = boids_json::point(b.get("position"), b.field("position"));
                if (b.has("velocity"))
                    boid.velocity = boids_json::point(b.get("velocity"), b.field("velocity"));
                in.boids.push_back(boid);
            }
        }
        if (r.has("world")) {
            const Reader w = r.object("world");
            w.only({"min", "max"});
            in.world_min = boids_json::point(w.get("min"), w.field("min"));
            in.world_max = boids_json::point(w.get("max"), w.field("max"));
        }
        if (r.has("edges")) {
            const std::string e = r.string("edges");
            if (e == "wrap")
                in.edges = Edges::Wrap;
            else if (e == "steer")
                in.edges = Edges::Steer;
            else
                throw InputError(r.field("edges"),
                                 "must be \"wrap\" or \"steer\", got \"" + e + "\"");
        }
        if (r.has("margin")) {
            in.margin = r.number("margin");
            if (in.margin < 0)  // −1 means "the default" inside; refuse it here
                throw InputError(r.field("margin"),
                                 "must be a width of 1e-6 to 1e6, got " + given(in.margin));
        }
        if (r.has("obstacles")) {
            const json& os = r.get("obstacles");
            const std::string of = r.field("obstacles");
            if (!os.is_array())
                throw InputError(of, "must be a list of circles, got " + describe(os));
            if (os.size() > std::size_t(Boids::kMaxObstacles))
                throw InputError(of, "has " + std::to_string(os.size()) + " obstacles; at most " +
                                         std::to_string(Boids::kMaxObstacles));
            for (std::size_t k = 0; k < os.size(); ++k) {
                const Reader o(os[k], element(of, k));
                o.only({"center", "radius"});
                in.obstacles.push_back(
                    {boids_json::point(o.get("center"), o.field("center")), o.number("radius")});
            }
        }
        if (r.has("radius")) in.radius = r.number("radius");
        if (r.has("separation_radius")) {
            in.separation_radius = r.number("separation_radius");
            if (in.separation_radius < 0)  // −1 means "the default" inside; refuse it here
                throw InputError(r.field("separation_radius"),
                                 "must be ≥ 0 (the separation radius r_sep), got " +
                                     given(in.separation_radius));
        }
        if (r.has("fov")) in.fov = r.number("fov");
        if (r.has("weights")) {
            const Reader w = r.object("weights");
            w.only({"separation", "alignment", "cohesion", "avoidance", "bounds"});
            if (w.has("separation")) in.weights.separation = w.number("separation");
            if (w.has("alignment")) in.weights.alignment = w.number("alignment");
            if (w.has("cohesion")) in.weights.cohesion = w.number("cohesion");
            if (w.has("avoidance")) in.weights.avoidance = w.number("avoidance");
            if (w.has("bounds")) in.weights.bounds = w.number("bounds");
        }
        if (r.has("max_speed")) in.max_speed = r.number("max_speed");
        if (r.has("min_speed")) in.min_speed = r.number("min_speed");
        if (r.has("max_force")) in.max_force = r.number("max_force");
        if (r.has("dt")) in.dt = r.number("dt");
        if (r.has("steps"))
            in.steps = int(r.integer("steps", 1, Boids::kMaxSteps,
                                     "1 to " + std::to_string(Boids::kMaxSteps)));
        if (r.has("focus"))
            in.focus = int(r.integer("focus", -1000000, 1000000, "a boid index"));
        return in;
    }

    static json input_json(const Boids::Input& in) {
        json j;
        if (in.random.count > 0) {
            j["random"] = {{"count", in.random.count}, {"seed", in.random.seed}};
        } else {
            json bs = json::array();
            for (const auto& b : in.boids) {
                json o = {{"position", nice_point(b.position)}};
                if (b.velocity != glm::dvec2(0)) o["velocity"] = nice_point(b.velocity);
                bs.push_back(o);
            }
            j["boids"] = bs;
        }
        j["world"] = {{"min", nice_point(in.world_min)}, {"max", nice_point(in.world_max)}};
        j["edges"] = Boids::edges_name(in.edges);
        if (in.margin != -1) j["margin"] = nice_number(in.margin);
        if (!in.obstacles.empty()) {
            json os = json::array();
            for (const auto& o : in.obstacles)
                os.push_back({{"center", nice_point(o.center)}, {"radius", nice_number(o.radius)}});
            j["obstacles"] = os;
        }
        j["radius"] = nice_number(in.radius);
        if (in.separation_radius != -1) j["separation_radius"] = nice_number(in.separation_radius);
        j["fov"] = nice_number(in.fov);
        j["weights"] = {{"separation", nice_number(in.weights.separation)},
                        {"alignment", nice_number(in.weights.alignment)},
                        {"cohesion", nice_number(in.weights.cohesion)},
                        {"avoidance", nice_number(in.weights.avoidance)},
                        {"bounds", nice_number(in.weights.bounds)}};
        j["max_speed"] = nice_number(in.max_speed);
        j["min_speed"] = nice_number(in.min_speed);
        j["max_force"] = nice_number(in.max_force);
        j["dt"] = nice_number(in.dt);
        j["steps"] = in.steps;
        j["focus"] = in.focus;
        return j;
    }

    static json result(const Boids::Result& r) {
        json j;
        j["dt"] = r.dt;
        j["steps"] = r.steps;
        j["t"] = r.t;
        json p = json::array(), v = json::array();
        for (const auto& x : r.positions) p.push_back(to_json(x));
        for (const auto& x : r.velocities) v.push_back(to_json(x));
        j["positions"] = p;
        j["velocities"] = v;
        j["focus"] = {{"index", r.focus},
                      {"x", to_json(r.x)},
                      {"v", to_json(r.v)},
                      {"neighbours", r.rules.neighbours},
                      {"separation", to_json(r.rules.separation)},
                      {"alignment", to_json(r.rules.alignment)},
                      {"cohesion", to_json(r.rules.cohesion)},
                      {"avoidance", to_json(r.rules.avoidance)},
                      {"bounds", to_json(r.rules.bounds)},
                      {"steering", to_json(r.rules.steering)}};
        j["polarisation"] = r.polarisation;
        j["nearest"] = r.nearest;
        j["final_polarisation"] = r.polarisation.back();
        j["final_nearest"] = r.nearest.back();
        return j;
    }

    static json example() {
        // Boid 0 with three neighbours (two close, one not) and two boids it cannot see.
        return parse_json(R"({
            "boids": [{"position": [0, 0], "velocity": [1, 0]},
                      {"position": [1, 0], "velocity": [0, 1]},
                      {"position": [0, -2], "velocity": [1, 1]},
                      {"position": [-3, 4], "velocity": [1, -1]},
                      {"position": [6, 2], "velocity": [-1, 0]},
                      {"position": [-5, -6], "velocity": [0, 1]}],
            "world": {"min": [-10, -10], "max": [10, 10]}, "edges": "wrap",
            "radius": 5.5, "separation_radius": 2.5,
            "weights": {"separation": 1, "alignment": 1, "cohesion": 1},
            "max_speed": 2, "max_force": 4, "dt": 0.1, "steps": 60})");
    }
};

Algorithm boids_algorithm() {
    return make_algorithm<Boids>([](const Boids::Input& in) { return Boids::compute(in); });
}

}  // namespace cg
