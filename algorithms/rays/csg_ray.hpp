// CSG on ray segments, step by step (csg-ray): the course's "intersect the ray with every
// primitive, then perform the boolean operations on the resulting line segments".
//
// Steps: one per leaf, children before their node (post-order) — the ray carried into the
// leaf's frame, its roots (a box: its three slabs) and the segments where it is inside, with
// why a tangent ray gives none —; one per internal node — both operand lists, the merge by the
// node's operation, the resulting list —; then the hit: the first end of the root's list with
// t > ε and the normal of the surface it came from (reversed when it came from a subtracted
// operand). The tree, the rules (strictly inside; touching segments join in a union, a touch in
// an intersection vanishes; ±∞ ends) and the transforms are those of rays/csg.hpp, whose plain
// csg_intersect() computes the same numbers in one call.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "rays/csg.hpp"

namespace cg {

struct CsgRay {
    struct Input {
        CsgTree tree;
        glm::dvec3 origin{0.0};     // E, world space
        glm::dvec3 direction{0.0};  // d, world space, ≠ 0, not necessarily unit
        bool operator==(const Input&) const = default;
    };
    // The hit, every node's list (post-order, the root's last) and the input they belong to.
    struct Result {
        Shared<Input> in;
        CsgHit hit;
        std::vector<CsgSpans> lists;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Nodes, Hit, Done };

    struct State {
        Shared<Input> in;
        Shared<PreparedCsg> prepared;  // the leaves' frames, computed once
        Phase phase = Phase::Nodes;
        int next = 0;                  // the node the next step computes (post-order)
        int last = -1;                 // the node the last step computed (-1: none, or the hit)
        std::vector<CsgSpans> lists;   // every node's list, as far as computed
        CsgHit hit;                    // filled by the last step
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);    // validate, then begin
    static State begin(Shared<Input> in);   // a fresh state for a valid input
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return {s.in, s.hit, s.lists}; }
    static Result result(State&& s) { return {s.in, std::move(s.hit), std::move(s.lists)}; }
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        std::size_t n = heap_bytes(s.lists);
        return n + s.hit.segments.capacity() * sizeof(CsgSpan);
    }

    // Exam practice (csg_ray_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The plain function: every list and the hit in one call (csg_intersect is the hit alone).
    static Result solve(Shared<Input> in);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

// A list as the course writes it: "[3, 7] ∪ [9, ∞)", "∅".
std::string csg_spans_text(const CsgSpans& spans);
// What a node is called in the narration and the result: its name, a leaf's "leaf k", or its
// path in the input.
std::string csg_node_label(const CsgNode& n);
// A leaf's solid as translucent faces for the 3D canvas (a quadric's mesh within its caps, or
// unbounded ones within ±reach; a box's six faces), placed by the transforms down to it.
void add_csg_leaf_mesh(const CsgTree& t, int node, double reach, Style style, float alpha,
                       std::vector<Face3>& faces);
// A primitive in words: "sphere r = 2 centred at (0, 0, -1)", "box [0, 1]×[0, 1]×[0, 1]".
std::string csg_primitive_text(const CsgNode& leaf);

}  // namespace cg
