// Toon shading exam problems: three triangles whose unit normals are integer vectors over an
// integer length (Pythagorean quadruples: (1, 2, 2)/3, (2, 3, 6)/7, …, so N̂·L̂ is a fraction a
// student can work exactly), a light direction of the same kind, and one or two thresholds in
// tenths. One face in three or so is turned from the light. No N̂·L̂ lands exactly on a
// threshold (the rounded double could then fall either side); the tie rule has its own test.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>

#include "core/format.hpp"
#include "npr/toon_shading.hpp"

namespace cg {

namespace {

// (a, b, c) with a² + b² + c² = m², m listed last.
constexpr int kQuads[][4] = {{0, 0, 1, 1}, {1, 2, 2, 3}, {2, 3, 6, 7}, {1, 4, 8, 9},
                             {4, 4, 7, 9}, {2, 6, 9, 11}, {0, 3, 4, 5}, {2, 10, 11, 15}};

glm::ivec3 random_unit_ish(Rng& rng, int& m) {
    const auto& q = kQuads[rng.integer(0, 7)];
    int v[3] = {q[0], q[1], q[2]};
    for (int i = 2; i > 0; --i) std::swap(v[i], v[rng.integer(0, i)]);  // shuffle the axes
    for (int& x : v)
        if (rng.chance(0.5)) x = -x;
    m = q[3];
    return {v[0], v[1], v[2]};
}

// The triangle at `p0` with outward normal along n: u ⊥ n, v = n × u, (u × v) = |u|² n.
void add_triangle(ToonShading::Input& in, glm::dvec3 p0, glm::ivec3 n) {
    const glm::dvec3 nd(n);
    glm::dvec3 u{0, 0, 0};
    for (const glm::dvec3 c : {glm::dvec3{1, 0, 0}, glm::dvec3{0, 1, 0}, glm::dvec3{0, 0, 1}}) {
        u = glm::cross(nd, c);
        if (u != glm::dvec3{0, 0, 0}) break;
    }
    const glm::dvec3 v = glm::cross(nd, u);
    const int base = static_cast<int>(in.mesh.vertices.size());
    in.mesh.vertices.push_back(p0);
    in.mesh.vertices.push_back(p0 + u);
    in.mesh.vertices.push_back(p0 + v);
    in.mesh.faces.push_back({base, base + 1, base + 2});
}

// The integer direction of v (made coprime) and, when its length is an integer, that length.
std::string fraction(glm::dvec3 v) {
    long long a = std::llround(v.x), b = std::llround(v.y), c = std::llround(v.z);
    const long long g = std::gcd(std::gcd(std::llabs(a), std::llabs(b)), std::llabs(c));
    if (g > 0) a /= g, b /= g, c /= g;
    const long long q = a * a + b * b + c * c;
    const long long m = std::llround(std::sqrt(static_cast<double>(q)));
    const std::string dir = "(" + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + ")";
    if (m * m == q) return m == 1 ? dir : dir + "/" + std::to_string(m);
    return dir + "/√" + std::to_string(q);
}

}  // namespace

ToonShading::Input ToonShading::exam_input(Rng& rng) {
    for (;;) {
        Input in;
        int ml = 1;
        const glm::ivec3 l = random_unit_ish(rng, ml);
        in.light = glm::dvec3(l);
        const int bands = rng.chance(0.5) ? 2 : 3;
        while (static_cast<int>(in.thresholds.size()) < bands - 1) {
            const double t = rng.integer(2, 8) / 10.0;
            if (std::find(in.thresholds.begin(), in.thresholds.end(), t) == in.thresholds.end())
                in.thresholds.push_back(t);
        }
        std::sort(in.thresholds.begin(), in.thresholds.end());
        bool tie = false;
        for (int k = 0; k < 3; ++k) {
            int mn = 1;
            const glm::ivec3 n = random_unit_ish(rng, mn);
            add_triangle(in, {3.0 * k, 0, 0}, n);
            // N̂·L̂ = (n·l)/(mn ml) equals t = j/10 iff 10 (n·l) = j mn ml: exact in integers.
            const long long dot = static_cast<long long>(n.x) * l.x + static_cast<long long>(n.y) * l.y +
                                  static_cast<long long>(n.z) * l.z;
            for (double t : in.thresholds)
                tie = tie || 10 * dot == std::llround(t * 10) * mn * ml;
        }
        if (!tie) return in;
    }
}

std::string ToonShading::question(const Input& in) {
    std::string q = "Toon shading with flat faces. The unit light direction (towards the light) is L̂ = " +
                    fraction(in.light) + ". The faces' unit outward normals are";
    for (std::size_t k = 0; k < in.mesh.faces.size(); ++k)
        q += (k ? ", " : " ") + std::string("N̂") + std::to_string(k) + " = " +
             fraction(npr::newell(in.mesh.vertices, in.mesh.faces[k]));
    q += ". The thresholds are";
    for (std::size_t i = 0; i < in.thresholds.size(); ++i)
        q += (i ? ", " : " ") + std::string("t") + std::to_string(i + 1) + " = " + num(in.thresholds[i]);
    q += " (" + std::to_string(in.thresholds.size() + 1) +
         " bands, band b is d in [t_b, t_{b+1}) with d = max(0, N̂·L̂); a tie goes to the brighter band). "
         "Give band: the band of each face, 0 the darkest.";
    return q;
}

std::vector<std::string> ToonShading::answer_fields() {
    return {"band"};
}

}  // namespace cg
