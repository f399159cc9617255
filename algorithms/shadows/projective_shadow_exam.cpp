// Projective shadow exam problems: an axis plane (x, y or z = c with c ∈ {−1, 0, 1}, the normal
// along the positive axis), a small integer point light 2 to 6 above it (one problem in four a
// directional light, the sun, with a small integer direction), and a triangle of integer vertices
// between the plane and the light's height (now and then one on the plane: its own shadow).
// The question asks for the shadow matrix and the shadow of the highest vertex.
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "shadows/projective_shadow.hpp"

namespace cg {

namespace {

int highest(const ProjectiveShadow::Input& in) {
    int best = 0;
    double top = -1e300;
    for (std::size_t k = 0; k < in.polygon.size(); ++k) {
        const double h = glm::dot(in.normal, in.polygon[k]) + in.d;
        if (h > top) top = h, best = int(k);
    }
    return best;
}

}  // namespace

ProjectiveShadow::Input ProjectiveShadow::exam_input(Rng& rng) {
    Input in;
    const int axis = int(rng.integer(0, 2));
    static constexpr int kOffsets[] = {0, 0, 0, 1, -1};
    const int c = kOffsets[rng.integer(0, 4)];
    in.normal = glm::dvec3(0);
    in.normal[axis] = 1;
    in.d = -c;
    const bool sun = rng.chance(0.25);
    const int height = int(rng.integer(2, 6));
    if (sun) {
        glm::dvec3 l;
        for (int i = 0; i < 3; ++i) l[i] = double(rng.integer(-2, 2));
        l[axis] = double(rng.integer(1, 2));
        in.light = glm::dvec4(l, 0);
    } else {
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) p[i] = double(rng.integer(-3, 3));
        p[axis] = c + height;
        in.light = glm::dvec4(p, 1);
    }
    in.polygon.resize(3);
    for (auto& v : in.polygon) {
        for (int i = 0; i < 3; ++i) v[i] = double(rng.integer(-3, 3));
        v[axis] = c + double(rng.integer(rng.chance(0.15) ? 0 : 1, sun ? 3 : height - 1));
    }
    return in;
}

std::string ProjectiveShadow::question(const Input& in) {
    std::string poly;
    for (std::size_t k = 0; k < in.polygon.size(); ++k)
        poly += (k ? ", " : "") + std::string("p") + std::to_string(k) + " = " + num(in.polygon[k]);
    const std::string light =
        in.light.w == 0
            ? "a directional light (the sun) in the direction l = " + num(glm::dvec3(in.light)) +
                  " (toward the light), L = [l, 0]"
            : "a point light at " + num(glm::dvec3(in.light)) + ", L = [L, 1]";
    const int k = highest(in);
    return "A triangle " + poly +
           " casts a shadow onto the plane n · x + d = 0 with n = " + num(in.normal) +
           ", d = " + num(in.d) + " from " + light +
           ". With P = [n, d], build the shadow matrix M = (P · L) I − L Pᵀ (matrix: 4×4, rows, "
           "acting on column vectors [x, y, z, 1]) and give the shadow of vertex p" +
           std::to_string(k) + " (shadow/" + std::to_string(k) + ": M p, then divide by w′).";
}

std::vector<std::string> ProjectiveShadow::answer_fields(const Input& in) {
    return {"matrix", "shadow/" + std::to_string(highest(in))};
}

}  // namespace cg
