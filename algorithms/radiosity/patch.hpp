// Patches for radiosity: flat, one-sided emitters and receivers (rectangles, discs, triangles,
// and the differential "point" element), their area, unit normal, area-preserving sample points
// and ray intersection. Reused by every radiosity algorithm.
//
// Conventions: a rectangle is a corner and two perpendicular edges u, v; its normal is
// u × v / |u × v| (right-handed: counter-clockwise seen from the front). A disc is a centre, a
// normal (any length) and a radius. A triangle is three points p0 p1 p2, normal
// (p1 − p0) × (p2 − p0) normalised. A point is a differential area element dA at a centre with a
// normal: area 0, usable only as the patch a form factor starts from. Patches are one-sided:
// light leaves from the front (the normal's side) and is received on the front; a ray reaching
// a patch's back counts as a miss.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace cg {

struct Patch {
    enum class Type : std::uint8_t { Rectangle, Disc, Triangle, Point };
    Type type = Type::Rectangle;
    glm::dvec3 a{0, 0, 0};  // rectangle corner, disc/point centre, triangle p0
    glm::dvec3 b{1, 0, 0};  // rectangle edge_u, disc/point normal, triangle p1
    glm::dvec3 c{0, 1, 0};  // rectangle edge_v, triangle p2 (unused for discs and points)
    double radius = 0;      // discs
    bool operator==(const Patch&) const = default;

    static Patch rectangle(glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v);
    static Patch disc(glm::dvec3 centre, glm::dvec3 normal, double radius);
    static Patch triangle(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2);
    static Patch point(glm::dvec3 centre, glm::dvec3 normal);
};

const char* type_name(Patch::Type t);

double area(const Patch& p);
glm::dvec3 normal(const Patch& p);  // unit
glm::dvec3 centre(const Patch& p);  // the centroid
// A largest extent (for scales and tolerances): the longest edge or the diameter.
double extent(const Patch& p);
// An area-preserving map of the unit square onto the patch: uniform (s, t) give uniform points.
glm::dvec3 point_at(const Patch& p, double s, double t);
// Two unit tangents (t1, t2) with t1 × t2 = n: for a rectangle t1 ∥ u, for a triangle ∥ p1 − p0.
void tangents(const Patch& p, glm::dvec3& t1, glm::dvec3& t2);

// The distance t > 0 along o + t d (d need not be unit) at which the ray meets the patch's front
// side, if it does. `eps` is the smallest t counted (self-hits at the origin are not).
std::optional<double> hit(const Patch& p, const glm::dvec3& o, const glm::dvec3& d,
                          double eps = 1e-12);

// Checks a patch (finite, bounded coordinates, non-zero area or normal, perpendicular edges),
// throwing InputError naming `field` ("from", "enclosure[2]"); `allow_point` for the start patch.
void validate_patch(const Patch& p, const std::string& field, bool allow_point);

}  // namespace cg
