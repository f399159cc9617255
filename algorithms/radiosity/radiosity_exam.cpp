// Radiosity exam problems: one progressive-refinement step by hand on 3 patches. Patch 0 (a × b,
// the only emitter) lies on the floor; patch 1 (a × c) stands on its edge at a right angle;
// patch 2 (a × b) faces patch 0 at height c, sharing its top edge with patch 1. The question
// gives the areas' sizes, E_0, the reflectances and F_01, F_02 (analytic formulas); the student
// names the shooter, works out F_j0 = A_0 F_0j / A_j by reciprocity and the radiosity each patch
// receives, ΔB_j = ρ_j F_j0 ΔB_0 (RGB).
#include "core/format.hpp"
#include "radiosity/radiosity.hpp"

namespace cg {

Radiosity::Input Radiosity::exam_input(Rng& rng) {
    Input in;
    in.method = Method::Progressive;
    in.form_factors = FormFactors::Analytic;
    in.rays = 200;
    in.seed = std::uint64_t(rng.integer(1, 1000));
    in.max_steps = 1;
    const double a = double(rng.integer(1, 3)), b = double(rng.integer(1, 3)),
                 c = double(rng.integer(1, 3));
    const double e = double(rng.integer(1, 5));
    auto rho = [&] {
        return glm::dvec3(0.25 * double(rng.integer(1, 3)), 0.25 * double(rng.integer(1, 3)),
                          0.25 * double(rng.integer(1, 3)));
    };
    in.surfaces = {
        {Patch::rectangle({0, 0, 0}, {a, 0, 0}, {0, b, 0}), {e, e, e}, rho()},
        {Patch::rectangle({0, 0, 0}, {0, 0, c}, {a, 0, 0}), {0, 0, 0}, rho()},
        {Patch::rectangle({0, 0, c}, {0, b, 0}, {a, 0, 0}), {0, 0, 0}, rho()},
    };
    in.camera = {{0.5 * a, 2 * b + c, 0.5 * c}, {0.5 * a, 0, 0.5 * c}, {0, 0, 1}, 60, 12, 12};
    return in;
}

std::string Radiosity::question(const Input& in) {
    const Patch &p0 = in.surfaces[0].patch, &p1 = in.surfaces[1].patch, &p2 = in.surfaces[2].patch;
    const double a = p0.b.x, b = p0.c.y, c = p1.b.z;
    const double f01 = ff::analytic(p0, p1).value, f02 = ff::analytic(p0, p2).value;
    auto rgb = [](const glm::dvec3& v) { return num(v, 4); };
    return "Three patches: patch 0 is a " + num(a) + " × " + num(b) +
           " floor emitting E_0 = " + rgb(in.surfaces[0].emission) + "; patch 1 is a " + num(a) +
           " × " + num(c) + " wall standing on its edge of length " + num(a) +
           "; patch 2 is a " + num(a) + " × " + num(b) + " ceiling at height " + num(c) +
           ". Reflectances ρ_0 = " + rgb(in.surfaces[0].reflectance) + ", ρ_1 = " +
           rgb(in.surfaces[1].reflectance) + ", ρ_2 = " + rgb(in.surfaces[2].reflectance) +
           ". The form factors from the floor are F_01 = " + num(f01, 5) + " and F_02 = " +
           num(f02, 5) +
           ". Progressive refinement starts with B = ΔB = E. Do its first step by hand: which "
           "patch shoots (first_shot/shooter), the form factors back to it by reciprocity "
           "A_i F_ij = A_j F_ji for every patch (first_shot/F_ji, 0 for the shooter itself), and "
           "the radiosity each patch receives, ΔB_j = ρ_j F_ji ΔB_i per channel "
           "(first_shot/delta_B, a list of [r, g, b]).";
}

std::vector<std::string> Radiosity::answer_fields(const Input&) {
    return {"first_shot/shooter", "first_shot/F_ji", "first_shot/delta_B"};
}

}  // namespace cg
