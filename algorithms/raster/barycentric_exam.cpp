// Barycentric exam problems: mostly 2D, a triangle with whole-number vertices in [0, 6]² (either
// orientation, never thin) and one or two points with whole or half coordinates near it —
// inside, outside, now and then exactly on an edge (a midpoint) or at a vertex. About one
// problem in five is 3D: whole-number vertices in [0, 4]³ and a point given as a combination of
// them with weights in quarters, in the plane or pushed off it along the normal.
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "raster/barycentric.hpp"

namespace cg {

namespace {

std::string pt(int dim, const glm::dvec3& p) {
    return dim == 2 ? num(glm::dvec2(p.x, p.y)) : num(p);
}

double half(Rng& rng, double lo, double hi) {
    return rng.integer(static_cast<long long>(2 * lo), static_cast<long long>(2 * hi)) / 2.0;
}

}  // namespace

Barycentric::Input Barycentric::exam_input(Rng& rng) {
    Input in;
    auto& v = in.triangle;
    const int points = rng.chance(0.6) ? 1 : 2;
    if (rng.chance(0.8)) {
        in.dim = 2;
        do {
            for (auto& p : v) p = {double(rng.integer(0, 6)), double(rng.integer(0, 6)), 0};
        } while (std::fabs(glm::cross(v[1] - v[0], v[2] - v[0]).z) < 6);
        for (int k = 0; k < points; ++k) {
            const double kind = rng.uniform(0, 1);
            glm::dvec3 p;
            if (kind < 0.15) {
                const int i = static_cast<int>(rng.integer(0, 2));
                p = (v[i] + v[(i + 1) % 3]) / 2.0;  // on an edge
            } else if (kind < 0.22) {
                p = v[rng.integer(0, 2)];  // a vertex
            } else {
                p = {half(rng, -1, 7), half(rng, -1, 7), 0};
            }
            in.points.push_back(p);
        }
    } else {
        in.dim = 3;
        glm::dvec3 n;
        do {
            for (auto& p : v)
                p = {double(rng.integer(0, 4)), double(rng.integer(0, 4)),
                     double(rng.integer(0, 4))};
            n = glm::cross(v[1] - v[0], v[2] - v[0]);
        } while (glm::dot(n, n) < 16);
        for (int k = 0; k < points; ++k) {
            const double a = rng.integer(-1, 4) / 4.0, b = rng.integer(0, 4) / 4.0;
            glm::dvec3 p = a * v[0] + b * v[1] + (1 - a - b) * v[2];
            if (rng.chance(0.5)) p += (rng.integer(1, 2) / 4.0) * n;  // off the plane
            in.points.push_back(p);
        }
    }
    return in;
}

std::string Barycentric::question(const Input& in) {
    const auto& v = in.triangle;
    std::string points;
    for (std::size_t k = 0; k < in.points.size(); ++k)
        points += std::string(k ? " and " : "") + "P" + std::to_string(k) + " = " +
                  pt(in.dim, in.points[k]);
    std::string q = "Give the barycentric coordinates of " + points +
                    " in the triangle A = " + pt(in.dim, v[0]) + ", B = " + pt(in.dim, v[1]) +
                    ", C = " + pt(in.dim, v[2]) +
                    (in.points.size() > 1 ? "; is each point inside?" : "; is P0 inside?");
    if (in.dim == 2)
        q += " Give the triangle's signed area ½ (B − A) × (C − A) (area), and for each point "
             "(results, a list) an object with \"weights\": [α, β, γ] = [A_a, A_b, A_c] / area, "
             "\"inside\" (the boundary counts as inside), \"on_edge\", and \"areas\": the signed "
             "areas [A_a, A_b, A_c] of (P, B, C), (A, P, C) and (A, B, P).";
    else
        q += " The points need not lie in the triangle's plane: take n = (B − A) × (C − A) "
             "and give area = |n|/2 (area), then for each point (results, a list) an object "
             "with \"weights\": [α, β, γ] of its projection P′ onto the plane, \"inside\" (the "
             "boundary counts), \"on_edge\", \"areas\": [A_a, A_b, A_c] = ½ ((C − B) × (P′ − "
             "B)) · N and so on (N = n/|n|), \"distance\": (P − A) · N (signed) and \"projected\": "
             "P′.";
    return q;
}

std::vector<std::string> Barycentric::answer_fields() {
    return {"area", "results"};
}

}  // namespace cg
