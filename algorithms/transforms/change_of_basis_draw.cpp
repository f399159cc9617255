// Change of basis, the picture (3D). The world frame faint at the origin; F1 and F2 as their axes
// at their origins, named as the course names them — v₁, v₂, v₃ from O_v and w₁, w₂, w₃ from
// O_w, in the axes' colours, the frame the current step works on solid and the other faint.
// The points where they are in the world, each named with its coordinates in the frame the
// step is about ("P0 = (3, 2, 0) in F1", then "P0 = (1, −1, 0) in F2"), and dashed
// construction lines: P reached from O_v along v₁, v₂, v₃ (the F1 step), and from O_w along
// w₁, w₂, w₃ (the step that maps it). Vectors are arrows from O_v, named the same way.
//
// The camera frames the frames, the points and the vectors. A 2D input (everything in z = 0,
// the third axes (0, 0, 1)) is seen face-on from +z, orthographic, with coordinates (x, y) and
// no third axes (they would point straight at the viewer): so a right angle looks right.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "transforms/change_of_basis.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using Frame = ChangeOfBasis::Frame;
using Phase = ChangeOfBasis::Phase;

// The world axes' colours (as the viewer draws a frame), for F1's and F2's axes.
constexpr std::uint32_t kAxisColour[3] = {0xd62728ff, 0x2ca02cff, 0x1f77b4ff};

double max_abs(dvec3 v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// Everything in z = 0 with both third axes along z: the course's 2D case.
bool is_planar(const ChangeOfBasis::Input& in, const std::vector<dvec3>& world) {
    auto flat = [](dvec3 p) { return std::fabs(p.z) <= 1e-12 * std::max(1.0, max_abs(p)); };
    for (const Frame* f : {&in.from, &in.to}) {
        if (!flat(f->origin) || !flat(f->axes[0]) || !flat(f->axes[1])) return false;
        if (f->axes[2].x != 0 || f->axes[2].y != 0) return false;
    }
    for (const dvec3& p : world)
        if (!flat(p)) return false;
    return true;
}

}  // namespace

void ChangeOfBasis::draw(const State& s, Scene& scene) {
    const Frame &f1 = s.in->from, &f2 = s.in->to;
    const Result& r = s.r;
    const bool started = s.phase != Phase::WorldFromF1;
    const dmat4 world_f1 = world_from(f1);
    std::vector<dvec3> world;  // the points and the vectors' tips, in the world
    for (const dvec3& p : s.in->points) world.push_back(dvec3(world_f1 * dvec4(p, 1.0)));
    for (const dvec3& u : s.in->vectors) world.push_back(dvec3(world_f1 * dvec4(u, 1.0)));
    const bool planar = is_planar(*s.in, world);
    // Coordinates as the course writes them: (x, y) in 2D.
    const auto coords = [&](dvec3 c) { return planar ? num(dvec2(c), 4) : num(c, 4); };

    // What the camera frames: the origin, both frames, the points and the vectors.
    dvec3 lo(0.0), hi(0.0);
    const auto frame = [&](dvec3 p) {
        if (std::isfinite(p.x + p.y + p.z)) lo = glm::min(lo, p), hi = glm::max(hi, p);
    };
    for (const dvec3& p : world) frame(p);

    const bool f1_active = started && (s.last == Phase::WorldFromF1 || s.last == Phase::Compose);
    const bool f2_active = started && s.last != Phase::WorldFromF1;
    scene.frames3.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0, "", 0.35f});
    const auto axes = [&](const Frame& f, const char* const names[3], bool active) {
        for (int i = 0; i < (planar ? 2 : 3); ++i) {
            Segment3 a{f.origin, f.origin + f.axes[i], names[i], {Role::Neutral, 2.5f}, true};
            a.style.rgba = (kAxisColour[i] & ~0xffu) | (active ? 0xffu : 0x73u);
            a.priority = active ? 0 : -1;
            scene.segments3.push_back(a);
            frame(a.b);
        }
        frame(f.origin);
    };
    static const char* const kV[3] = {"v₁", "v₂", "v₃"};
    static const char* const kW[3] = {"w₁", "w₂", "w₃"};
    axes(f1, kV, f1_active);
    axes(f2, kW, f2_active);
    scene.labels3.push_back({f1.origin, "O_v", {f1_active ? Role::Active : Role::Neutral}});
    scene.labels3.push_back({f2.origin, "O_w", {f2_active ? Role::Active : Role::Neutral}});
    if (lo.x < hi.x || lo.y < hi.y || lo.z < hi.z) add_focus(scene, lo, hi);
    if (planar) scene.view3 = {{0, 0, -1}, {0, 1, 0}, true};

    const Style f1_lines{Role::Construction, 1.5f, true};
    const Style f2_lines{Role::Active, 1.5f, true};
    // O → O + c₁a₁ → … → O + c₁a₁ + c₂a₂ + c₃a₃, skipping legs of length 0.
    const auto path = [&](const Frame& f, dvec3 c, const Style& style) {
        dvec3 at = f.origin;
        for (int i = 0; i < 3; ++i) {
            if (c[i] == 0) continue;
            const dvec3 next = at + c[i] * f.axes[i];
            scene.segments3.push_back({at, next, "", style, false});
            at = next;
        }
    };

    if (!started) return;
    const bool mapping_point = s.last == Phase::Points;
    const std::size_t current = mapping_point ? r.points.size() - 1 : r.points.size();
    for (std::size_t k = 0; k < r.world.size(); ++k) {
        const bool mapped = k < r.points.size(), now = mapping_point && k == current;
        const std::string label =
            "P" + std::to_string(k) + " = " +
            (mapped ? coords(r.points[k]) + " in F2" : coords(s.in->points[k]) + " in F1");
        scene.points3.push_back({r.world[k],
                                 label,
                                 {now      ? Role::Active
                                  : mapped ? Role::Kept
                                           : Role::Subject},
                                 5.0f,
                                 now || s.last == Phase::WorldFromF1 ? 1 : 0});
        if (s.last == Phase::WorldFromF1) path(f1, s.in->points[k], f1_lines);
        if (now) path(f2, r.points[k], f2_lines);
    }
    const bool mapping_vector = s.last == Phase::Vectors;
    for (std::size_t k = 0; k < s.in->vectors.size(); ++k) {
        const dvec3 u = dvec3(world_f1 * dvec4(s.in->vectors[k], 0.0));
        const bool mapped = k < r.vectors.size();
        const bool now = mapping_vector && k + 1 == r.vectors.size();
        const std::string label =
            "u" + std::to_string(k) + " = " +
            (mapped ? coords(r.vectors[k]) + " in F2" : coords(s.in->vectors[k]) + " in F1");
        scene.segments3.push_back({f1.origin,
                                   f1.origin + u,
                                   label,
                                   {now ? Role::Active : Role::Subject, 2.0f},
                                   true,
                                   0,
                                   now ? 1 : 0});
    }
}

}  // namespace cg
