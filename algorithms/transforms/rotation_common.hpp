// Shared by the 3D rotation algorithms (arbitrary axis, Euler angles, slerp): the three
// coordinate rotations, angles in degrees with exact values where a student expects them,
// matrices as rows / text / LaTeX, and the pictures' props (a small house, circles, arcs).
//
// Conventions (the project's): right-handed, column vectors p' = R p, a positive angle turns
// counter-clockwise when seen from the axis tip looking toward the origin:
//   R_x(θ) = [1 0 0; 0 c −s; 0 s c],  R_y(θ) = [c 0 s; 0 1 0; −s 0 c],  R_z(θ) = [c −s 0; s c 0; 0
//   0 1].
// glm matrices are indexed m[column][row]; every function here that says "rows" means rows.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cg::rot {

struct CosSin {
    double c = 1, s = 0;
    bool operator==(const CosSin&) const = default;
};

// cos and sin of an angle in degrees. The angle is reduced modulo 360 exactly (fmod), and
// multiples of 30° and 45° give the values a student writes (0, ±1/2, ±√2/2, ±√3/2, ±1) rather
// than cos(π/2) = 6.1e-17, so a 90° turn prints as 0s and 1s.
CosSin cos_sin_deg(double deg);
// The angle in (−180, 180], reduced exactly.
double wrap_deg(double deg);
double deg(double radians);
double rad(double degrees);

// The rotation about coordinate axis `axis` (0 = x, 1 = y, 2 = z) with the given cos and sin.
glm::dmat3 rotation(int axis, CosSin cs);
inline CosSin inverse(CosSin cs) {
    return {cs.c, -cs.s};
}
char axis_name(int axis);  // 'x', 'y', 'z'

// Rows of a 3×3 matrix, or of its 4×4 homogeneous extension (last row and column 0 0 0 1).
std::vector<std::vector<double>> rows3(const glm::dmat3& m);
std::vector<std::vector<double>> rows4(const glm::dmat3& m);
// "[1 0 0; 0 0 -1; 0 1 0]" and the LaTeX bmatrix; `homogeneous` shows the 4×4 form.
std::string matrix_text(const glm::dmat3& m, int digits = 4);
std::string matrix_tex(const glm::dmat3& m, bool homogeneous = false, int digits = 4);
std::string vector_tex(glm::dvec3 v, int digits = 4);  // a column
// Round-off below 1e-15 shown as 0 (narration only; the numbers computed are kept as they are).
double clean(double x);

// The largest |entry| of a − b.
double max_diff(const glm::dmat3& a, const glm::dmat3& b);

// ---- picture props ----

// A small house (box and gable roof) as faces, its local frame given by `right`, `up`, `front`
// (orthonormal, right-handed), centred at `centre`, `size` across. Walls, roof and the front
// (door) face get their own colours so the orientation reads at a glance.
struct HousePlacement {
    glm::dvec3 centre{0, 0, 0};
    glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, front{0, 0, 1};
    double size = 1.0;
};
// Draws the house as `transform` · (placed house). `ghost` draws it faint (where it was).
void draw_house(Scene& scene, const HousePlacement& h, const glm::dmat3& transform, bool ghost);
// Corners of the house in world coordinates before `transform` (for extents and tests).
std::vector<glm::dvec3> house_points(const HousePlacement& h);

// A circle of `radius` about `centre` in the plane perpendicular to `normal` (unit), as
// segments; `from`/`to` (degrees, measured from `start` — a unit vector in the plane) draw
// an arc instead.
void draw_circle(Scene& scene, glm::dvec3 centre, glm::dvec3 normal, double radius, Style style,
                 int segments = 48);
void draw_arc(Scene& scene, glm::dvec3 centre, glm::dvec3 normal, glm::dvec3 start, double radius,
              double from_deg, double to_deg, Style style, bool arrow, const std::string& label);

// Any unit vector perpendicular to unit `n` (deterministic: crossed with the axis n is
// least aligned with).
glm::dvec3 perpendicular(glm::dvec3 n);

}  // namespace cg::rot

namespace cg::rot {

// ---- Euler angles (shared by the Euler-angle and slerp lessons) ----
// `order` names the three rolls in the order they are applied: "xyz" rolls about x first, then
// y, then z, all about the fixed world axes, so with column vectors
//   R = R_z(θ3) R_y(θ2) R_x(θ1),  angles (θ1, θ2, θ3) in the order of the letters.
// The six orders use each axis once (Tait–Bryan angles).
bool valid_order(const std::string& order);
glm::dmat3 euler_matrix(const std::string& order, glm::dvec3 angles_deg);
// The angles (degrees, order "xyz") of a rotation matrix: θ2 ∈ [−90, 90], θ1, θ3 ∈ (−180, 180];
// at gimbal lock (cos θ2 = 0) θ1 is taken as 0.
glm::dvec3 euler_xyz_of(const glm::dmat3& m);

}  // namespace cg::rot
