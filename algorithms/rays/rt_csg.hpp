// CSG objects in the ray tracer: a scene object {"type": "csg", "tree": NODE, "material"} is a
// CSG tree (rays/csg.hpp) traced as one solid of one material. Its hit for a ray is the first
// end of the root's segment list beyond t_min (csg_intersect_t), its normal that end's surface
// normal (reversed for a subtracted operand); shadow rays test it the same way, so light passes
// through the hollows a difference cuts. Its cost in the tracer's limits is its number of leaves
// (one ray-primitive test each).
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>

#include "rays/csg.hpp"

namespace cg::rt {

struct Object;

// The ray-object tests one ray costs against this object: a CSG tree's leaves, else 1.
std::size_t object_tests(const Object& o);

// Throws InputError naming the field (the tree's paths start at the object's, such as
// "objects[2].tree.left.primitive.params.r"): validate_csg, and coordinates (every leaf's
// placement and a box's corners) within ±1e12.
void validate_csg_object(const Object& o);

// The nearest hit's t beyond t_min (+∞: none), and the unit normal there (out of the solid; the
// caller turns it to face the ray).
double intersect_csg(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
                     double t_min);
glm::dvec3 csg_hit_normal(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
                          double t_min);

}  // namespace cg::rt
