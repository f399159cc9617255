// Radiosity, JSON:
//   input  {"surfaces": [surface, ...],
//           "subdivision": n (1..32, default 1: each surface into n × n patches),
//           "method": "jacobi" | "gauss-seidel" (default) | "progressive",
//           "form_factors": {"method": "hemicube" (default) | "monte-carlo" | "analytic",
//                            "resolution": R (even, 2..128, default 16), "samples": m (1..8,
//                            default 1), "rays": N (1..100000, default 2000), "seed": s},
//           "tolerance": t (> 0, default 1e-4), "max_steps": k (1..100000, default 500),
//           "camera": {"position", "target", "up", "fov_deg" (vertical), "width", "height"}}
//   surface  a rectangle or triangle patch as form-factor reads it (radiosity/patch_json.hpp)
//            with "emission": [r, g, b] (default 0) and "reflectance": [r, g, b] (default 0.5)
//   result {"patches": N, "steps", "converged", "residual", "reciprocity_error",
//           "min_row_sum", "max_row_sum", "table": [{"patch", "surface", "area", "E", "rho",
//           "B", "row_sum"}, ...], "radiosity": [[r, g, b], ...], "shot_power", "unshot_power",
//           "first_shot": {"shooter", "F_ji", "delta_B"} | null (not progressive),
//           "form_factors": rows of F | null (more than 16 patches)}
#include <limits>

#include "io/registry.hpp"
#include "radiosity/patch_json.hpp"
#include "radiosity/radiosity.hpp"

namespace cg {

namespace {

using Method = Radiosity::Method;
using FF = Radiosity::FormFactors;

json rgb(const glm::dvec3& v) {
    return json::array({v.x, v.y, v.z});
}

const char* method_name(Method m) {
    return m == Method::Jacobi ? "jacobi" : m == Method::GaussSeidel ? "gauss-seidel" : "progressive";
}
const char* ff_name(FF m) {
    return m == FF::Hemicube ? "hemicube" : m == FF::MonteCarlo ? "monte-carlo" : "analytic";
}

}  // namespace

template <>
struct JsonIo<Radiosity> {
    static Radiosity::Input input(const json& j) {
        Reader r(j);
        r.only({"surfaces", "subdivision", "method", "form_factors", "tolerance", "max_steps",
                "camera"});
        Radiosity::Input in;
        const json& list = r.get("surfaces");
        if (!list.is_array())
            throw InputError(r.field("surfaces"), "must be a list of surfaces, got " + describe(list));
        if (list.size() > Radiosity::kMaxPatches)
            throw InputError(r.field("surfaces"), "has " + std::to_string(list.size()) +
                                                      " surfaces; at most " +
                                                      std::to_string(Radiosity::kMaxPatches));
        for (std::size_t k = 0; k < list.size(); ++k) {
            const Reader s(list[k], element(r.field("surfaces"), k));
            Radiosity::Surface surface;
            surface.patch = read_patch(s, {"emission", "reflectance"});
            if (s.has("emission")) surface.emission = s.point3("emission");
            if (s.has("reflectance")) surface.reflectance = s.point3("reflectance");
            in.surfaces.push_back(surface);
        }
        if (r.has("subdivision"))
            in.subdivision = int(r.integer("subdivision", 1, Radiosity::kMaxSubdivision, "from 1 to 32"));
        if (r.has("method")) {
            const std::string m = r.string("method");
            if (m == "jacobi")
                in.method = Method::Jacobi;
            else if (m == "gauss-seidel")
                in.method = Method::GaussSeidel;
            else if (m == "progressive")
                in.method = Method::Progressive;
            else
                throw InputError(r.field("method"),
                                 "must be \"jacobi\", \"gauss-seidel\" or \"progressive\", got \"" +
                                     m + "\"");
        }
        if (r.has("form_factors")) {
            const Reader f = r.object("form_factors");
            f.only({"method", "resolution", "samples", "rays", "seed"});
            if (f.has("method")) {
                const std::string m = f.string("method");
                if (m == "hemicube")
                    in.form_factors = FF::Hemicube;
                else if (m == "monte-carlo")
                    in.form_factors = FF::MonteCarlo;
                else if (m == "analytic")
                    in.form_factors = FF::Analytic;
                else
                    throw InputError(f.field("method"),
                                     "must be \"hemicube\", \"monte-carlo\" or \"analytic\", got \"" +
                                         m + "\"");
            }
            if (f.has("resolution"))
                in.resolution = int(f.integer("resolution", 2, Radiosity::kMaxResolution,
                                            "an even number of cells from 2 to 128"));
            if (f.has("samples"))
                in.samples = int(f.integer("samples", 1, Radiosity::kMaxSamples, "from 1 to 8"));
            if (f.has("rays"))
                in.rays = f.integer("rays", 1, Radiosity::kMaxRays, "from 1 to 100000");
            if (f.has("seed"))
                in.seed = std::uint64_t(f.integer("seed", 0, std::numeric_limits<long long>::max(),
                                                "a non-negative integer"));
        }
        if (r.has("tolerance")) in.tolerance = r.number("tolerance");
        if (r.has("max_steps"))
            in.max_steps = int(r.integer("max_steps", 1, Radiosity::kMaxSteps, "from 1 to 100000"));
        if (r.has("camera")) {
            const Reader c = r.object("camera");
            c.only({"position", "target", "up", "fov_deg", "width", "height"});
            auto& cam = in.camera;
            if (c.has("position")) cam.position = c.point3("position");
            if (c.has("target")) cam.target = c.point3("target");
            if (c.has("up")) cam.up = c.point3("up");
            if (c.has("fov_deg")) cam.fov_deg = c.number("fov_deg");
            if (c.has("width"))
                cam.width = int(c.integer("width", 1, Radiosity::kMaxImage, "from 1 to 64 pixels"));
            if (c.has("height"))
                cam.height = int(c.integer("height", 1, Radiosity::kMaxImage, "from 1 to 64 pixels"));
        }
        return in;
    }

    static json input_json(const Radiosity::Input& in) {
        json surfaces = json::array();
        for (const auto& s : in.surfaces) {
            json p = patch_json(s.patch);
            p["emission"] = nice_point(s.emission);
            p["reflectance"] = nice_point(s.reflectance);
            surfaces.push_back(p);
        }
        const auto& c = in.camera;
        return json{{"surfaces", surfaces},
                    {"subdivision", in.subdivision},
                    {"method", method_name(in.method)},
                    {"form_factors",
                     {{"method", ff_name(in.form_factors)},
                      {"resolution", in.resolution},
                      {"samples", in.samples},
                      {"rays", in.rays},
                      {"seed", in.seed}}},
                    {"tolerance", in.tolerance},
                    {"max_steps", in.max_steps},
                    {"camera",
                     {{"position", nice_point(c.position)},
                      {"target", nice_point(c.target)},
                      {"up", nice_point(c.up)},
                      {"fov_deg", nice_number(c.fov_deg)},
                      {"width", c.width},
                      {"height", c.height}}}};
    }

    static json result(const Radiosity::Result& r) {
        const auto& sc = *r.scene;
        const std::size_t n = sc.patches.size();
        json table = json::array(), B = json::array();
        double lo = n ? 1e300 : 0, hi = 0;
        for (std::size_t k = 0; k < n; ++k) {
            table.push_back({{"patch", k},
                             {"surface", sc.surface[k]},
                             {"area", sc.area[k]},
                             {"E", rgb(sc.emission[k])},
                             {"rho", rgb(sc.reflectance[k])},
                             {"B", rgb(r.radiosity[k])},
                             {"row_sum", r.row_sum[k]}});
            B.push_back(rgb(r.radiosity[k]));
            lo = std::min(lo, r.row_sum[k]);
            hi = std::max(hi, r.row_sum[k]);
        }
        json shot = nullptr;
        if (r.first_shot.shooter >= 0)
            shot = json{{"shooter", r.first_shot.shooter},
                        {"F_ji", r.first_shot.f_ji},
                        {"delta_B", r.first_shot.delta_b}};
        json F = nullptr;
        if (n <= 16) {
            F = json::array();
            for (std::size_t i = 0; i < n; ++i)
                F.push_back(std::vector<double>(r.form_factors.begin() + std::ptrdiff_t(i * n),
                                                r.form_factors.begin() + std::ptrdiff_t(i * n + n)));
        }
        return json{{"patches", n},
                    {"steps", r.steps},
                    {"converged", r.converged},
                    {"residual", r.residual},
                    {"reciprocity_error", r.reciprocity_error},
                    {"min_row_sum", lo},
                    {"max_row_sum", hi},
                    {"table", table},
                    {"radiosity", B},
                    {"shot_power", rgb(r.shot_power)},
                    {"unshot_power", rgb(r.unshot_power)},
                    {"first_shot", shot},
                    {"form_factors", F}};
    }

    static json example() {
        // A Cornell box, the unit cube with inward normals: white floor, ceiling, back and front
        // walls, a red left and a green right wall, and a square lamp just under the ceiling.
        auto rect = [](glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v, glm::dvec3 rho,
                       glm::dvec3 e = {0, 0, 0}) {
            return json{{"type", "rectangle"},     {"corner", nice_point(corner)},
                        {"edge_u", nice_point(u)}, {"edge_v", nice_point(v)},
                        {"emission", nice_point(e)}, {"reflectance", nice_point(rho)}};
        };
        const glm::dvec3 white{0.75, 0.75, 0.75}, red{0.75, 0.2, 0.2}, green{0.2, 0.75, 0.2};
        json surfaces = json::array({
            rect({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, white),  // floor, normal +y
            rect({0, 1, 0}, {1, 0, 0}, {0, 0, 1}, white),  // ceiling, −y
            rect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, white),  // back wall, +z
            rect({0, 0, 1}, {0, 1, 0}, {1, 0, 0}, white),  // front wall (behind the camera), −z
            rect({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, red),    // left wall, +x
            rect({1, 0, 0}, {0, 0, 1}, {0, 1, 0}, green),  // right wall, −x
            rect({0.35, 0.99, 0.35}, {0.3, 0, 0}, {0, 0, 0.3}, {0.8, 0.8, 0.8},
                 {10, 10, 10}),  // the lamp, facing down
        });
        return json{{"surfaces", surfaces},
                    {"subdivision", 2},
                    {"method", "gauss-seidel"},
                    {"form_factors", {{"method", "hemicube"}, {"resolution", 8}, {"samples", 1}}},
                    {"tolerance", 1e-3},
                    {"max_steps", 100},
                    {"camera",
                     {{"position", {0.5, 0.5, 0.95}},
                      {"target", {0.5, 0.5, 0}},
                      {"up", {0, 1, 0}},
                      {"fov_deg", 80},
                      {"width", 24},
                      {"height", 24}}}};
    }
};

Algorithm radiosity_algorithm() {
    return make_algorithm<Radiosity>(
        [](const Radiosity::Input& in) { return Radiosity::compute(in); });
}

}  // namespace cg
