// Photon mapping: emission and tracing, the kd-tree, the k nearest photons and the estimate.
#include "gi/photon_map.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/format.hpp"
#include "rays/quadric.hpp"

namespace cg {

using glm::dvec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

void check_point(const dvec3& p, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(p[i]) || std::fabs(p[i]) > PhotonMap::kMaxCoordinate)
            throw InputError(field + "[" + std::to_string(i) + "]",
                             "must be within ±1e6 (got " + given(p[i]) + ")");
}

void check_direction(const dvec3& v, const std::string& field) {
    check_point(v, field);
    if (v == dvec3(0.0)) throw InputError(field, "must not be the zero vector");
}

void check_range(double v, double lo, double hi, const std::string& field, const char* why) {
    if (!(v >= lo && v <= hi)) throw InputError(field, std::string(why) + " (got " + given(v) + ")");
}

std::string at(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
}

// Two unit vectors completing the unit n to a right-handed frame.
void frame(dvec3 n, dvec3& t1, dvec3& t2) {
    const dvec3 a = std::fabs(n.x) < 0.5 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    t1 = unit(glm::cross(n, a));
    t2 = glm::cross(n, t1);
}

// A direction about the unit axis with cos θ = 1 − ξ₁ (1 − cos α), φ = 2π ξ₂: uniform over the
// cone of half-angle α (the whole sphere at α = 180°).
dvec3 cone_direction(dvec3 axis, double one_minus_cos_alpha, Rng& rng) {
    const double c = 1 - rng.uniform(0, 1) * one_minus_cos_alpha;
    const double s = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * kPi * rng.uniform(0, 1);
    dvec3 t1, t2;
    frame(axis, t1, t2);
    return unit(s * std::cos(phi) * t1 + s * std::sin(phi) * t2 + c * axis);
}

// A cosine-distributed direction about the unit n (a diffuse bounce): r = √ξ₁, φ = 2π ξ₂.
dvec3 cosine_direction(dvec3 n, Rng& rng) {
    const double u = rng.uniform(0, 1), r = std::sqrt(u), phi = 2 * kPi * rng.uniform(0, 1);
    dvec3 t1, t2;
    frame(n, t1, t2);
    return unit(r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + std::sqrt(1 - u) * n);
}

// 1 − cos α = 2 sin²(α/2), written so that a narrow cone keeps its digits.
double one_minus_cos(const PhotonMap::Light& l) {
    const double s = std::sin(l.cone_deg * kPi / 360);
    return l.cone_deg >= 180 ? 2.0 : 2 * s * s;
}

}  // namespace

// ---- [validate and start] -------------------------------------------------------------------

void PhotonMap::validate(const Input& in) {
    if (in.objects.empty()) throw InputError("objects", "must have at least 1 object (got none)");
    if (in.objects.size() > kMaxObjects)
        throw InputError("objects", "must have at most 32 objects (got " +
                                        std::to_string(in.objects.size()) + ")");
    for (std::size_t i = 0; i < in.objects.size(); ++i) {
        const Object& o = in.objects[i];
        const std::string f = at("objects", i);
        if (o.shape == Shape::Sphere) {
            check_point(o.center, f + ".center");
            check_range(o.radius, 1e-6, 1e6, f + ".radius", "must be 1e-6 to 1e6");
        } else {
            check_point(o.center, f + ".point");
            check_direction(o.normal, f + ".normal");
        }
        check_range(o.albedo, 0, 1, f + ".albedo", "must be 0 to 1");
        check_range(o.ior, 1, 3, f + ".ior", "must be 1 to 3");
    }
    if (in.lights.empty()) throw InputError("lights", "must have at least 1 light (got none)");
    if (in.lights.size() > kMaxLights)
        throw InputError("lights", "must have at most 8 lights (got " +
                                       std::to_string(in.lights.size()) + ")");
    for (std::size_t i = 0; i < in.lights.size(); ++i) {
        const Light& l = in.lights[i];
        const std::string f = at("lights", i);
        check_point(l.position, f + ".position");
        if (!(l.power > 0 && l.power <= 1e12))
            throw InputError(f + ".power", "must be > 0 and at most 1e12 (got " + given(l.power) + ")");
        check_direction(l.direction, f + ".direction");
        if (!(l.cone_deg >= 1e-4 && l.cone_deg <= 180))
            throw InputError(f + ".cone_deg", "must be 1e-4 to 180 degrees (got " + given(l.cone_deg) + ")");
    }
    if (in.photons < 1 || in.photons > kMaxPhotons)
        throw InputError("photons", "must be 1 to 1000000 (got " + std::to_string(in.photons) + ")");
    if (in.max_bounces < 1 || in.max_bounces > kMaxBounces)
        throw InputError("max_bounces", "must be 1 to 64 (got " + std::to_string(in.max_bounces) + ")");
    check_point(in.query, "query");
    if (in.k < 1 || in.k > kMaxK)
        throw InputError("k", "must be 1 to 10000 (got " + std::to_string(in.k) + ")");
}

PhotonMap::World PhotonMap::prepare(const Input& in) {
    rt::Scene sc;
    sc.materials.push_back(rt::Material{});
    double extent = 1;
    for (const Object& o : in.objects) {
        rt::Object r;
        if (o.shape == Shape::Sphere) {
            r.kind = rt::ObjectKind::Quadric;
            r.quadric.kind = QuadricKind::Sphere;
            r.quadric.r = o.radius;
            r.quadric.world_from_model = glm::translate(glm::dmat4(1.0), o.center);
            extent = std::max(extent, glm::length(o.center) + o.radius);
        } else {
            r.kind = rt::ObjectKind::Plane;
            r.p0 = o.center;
            r.normal = o.normal;
            extent = std::max(extent, glm::length(o.center));
        }
        sc.objects.push_back(r);
    }
    for (const Light& l : in.lights) extent = std::max(extent, glm::length(l.position));
    extent = std::max(extent, glm::length(in.query));
    World w;
    w.prepared = rt::prepare(sc);
    w.extent = extent;
    const int n = int(in.lights.size());
    for (int i = 0; i < n; ++i) w.emitted_by.push_back(in.photons / n + (i < in.photons % n ? 1 : 0));
    // The surface nearest the query point gives the normal of the direct-lighting reference.
    double best = Quadric::kInf;
    for (const Object& o : in.objects) {
        double d;
        dvec3 n3;
        if (o.shape == Shape::Sphere) {
            d = std::fabs(glm::length(in.query - o.center) - o.radius);
            n3 = unit(in.query - o.center);
        } else {
            n3 = unit(o.normal);
            d = std::fabs(glm::dot(in.query - o.center, n3));
        }
        if (d < best && n3 != dvec3(0.0)) best = d, w.query_normal = n3;
    }
    return w;
}

PhotonMap::State PhotonMap::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.world = Shared<World>(prepare(in));
    s.rng = Rng(in.seed);
    s.photons.reserve(std::size_t(in.photons));
    return s;
}

// ---- [the pieces] ---------------------------------------------------------------------------

int PhotonMap::light_of(const World& w, int photon) {
    int l = 0;
    while (l + 1 < int(w.emitted_by.size()) && photon >= w.emitted_by[l]) photon -= w.emitted_by[l++];
    return l;
}

PhotonMap::Event PhotonMap::trace_photon(const Input& in, const World& w, int light, double power,
                                         Rng& rng, std::vector<Photon>& photons, Path* path) {
    const Light& L = in.lights[std::size_t(light)];
    dvec3 origin = L.position;
    dvec3 d = cone_direction(unit(L.direction), one_minus_cos(L), rng);
    if (path) {
        path->light = light, path->origin = origin, path->power = power;
        path->bounces.clear(), path->stored = 0;
    }
    bool specular = false, diffuse = false;
    auto record = [&](Event e, dvec3 p, int object, double xi = 0, double P = 0) {
        if (path) path->bounces.push_back({e, p, object, xi, P});
        return e;
    };
    for (int bounce = 0;; ++bounce) {
        if (bounce == in.max_bounces) return record(Event::Limit, origin, -1);
        const rt::Hit h = rt::nearest_hit(w.prepared, origin, d);
        if (h.object < 0) return record(Event::Escape, origin + 2 * w.extent * d, -1);
        const Object& o = in.objects[std::size_t(h.object)];
        if (o.material == Material::Mirror) {
            const rt::SecondaryRay r = rt::mirror_ray(w.prepared, h, d);
            origin = r.origin, d = r.direction, specular = true;
            record(Event::Reflect, h.point, h.object);
        } else if (o.material == Material::Glass) {
            const rt::SecondaryRay r = rt::transmitted_ray(w.prepared, h, d, o.ior);
            origin = r.origin, d = r.direction, specular = true;
            record(r.total_internal ? Event::TotalInternal : Event::Refract, h.point, h.object);
        } else {
            photons.push_back({h.point, d, power, light, specular && !diffuse});
            if (path) ++path->stored;
            diffuse = true;
            // Russian roulette: survive with probability P = ρ, the power kept (Φ ρ / P = Φ).
            const double xi = rng.uniform(0, 1), P = o.albedo;
            if (!(xi < P)) return record(Event::Absorb, h.point, h.object, xi, P);
            record(Event::Survive, h.point, h.object, xi, P);
            d = cosine_direction(h.normal, rng);
            origin = rt::offset_point(w.prepared, h.point, h.normal);
        }
    }
}

PhotonMap::Node PhotonMap::split(const std::vector<Photon>& ph, std::vector<int>& order, int lo,
                                 int hi) {
    Node n;
    n.lo = lo, n.hi = hi, n.m = (lo + hi) / 2;
    n.box_lo = n.box_hi = ph[std::size_t(order[std::size_t(lo)])].position;
    for (int i = lo + 1; i < hi; ++i) {
        const dvec3& p = ph[std::size_t(order[std::size_t(i)])].position;
        n.box_lo = glm::min(n.box_lo, p), n.box_hi = glm::max(n.box_hi, p);
    }
    const dvec3 size = n.box_hi - n.box_lo;
    n.axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const int a = n.axis;
    std::nth_element(order.begin() + lo, order.begin() + n.m, order.begin() + hi,
                     [&](int i, int j) {
                         const double ci = ph[std::size_t(i)].position[a];
                         const double cj = ph[std::size_t(j)].position[a];
                         return ci < cj || (ci == cj && i < j);
                     });
    n.split = ph[std::size_t(order[std::size_t(n.m)])].position[a];
    return n;
}

double PhotonMap::distance2(dvec3 a, dvec3 b) {
    const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
    return dx * dx + dy * dy + dz * dz;
}

bool PhotonMap::offer(std::vector<Neighbour>& heap, int k, Neighbour n) {
    if (int(heap.size()) < k) {
        heap.push_back(n);
        std::push_heap(heap.begin(), heap.end());
        return true;
    }
    if (!(n < heap.front())) return false;
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = n;
    std::push_heap(heap.begin(), heap.end());
    return true;
}

std::vector<int> PhotonMap::nearest_brute_force(const std::vector<Photon>& ph, dvec3 x, int k) {
    std::vector<Neighbour> all;
    all.reserve(ph.size());
    for (std::size_t i = 0; i < ph.size(); ++i) all.push_back({distance2(x, ph[i].position), int(i)});
    const std::size_t n = std::min(all.size(), std::size_t(std::max(k, 0)));
    std::partial_sort(all.begin(), all.begin() + std::ptrdiff_t(n), all.end());
    std::vector<int> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(all[i].photon);
    return out;
}

double PhotonMap::direct_irradiance(const Input& in, const World& w, dvec3 x) {
    double e = 0;
    for (const Light& l : in.lights) {
        const dvec3 to = l.position - x;
        const double d2 = glm::dot(to, to);
        if (!(d2 > 0)) continue;
        const dvec3 dir = unit(to);
        const double omc = one_minus_cos(l);
        if (l.cone_deg < 180 && glm::dot(-dir, unit(l.direction)) < 1 - omc) continue;  // outside the cone
        const dvec3 from = x + w.prepared.epsilon * dir;
        if (rt::blocked(w.prepared, from, to, 0, 1 - 1e-9)) continue;
        const double omega = 2 * kPi * omc;
        e += l.power / omega * std::fabs(glm::dot(dir, w.query_normal)) / d2;
    }
    return e;
}

// ---- [the state machine] --------------------------------------------------------------------

void PhotonMap::advance(State& s) {
    const Input& in = *s.in;
    const World& w = *s.world;
    if (s.phase == Phase::Done) return;  // a finished machine stays as it is
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Emit: {
            // The first kOneByOne photons one at a time, then batches.
            const int rest = in.photons - kOneByOne;
            const int batch = rest > 0 ? (rest + kBatches - 1) / kBatches : 1;
            const int n = s.emitted < kOneByOne ? 1 : std::min(batch, in.photons - s.emitted);
            s.batch_first = s.emitted;
            for (int i = 0; i < n; ++i, ++s.emitted) {
                const int l = light_of(w, s.emitted);
                const double power = in.lights[std::size_t(l)].power / w.emitted_by[std::size_t(l)];
                const bool last = i + 1 == n;
                const Event e = trace_photon(in, w, l, power, s.rng, s.photons, last ? &s.path : nullptr);
                if (last) s.path.photon = s.emitted;
                s.escaped += e == Event::Escape, s.absorbed += e == Event::Absorb;
                s.limited += e == Event::Limit;
            }
            if (s.emitted == in.photons) {
                s.phase = Phase::Build;
                const int np = int(s.photons.size());
                s.order.resize(std::size_t(np));
                for (int i = 0; i < np; ++i) s.order[std::size_t(i)] = i;
                s.axis.assign(std::size_t(np), 0);
                if (np > 0) s.todo.push_back({0, np, 0});
                else s.phase = Phase::Query;
            }
            break;
        }
        case Phase::Build: {
            const Range r = s.todo.back();
            s.todo.pop_back();
            s.node = split(s.photons, s.order, r.lo, r.hi);
            s.axis[std::size_t(s.node.m)] = std::uint8_t(s.node.axis);
            s.depth = std::max(s.depth, int(r.bound) + 1);  // bound holds the node's level here
            // Depth first: the left range is split next.
            if (s.node.m + 1 < r.hi) s.todo.push_back({s.node.m + 1, r.hi, r.bound + 1});
            if (r.lo < s.node.m) s.todo.push_back({r.lo, s.node.m, r.bound + 1});
            if (s.todo.empty()) {
                s.phase = Phase::Query;
                s.k = std::min(in.k, int(s.photons.size()));
                if (s.k > 0) s.todo.push_back({0, int(s.photons.size()), 0});
                s.heap.reserve(std::size_t(s.k));
            }
            if (s.todo.empty()) s.phase = Phase::Estimate;
            break;
        }
        case Phase::Query: {
            if (s.todo.empty()) {  // nothing stored: straight to the estimate
                s.phase = Phase::Estimate;
                s.last = Phase::Estimate;
                advance(s);
                return;
            }
            s.range = s.todo.back();
            s.todo.pop_back();
            const bool full = int(s.heap.size()) == s.k;
            if (full && s.range.bound > s.heap.front().d2) {
                s.at = -1;
                ++s.pruned;
            } else {
                const int m = (s.range.lo + s.range.hi) / 2, p = s.order[std::size_t(m)];
                const int a = s.axis[std::size_t(m)];
                s.at = p;
                s.d2 = distance2(in.query, s.photons[std::size_t(p)].position);
                s.taken = offer(s.heap, s.k, {s.d2, p});
                s.replaced = full && s.taken;
                ++s.visited;
                const double diff = in.query[a] - s.photons[std::size_t(p)].position[a];
                const Range left{s.range.lo, m, 0}, right{m + 1, s.range.hi, 0};
                Range near = diff < 0 ? left : right, far = diff < 0 ? right : left;
                far.bound = diff * diff, near.bound = s.range.bound;
                if (far.lo < far.hi) s.todo.push_back(far);
                if (near.lo < near.hi) s.todo.push_back(near);
            }
            if (int(s.heap.size()) == s.k) s.r2 = s.heap.front().d2;
            if (s.todo.empty()) s.phase = Phase::Estimate;
            break;
        }
        case Phase::Estimate: {
            s.sum_power = 0;
            std::vector<Neighbour> sorted = s.heap;
            std::sort(sorted.begin(), sorted.end());
            for (const Neighbour& n : sorted) s.sum_power += s.photons[std::size_t(n.photon)].power;
            s.r2 = s.heap.empty() ? 0 : s.heap.front().d2;
            s.degenerate = !(s.r2 > 0);
            s.irradiance = s.degenerate ? 0 : s.sum_power / (kPi * s.r2);
            if (!std::isfinite(s.irradiance)) s.irradiance = 0, s.degenerate = true;
            s.phase = Phase::Done;
            break;
        }
        case Phase::Done: break;
    }
}

void PhotonMap::step(State& s, StepInfo* info) {
    advance(s);
    if (info) narrate(s, *info);
}

PhotonMap::Result PhotonMap::result(const State& s) {
    const Input& in = *s.in;
    const World& w = *s.world;
    Result r;
    for (std::size_t l = 0; l < in.lights.size(); ++l) {
        r.emitted.push_back(w.emitted_by[l]);
        r.power_per_photon.push_back(in.lights[l].power / w.emitted_by[l]);
    }
    r.photons = s.photons;
    for (const Photon& p : s.photons) r.caustic += p.caustic;
    r.escaped = s.escaped, r.absorbed = s.absorbed, r.limited = s.limited;
    r.order = s.order, r.axis = s.axis, r.depth = s.depth;
    std::vector<Neighbour> sorted = s.heap;
    std::sort(sorted.begin(), sorted.end());
    for (const Neighbour& n : sorted) {
        r.neighbours.push_back(n.photon);
        r.distances.push_back(std::sqrt(n.d2));
    }
    r.visited = s.visited, r.pruned = s.pruned;
    r.radius = std::sqrt(s.r2);
    r.sum_power = s.sum_power;
    r.irradiance = s.irradiance;
    r.degenerate = s.degenerate;
    r.direct_irradiance = direct_irradiance(in, w, in.query);
    return r;
}

std::size_t PhotonMap::bytes(const State& s) {
    return heap_bytes(s.photons) + heap_bytes(s.order) + heap_bytes(s.axis) + heap_bytes(s.todo) +
           heap_bytes(s.heap) + heap_bytes(s.path.bounces);
}

// ---- [the plain function] -------------------------------------------------------------------

namespace {

void build(const std::vector<PhotonMap::Photon>& ph, std::vector<int>& order,
           std::vector<std::uint8_t>& axis, int lo, int hi, int level, int& depth) {
    if (lo >= hi) return;
    const PhotonMap::Node n = PhotonMap::split(ph, order, lo, hi);
    axis[std::size_t(n.m)] = std::uint8_t(n.axis);
    depth = std::max(depth, level + 1);
    build(ph, order, axis, lo, n.m, level + 1, depth);
    build(ph, order, axis, n.m + 1, hi, level + 1, depth);
}

struct Search {
    const std::vector<PhotonMap::Photon>& ph;
    const std::vector<int>& order;
    const std::vector<std::uint8_t>& axis;
    glm::dvec3 x;
    int k;
    std::vector<PhotonMap::Neighbour> heap;
    int visited = 0, pruned = 0;

    // The same order as the state machine: the near side first, the far side when its plane is
    // not beyond r².
    void visit(int lo, int hi, double bound) {
        if (int(heap.size()) == k && bound > heap.front().d2) {
            ++pruned;
            return;
        }
        const int m = (lo + hi) / 2, p = order[std::size_t(m)], a = axis[std::size_t(m)];
        PhotonMap::offer(heap, k, {PhotonMap::distance2(x, ph[std::size_t(p)].position), p});
        ++visited;
        const double diff = x[a] - ph[std::size_t(p)].position[a];
        if (diff < 0) {
            if (lo < m) visit(lo, m, bound);
            if (m + 1 < hi) visit(m + 1, hi, diff * diff);
        } else {
            if (m + 1 < hi) visit(m + 1, hi, bound);
            if (lo < m) visit(lo, m, diff * diff);
        }
    }
};

}  // namespace

int PhotonMap::build_tree(const std::vector<Photon>& ph, std::vector<int>& order,
                          std::vector<std::uint8_t>& axis) {
    const int np = int(ph.size());
    order.resize(std::size_t(np));
    for (int i = 0; i < np; ++i) order[std::size_t(i)] = i;
    axis.assign(std::size_t(np), 0);
    int depth = 0;
    build(ph, order, axis, 0, np, 0, depth);
    return depth;
}

std::vector<PhotonMap::Neighbour> PhotonMap::nearest(const std::vector<Photon>& ph,
                                                     const std::vector<int>& order,
                                                     const std::vector<std::uint8_t>& axis,
                                                     glm::dvec3 x, int k, int* visited,
                                                     int* pruned) {
    k = std::min(k, int(ph.size()));
    Search search{ph, order, axis, x, k, {}};
    search.heap.reserve(std::size_t(std::max(k, 0)));
    if (k > 0) search.visit(0, int(ph.size()), 0);
    if (visited) *visited = search.visited;
    if (pruned) *pruned = search.pruned;
    std::sort(search.heap.begin(), search.heap.end());
    return std::move(search.heap);
}

PhotonMap::Result PhotonMap::compute(const Input& in) {
    validate(in);
    const World w = prepare(in);
    Rng rng(in.seed);
    Result r;
    r.photons.reserve(std::size_t(in.photons));
    for (std::size_t l = 0; l < in.lights.size(); ++l) {
        const double power = in.lights[l].power / w.emitted_by[l];
        r.emitted.push_back(w.emitted_by[l]);
        r.power_per_photon.push_back(power);
        for (int i = 0; i < w.emitted_by[l]; ++i) {
            const Event e = trace_photon(in, w, int(l), power, rng, r.photons, nullptr);
            r.escaped += e == Event::Escape, r.absorbed += e == Event::Absorb;
            r.limited += e == Event::Limit;
        }
    }
    for (const Photon& p : r.photons) r.caustic += p.caustic;
    r.depth = build_tree(r.photons, r.order, r.axis);
    const std::vector<Neighbour> near =
        nearest(r.photons, r.order, r.axis, in.query, in.k, &r.visited, &r.pruned);
    for (const Neighbour& n : near) {
        r.neighbours.push_back(n.photon);
        r.distances.push_back(std::sqrt(n.d2));
        r.sum_power += r.photons[std::size_t(n.photon)].power;
    }
    const double r2 = near.empty() ? 0 : near.back().d2;
    r.radius = std::sqrt(r2);
    r.degenerate = !(r2 > 0);
    r.irradiance = r.degenerate ? 0 : r.sum_power / (kPi * r2);
    if (!std::isfinite(r.irradiance)) r.irradiance = 0, r.degenerate = true;
    r.direct_irradiance = direct_irradiance(in, w, in.query);
    return r;
}

}  // namespace cg
