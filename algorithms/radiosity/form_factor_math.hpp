// Form factors between patches, three ways: the analytic formulas where they exist, the hemicube
// and Monte Carlo ray casting. Reused by every radiosity algorithm.
//
//   F_ij = 1/A_i ∫_{A_i} ∫_{A_j} cos θ_i cos θ_j / (π r²) H_ij dA_j dA_i
//
// the fraction of the energy leaving patch i (diffusely) that arrives at patch j.
//
// Analytic (Howell's catalogue): parallel, directly opposed a × b rectangles at distance c
// (C-11); perpendicular rectangles sharing an edge of length l, widths w (from) and h (to)
// (C-14); coaxial parallel discs of radii r1, r2 at distance h; a differential element dA to a
// coaxial parallel disc, r² / (h² + r²).
//
// The hemicube: a unit half cube (top face at height 1 above the patch, side faces half as tall)
// on a point of patch i, its full face divided into R × R cells (each side R × R/2), cell area
// ΔA = (2/R)². The cell through which j is seen contributes the delta form factor
//   top cell at (x, y, 1):         ΔF = ΔA / (π (x² + y² + 1)²)
//   side cell at (±1, y, z) etc.:  ΔF = z ΔA / (π (y² + z² + 1)²)
// (the point-to-cell form factor). Projecting j onto the five faces is done cell by cell: the ray
// from the point through the cell's centre is tested against j (the pixel-centre convention: a
// cell is covered when its centre sees j). The sum over covered cells is F_dA→j, the form factor
// from that point. Averaged over an m × m grid of equal-area points of i (m = 1: the centre only,
// the classic single-hemicube approximation) it approximates F_ij.
//
// Monte Carlo: N rays, each from a uniform point of i in a cosine-distributed direction; the
// fraction that reach j (its front side) is an unbiased estimate N_ij / N_i of F_ij with standard
// error sqrt(F (1 − F) / N).
//
// Visibility: among a set of target patches a ray (or a hemicube cell) counts for the nearest
// one it meets (a z-buffer); with the single target j nothing occludes (H = 1).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "radiosity/patch.hpp"

namespace cg {

namespace ff {

// Howell C-11: parallel directly opposed rectangles a × b at distance c.
double parallel_rectangles(double a, double b, double c);
// Howell C-14: from a w × l rectangle to an h × l one sharing the edge l, at 90°.
double perpendicular_rectangles(double l, double w, double h);
// Coaxial parallel discs: from radius r1 to radius r2 at distance h.
double coaxial_discs(double r1, double r2, double h);
// A differential element to a coaxial parallel disc of radius r at distance h.
double point_to_disc(double r, double h);

enum class Case : std::uint8_t {
    None,
    ParallelRectangles,
    PerpendicularRectangles,
    CoaxialDiscs,
    PointToDisc
};
const char* case_name(Case c);  // "parallel-rectangles", ..., "none"

struct Analytic {
    Case kase = Case::None;
    double value = 0;                // F_ij (when kase != None)
    double reverse = 0;              // F_ji by the same formula (not for a point)
    std::array<double, 3> params{};  // (a, b, c) | (l, w, h) | (r1, r2, h) | (r, h, 0)
    bool operator==(const Analytic&) const = default;
};
// Which formula applies (detected geometrically, to 1e-9 of the patches' size) and its value.
Analytic analytic(const Patch& from, const Patch& to);

// The hemicube's faces: 0 top, 1 +x, 2 −x, 3 +y, 4 −y (x, y the from patch's tangents, z its
// normal).
constexpr int kFaces = 5;
const char* face_name(int face);
int face_cells(int resolution, int face);  // R² on top, R²/2 on a side
// The local centre (x, y, z) of cell k of a face and its delta form factor.
void cell(int resolution, int face, int k, double& x, double& y, double& z, double& dF);
double delta_top(double x, double y, double dA);
double delta_side(double y, double z, double dA);

// The points of i a hemicube stands on: the centre for m = 1, else the midpoints of an m × m
// grid of equal areas (one point for a differential element).
std::vector<glm::dvec3> hemicube_points(const Patch& from, int m);

// One face of the hemicube on every point, against `targets` (nearest hit wins): adds the mean
// over the points of the covered cells' ΔF to sums[t]; `coverage` (if given, face_cells long)
// receives per cell the fraction of points that see targets[0] through it.
void hemicube_face(const Patch& from, const std::vector<glm::dvec3>& points, const Patch* targets,
                   std::size_t count, int resolution, int face, double* sums,
                   std::vector<float>* coverage);
double hemicube(const Patch& from, const Patch& to, int resolution, int m);

// One ray of the Monte Carlo estimate: its origin and cosine-distributed direction.
void mc_ray(const Patch& from, Rng& rng, glm::dvec3& origin, glm::dvec3& dir);
// The index of the nearest target the ray reaches (front side), or -1.
int nearest(const Patch* targets, std::size_t count, const glm::dvec3& o, const glm::dvec3& d,
            double eps);
// `rays` rays: hits[t] += the rays reaching targets[t] first.
void mc_batch(const Patch& from, const Patch* targets, std::size_t count, long long rays, Rng& rng,
              long long* hits, double eps);
double monte_carlo(const Patch& from, const Patch& to, long long rays, std::uint64_t seed);
double std_error(double f, long long n);  // sqrt(F (1 − F) / N)

// The smallest t counted along a ray (a self-hit guard), from the patches' scale.
double ray_eps(const Patch& a, const Patch& b);

}  // namespace ff

}  // namespace cg
