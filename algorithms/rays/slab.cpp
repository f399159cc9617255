#include "rays/slab.hpp"

#include <utility>

namespace cg {

SlabHit ray_slabs(const Box& b, glm::dvec3 origin, glm::dvec3 direction) {
    SlabHit h;
    bool empty = false;
    for (int i = 0; i < 3; ++i) {
        const double o = origin[i], d = direction[i];
        if (d == 0) {  // parallel to the slab: inside it everywhere or nowhere
            if (!(b.min[i] < o && o < b.max[i])) h.parallel_outside[i] = empty = true;
            continue;
        }
        double t0 = (b.min[i] - o) / d, t1 = (b.max[i] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        h.t0[i] = t0, h.t1[i] = t1;
        if (t0 > h.t_near) h.t_near = t0, h.axis_near = i;
        if (t1 < h.t_far) h.t_far = t1, h.axis_far = i;
    }
    h.hit = !empty && h.t_near < h.t_far;
    return h;
}

}  // namespace cg
