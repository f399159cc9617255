// Back-face culling: drop the faces of a closed mesh that point away from the viewer.
//
// Faces are listed counter-clockwise as seen from outside the mesh, so the normal from Newell's
// method, N = Σ_i (y_i − y_{i+1})(z_i + z_{i+1}), (z_i − z_{i+1})(x_i + x_{i+1}),
// (x_i − x_{i+1})(y_i + y_{i+1}), points out of the solid. The view vector V runs from the eye
// TO the face (the course's convention): V = P_0 − eye with P_0 the face's first vertex under
// a perspective view, or V = the viewing direction under a parallel view. The course's test:
// cull the face when N·V > 0 (it faces away). N·V = 0 is a face seen edge-on: it is KEPT
// (it covers no area on screen, so keeping it costs nothing and never opens a hole).
//
// The decision uses Newell's N unnormalised (exact for integer coordinates); the result reports
// the unit normal and N̂·V. Culling alone is not hidden-surface removal: on a closed convex mesh
// it leaves exactly the visible faces, otherwise a z-buffer or painter's still has to run.
//
// Steps: one per face (its N, V, the sign of N·V, culled or kept); done.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct BackfaceCull {
    struct Input {
        std::vector<glm::dvec3> vertices;     // model points
        std::vector<std::vector<int>> faces;  // vertex indices, counter-clockwise from outside
        bool perspective = true;              // true: eye given; false: view_dir given
        glm::dvec3 eye{0, 0, 0};              // perspective: the eye point
        glm::dvec3 view_dir{0, 0, -1};        // parallel: the direction the viewer looks
        bool operator==(const Input&) const = default;
    };
    struct Result {
        std::vector<bool> culled;         // per face
        std::vector<glm::dvec3> normals;  // unit outward normals
        std::vector<double> dots;         // N̂·V per face
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Face, Finish, Done };

    struct State {
        Shared<Input> in;           // never changes during a run: copies of the state share it
        Phase phase = Phase::Face;  // the step to take next
        Phase last = Phase::Face;   // the step taken last
        int k = 0;                  // the next face; after a Face step, k − 1 was just decided
        glm::dvec3 n{0, 0, 0};      // the face just decided: Newell's N (unnormalised)
        glm::dvec3 v{0, 0, 0};      //   and its view vector V
        double ndotv = 0;           //   N·V with the unnormalised N (the sign decides)
        Result r;                   // filled face by face
        int culled = 0, kept = 0;
        bool operator==(const State&) const = default;
    };
    // The state's heap memory, for the timeline's memory budget (see Run::bytes).
    // The input is not counted: copies of a state share it (Shared<Input>).
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.r.culled) / 8 +
               heap_bytes(s.r.normals) + heap_bytes(s.r.dots);
    }

    static constexpr std::size_t kMaxVertices = 100'000;
    static constexpr std::size_t kMaxFaces = 100'000;

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State start(Shared<Input> in);  // the same, sharing an input already made
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    // run_to_end's: the spent state's per-face lists move out instead of being copied (the
    // copy was a third of the state machine's time on a 4,160-face mesh).
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);

    // Exam practice (backface_cull_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same algorithm as one straight-line function, for the benchmark's comparison.
    static Result cull(const Input& in);

    // Newell's normal of face f (unnormalised; its length is twice the face's area).
    static glm::dvec3 newell(const Input& in, const std::vector<int>& f);
    // The view vector of face f: P_0 − eye, or the view direction.
    static glm::dvec3 view_vector(const Input& in, const std::vector<int>& f);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
