#include "radiosity/form_factor_math.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace cg::ff {

using glm::dvec3;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double parallel_rectangles(double a, double b, double c) {
    const double X = a / c, Y = b / c;
    const double X2 = X * X, Y2 = Y * Y;
    const double s1 = std::sqrt(1 + Y2), s2 = std::sqrt(1 + X2);
    const double t = 0.5 * (std::log1p(X2) + std::log1p(Y2) - std::log1p(X2 + Y2)) +
                     X * s1 * std::atan(X / s1) + Y * s2 * std::atan(Y / s2) - X * std::atan(X) -
                     Y * std::atan(Y);
    return 2 / (kPi * X * Y) * t;
}

double perpendicular_rectangles(double l, double w, double h) {
    const double W = w / l, H = h / l;
    const double W2 = W * W, H2 = H * H, S = W2 + H2, r = std::sqrt(S);
    const double log_term = std::log1p(W2) + std::log1p(H2) - std::log1p(S) +
                            W2 * std::log(W2 * (1 + S) / ((1 + W2) * S)) +
                            H2 * std::log(H2 * (1 + S) / ((1 + H2) * S));
    return (W * std::atan(1 / W) + H * std::atan(1 / H) - r * std::atan(1 / r) + 0.25 * log_term) /
           (kPi * W);
}

double coaxial_discs(double r1, double r2, double h) {
    const double R1 = r1 / h, R2 = r2 / h;
    const double X = 1 + (1 + R2 * R2) / (R1 * R1);
    const double q = R2 / R1;
    // ½ (X − sqrt(X² − 4 q²)) = 2 q² / (X + sqrt(X² − 4 q²)): no cancellation for large X.
    return 2 * q * q / (X + std::sqrt(std::max(0.0, X * X - 4 * q * q)));
}

double point_to_disc(double r, double h) {
    return r * r / (h * h + r * r);
}

const char* case_name(Case c) {
    switch (c) {
        case Case::None:
            return "none";
        case Case::ParallelRectangles:
            return "parallel-rectangles";
        case Case::PerpendicularRectangles:
            return "perpendicular-rectangles";
        case Case::CoaxialDiscs:
            return "coaxial-discs";
        case Case::PointToDisc:
            return "point-to-disc";
    }
    return "none";
}

namespace {

bool near(const dvec3& a, const dvec3& b, double tol) {
    return glm::length(a - b) <= tol;
}
bool parallel_dirs(const dvec3& a, const dvec3& b) {
    return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))) <= 1e-9;
}
// Facing and coaxial: normals opposite, the centre of `to` straight above `from` along its
// normal. Returns the distance (0 when not).
double coaxial(const Patch& from, const Patch& to, double tol) {
    const dvec3 ni = normal(from), nj = normal(to);
    if (glm::dot(ni, nj) > -1 + 1e-12) return 0;
    const dvec3 d = centre(to) - centre(from);
    const double h = glm::dot(d, ni);
    if (!(h > tol)) return 0;
    if (glm::length(d - h * ni) > tol) return 0;
    return h;
}

}  // namespace

Analytic analytic(const Patch& from, const Patch& to) {
    Analytic out;
    const double scale = extent(from) + extent(to) + glm::length(centre(to) - centre(from));
    const double tol = 1e-9 * scale;
    using T = Patch::Type;
    auto finish = [&](Analytic a) {
        return std::isfinite(a.value) && std::isfinite(a.reverse) ? a : Analytic{};
    };
    if (from.type == T::Rectangle && to.type == T::Rectangle) {
        const double lu = glm::length(from.b), lv = glm::length(from.c);
        if (const double c = coaxial(from, to, tol); c > 0) {
            const double ju = glm::length(to.b), jv = glm::length(to.c);
            const bool same = parallel_dirs(from.b, to.b) && std::fabs(lu - ju) <= tol &&
                              std::fabs(lv - jv) <= tol;
            const bool swapped = parallel_dirs(from.b, to.c) && std::fabs(lu - jv) <= tol &&
                                 std::fabs(lv - ju) <= tol;
            if (same || swapped) {
                out.kase = Case::ParallelRectangles;
                out.params = {lu, lv, c};
                out.value = out.reverse = parallel_rectangles(lu, lv, c);
                return finish(out);
            }
            return out;
        }
        const dvec3 ni = normal(from), nj = normal(to);
        if (std::fabs(glm::dot(ni, nj)) > 1e-9) return out;
        if (!(glm::dot(ni, centre(to) - centre(from)) > tol) ||
            !(glm::dot(nj, centre(from) - centre(to)) > tol))
            return out;
        // The edges of each as (start, end, the other edge's length).
        struct Edge {
            dvec3 p, q;
            double other;
        };
        auto edges = [](const Patch& r) {
            const double lu = glm::length(r.b), lv = glm::length(r.c);
            return std::array<Edge, 4>{
                Edge{r.a, r.a + r.b, lv}, Edge{r.a + r.b, r.a + r.b + r.c, lu},
                Edge{r.a + r.b + r.c, r.a + r.c, lv}, Edge{r.a + r.c, r.a, lu}};
        };
        for (const Edge& e : edges(from))
            for (const Edge& g : edges(to))
                if ((near(e.p, g.p, tol) && near(e.q, g.q, tol)) ||
                    (near(e.p, g.q, tol) && near(e.q, g.p, tol))) {
                    const double l = glm::length(e.q - e.p);
                    out.kase = Case::PerpendicularRectangles;
                    out.params = {l, e.other, g.other};
                    out.value = perpendicular_rectangles(l, e.other, g.other);
                    out.reverse = perpendicular_rectangles(l, g.other, e.other);
                    return finish(out);
                }
        return out;
    }
    if (from.type == T::Disc && to.type == T::Disc) {
        if (const double h = coaxial(from, to, tol); h > 0) {
            out.kase = Case::CoaxialDiscs;
            out.params = {from.radius, to.radius, h};
            out.value = coaxial_discs(from.radius, to.radius, h);
            out.reverse = coaxial_discs(to.radius, from.radius, h);
            return finish(out);
        }
        return out;
    }
    if (from.type == T::Point && to.type == T::Disc) {
        if (const double h = coaxial(from, to, tol); h > 0) {
            out.kase = Case::PointToDisc;
            out.params = {to.radius, h, 0};
            out.value = point_to_disc(to.radius, h);
            out.reverse = 0;
            return finish(out);
        }
    }
    return out;
}

const char* face_name(int face) {
    static const char* kNames[] = {"top", "+x side", "−x side", "+y side", "−y side"};
    return kNames[face];
}

int face_cells(int resolution, int face) {
    return face == 0 ? resolution * resolution : resolution * resolution / 2;
}

double delta_top(double x, double y, double dA) {
    const double q = x * x + y * y + 1;
    return dA / (kPi * q * q);
}

double delta_side(double y, double z, double dA) {
    const double q = y * y + z * z + 1;
    return z * dA / (kPi * q * q);
}

void cell(int resolution, int face, int k, double& x, double& y, double& z, double& dF) {
    const double w = 2.0 / resolution, dA = w * w;
    const int i = k % resolution, j = k / resolution;
    const double a = -1 + (i + 0.5) * w;  // across the face, in (−1, 1)
    if (face == 0) {
        x = a, y = -1 + (j + 0.5) * w, z = 1;
        dF = delta_top(x, y, dA);
        return;
    }
    z = (j + 0.5) * w;  // up the side, in (0, 1)
    dF = delta_side(a, z, dA);
    switch (face) {
        case 1:
            x = 1, y = a;
            return;
        case 2:
            x = -1, y = -a;
            return;
        case 3:
            y = 1, x = -a;
            return;
        default:
            y = -1, x = a;
            return;
    }
}

std::vector<dvec3> hemicube_points(const Patch& from, int m) {
    if (m <= 1 || from.type == Patch::Type::Point) return {centre(from)};
    std::vector<dvec3> pts;
    pts.reserve(std::size_t(m) * m);
    for (int b = 0; b < m; ++b)
        for (int a = 0; a < m; ++a) pts.push_back(point_at(from, (a + 0.5) / m, (b + 0.5) / m));
    return pts;
}

int nearest(const Patch* targets, std::size_t count, const dvec3& o, const dvec3& d, double eps) {
    int best = -1;
    double best_t = 0;
    for (std::size_t t = 0; t < count; ++t)
        if (const auto h = hit(targets[t], o, d, eps); h && (best < 0 || *h < best_t))
            best = int(t), best_t = *h;
    return best;
}

double ray_eps(const Patch& a, const Patch& b) {
    const double scale = extent(a) + extent(b) + glm::length(centre(a) - centre(b));
    return 1e-12 * scale;
}

void hemicube_face(const Patch& from, const std::vector<dvec3>& points, const Patch* targets,
                   std::size_t count, int resolution, int face, double* sums,
                   std::vector<float>* coverage) {
    dvec3 t1, t2;
    tangents(from, t1, t2);
    const dvec3 n = normal(from);
    const double eps = count ? ray_eps(from, targets[0]) : 0;
    const int cells = face_cells(resolution, face);
    if (coverage) coverage->assign(std::size_t(cells), 0.0f);
    const double share = 1.0 / double(points.size());
    for (int k = 0; k < cells; ++k) {
        double x, y, z, dF;
        cell(resolution, face, k, x, y, z, dF);
        const dvec3 d = x * t1 + y * t2 + z * n;
        int seen0 = 0;
        for (const dvec3& p : points) {
            const int t = nearest(targets, count, p, d, eps);
            if (t < 0) continue;
            sums[t] += dF * share;
            seen0 += t == 0;
        }
        if (coverage) (*coverage)[std::size_t(k)] = float(seen0 * share);
    }
}

double hemicube(const Patch& from, const Patch& to, int resolution, int m) {
    const auto points = hemicube_points(from, m);
    double sum = 0;
    for (int f = 0; f < kFaces; ++f)
        hemicube_face(from, points, &to, 1, resolution, f, &sum, nullptr);
    return sum;
}

void mc_ray(const Patch& from, Rng& rng, dvec3& origin, dvec3& dir) {
    const double s = rng.uniform(0, 1), t = rng.uniform(0, 1);
    origin = point_at(from, s, t);
    const double u1 = rng.uniform(0, 1), u2 = rng.uniform(0, 1);
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    dvec3 t1, t2;
    tangents(from, t1, t2);
    dir = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + std::sqrt(1 - u1) * normal(from);
}

void mc_batch(const Patch& from, const Patch* targets, std::size_t count, long long rays, Rng& rng,
              long long* hits, double eps) {
    for (long long k = 0; k < rays; ++k) {
        dvec3 o, d;
        mc_ray(from, rng, o, d);
        const int t = nearest(targets, count, o, d, eps);
        if (t >= 0) ++hits[t];
    }
}

double monte_carlo(const Patch& from, const Patch& to, long long rays, std::uint64_t seed) {
    Rng rng(seed);
    long long hits = 0;
    mc_batch(from, &to, 1, rays, rng, &hits, ray_eps(from, to));
    return double(hits) / double(rays);
}

double std_error(double f, long long n) {
    return n > 0 ? std::sqrt(std::max(0.0, f * (1 - f)) / double(n)) : 0.0;
}

}  // namespace cg::ff
