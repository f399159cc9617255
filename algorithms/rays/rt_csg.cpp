#include "rays/rt_csg.hpp"

#include <cmath>

#include "core/format.hpp"
#include "core/step.hpp"
#include "rays/rt_scene.hpp"

namespace cg::rt {

std::size_t object_tests(const Object& o) {
    return o.kind == ObjectKind::Csg ? static_cast<std::size_t>(std::max(1, o.csg.leaves)) : 1;
}

void validate_csg_object(const Object& o) {
    validate_csg(o.csg);
    for (std::size_t k = 0; k < o.csg.nodes.size(); ++k) {
        const CsgNode& n = o.csg.nodes[k];
        if (!n.leaf) continue;
        const glm::dvec3 at(csg_world_from_leaf(o.csg, static_cast<int>(k))[3]);
        for (int i = 0; i < 3; ++i)
            if (std::fabs(at[i]) > kMaxCoordinate)
                throw InputError(n.path, "is placed at " + given(at) +
                                             ", beyond the scene's coordinate limit 1e12");
        if (n.kind == CsgPrimitive::Box) {
            check_coordinates(n.box.min, n.path + ".primitive.min");
            check_coordinates(n.box.max, n.path + ".primitive.max");
        }
    }
}

double intersect_csg(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
                     double t_min) {
    return csg_intersect_t(p, origin, direction, t_min);
}

glm::dvec3 csg_hit_normal(const PreparedCsg& p, glm::dvec3 origin, glm::dvec3 direction,
                          double t_min) {
    return csg_intersect(p, origin, direction, t_min).normal;
}

}  // namespace cg::rt
