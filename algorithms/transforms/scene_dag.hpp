// Hierarchical models: a scene DAG traversed depth first with a matrix stack.
//
// A model is a directed acyclic graph of named nodes. Each node carries a modelling transform
// M (given as translate / rotate / scale, applied as M = T R S, or as a 4×4 affine matrix), an
// optional shape (a unit cube [−½, ½]³ in the node's own coordinates) and a list of children.
// A node may be the child of several parents (the puppet's two arms share one "arm" node), so
// it is drawn once per path from the root, each time with that path's matrix:
//   world(root/a/b) = M_root · M_a · M_b   (column vectors: the leaf's matrix acts first).
//
// The traversal keeps a stack of matrices whose top is the current transform (I at the bottom):
//   visit(n):  push (copy the top);  top ← top · M_n;  if n has a shape: draw it with top;
//              visit each child in order;  pop.
// Each push, multiply, draw and pop is one step; the stack depth (pushes not yet popped)
// returns to 0 at the end.
//
// Refused: an unknown child name, a cycle (named), a missing root, a depth over 64 nodes, more
// than 1,000 node instances (paths from the root), a zero scale or a singular matrix (it
// flattens the node and everything under it and has no inverse, so the node's frame and its
// normals are lost), a non-affine matrix, a world matrix that overflows.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"

namespace cg {

struct SceneDag {
    static constexpr int kMaxDepth = 64;
    static constexpr int kMaxInstances = 1000;
    static constexpr int kMaxNodes = 1000;

    struct Node {
        std::string name;
        // Either the pieces (M = T R S; each optional) ...
        glm::dvec3 translate{0, 0, 0};
        glm::dvec3 axis{0, 0, 1};  // rotation axis (any length ≠ 0), used when has_rotate
        double angle_deg = 0;
        bool has_rotate = false;
        glm::dvec3 scale{1, 1, 1};
        // ... or a whole 4×4 affine matrix.
        bool has_matrix = false;
        glm::dmat4 matrix{1.0};
        bool box = false;                   // shape: a unit cube under the node's matrix
        std::vector<std::string> children;  // names, in drawing order
        bool operator==(const Node&) const = default;
    };
    struct Input {
        std::vector<Node> nodes;
        std::string root;
        bool operator==(const Input&) const = default;
    };

    struct Draw {
        std::string path;  // "torso/left_shoulder/arm"
        glm::dmat4 matrix{1.0};
        bool operator==(const Draw&) const = default;
    };
    struct Result {
        std::vector<Draw> draws;
        int max_depth = 0;
        int steps = 0;
        bool operator==(const Result&) const = default;
    };

    enum class Next : std::uint8_t { Push, Multiply, Draw, Children, Pop };
    enum class Event : std::uint8_t { None, Push, Multiply, Draw, Pop };

    struct Visit {
        int node = 0;
        int child = 0;  // the next child to visit
        Next next = Next::Push;
        bool operator==(const Visit&) const = default;
    };

    struct State {
        Input in;
        std::vector<glm::dmat4> local;          // M of each node
        std::vector<std::vector<int>> kids;     // children as indices
        int root = 0;
        std::vector<Visit> path;                // the DFS path (root first)
        std::vector<glm::dmat4> stack{glm::dmat4(1.0)};  // I at the bottom, top = current
        std::vector<Draw> draws;
        Event last = Event::None;
        int max_depth = 0;
        int steps = 0;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.path.empty(); }
    static Result result(const State& s);
    static Result result(State&& s);
    static void draw(const State& s, Scene& scene);

    // Exam practice (scene_dag_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The node's modelling matrix M = T R S (or its matrix).
    static glm::dmat4 local_matrix(const Node& n);
    // Every node instance (path from the root) with its world matrix, depth first — the same
    // traversal as one straight-line recursive function (for the benchmark and the picture).
    // `boxes_only` keeps only the instances that draw a shape: exactly the result's draws.
    static std::vector<Draw> expand(const Input& in, bool boxes_only);
    static Result traverse(const Input& in);
    // The eight corners of the unit cube [−½, ½]³ under m.
    static std::vector<glm::dvec3> corners(const glm::dmat4& m);
    static int depth(const State& s) { return static_cast<int>(s.stack.size()) - 1; }

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
