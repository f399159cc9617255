// The projection pipeline: a point from model to world to view (a look-at frame) to clip
// coordinates (the perspective matrix), the perspective divide to NDC, and NDC to the viewport;
// segments are clipped against the near plane in homogeneous coordinates before the divide.
//
// Two conventions, chosen by the input:
//   course  the notes' view frame looks down +z: x right, y up, z into the scene (the one
//           left-handed frame in the project: world coordinates stay right-handed), and
//               P = [c/a 0 0 0; 0 c 0 0; 0 0 (f+n)/(f−n) −2fn/(f−n); 0 0 1 0],  w = z
//   opengl  the view frame looks down −z (right-handed, as glm::lookAt), and
//               P = [c/a 0 0 0; 0 c 0 0; 0 0 −(f+n)/(f−n) −2fn/(f−n); 0 0 −1 0],  w = −z
// with c = cot(θ/2) for the vertical field of view θ, a the aspect ratio width/height, n and f
// the near and far distances (0 < n < f). Both map depth n to z_ndc = −1 and depth f to +1; the
// two view frames differ only in the sign of z and the two matrices in the sign of their third
// column, so a world point gets the very same clip coordinates either way.
//
// Instead of θ and a, an asymmetric (off-axis) frustum may be given as glFrustum takes it: the
// near rectangle [l, r] × [b, t] (view x and y at depth n; l < r, b < t), n and f. Then
//   opengl  P = [2n/(r−l) 0 (r+l)/(r−l) 0; 0 2n/(t−b) (t+b)/(t−b) 0;
//                0 0 −(f+n)/(f−n) −2fn/(f−n); 0 0 −1 0]     (glFrustum, glm::frustum)
//   course  the same with the third column negated (the view z is the depth, not −depth):
//           [2n/(r−l) 0 −(r+l)/(r−l) 0; 0 2n/(t−b) −(t+b)/(t−b) 0; 0 0 (f+n)/(f−n) −2fn/(f−n);
//            0 0 1 0].
// With l = −r, b = −t, t = n tan(θ/2) and r = a t it is the symmetric matrix above.
//
// The look-at frame (both conventions): f̂ = (center − eye)/|center − eye| the view direction,
// r = f̂ × up / |f̂ × up| (right), u = r × f̂ (up); the view matrix has rows r, u and f̂ (course)
// or −f̂ (opengl), each with the translation −row · eye. Without eye/center/up the view matrix
// is the identity: the points are given in view coordinates.
//
// Clip coordinates (x, y, z, w) are inside the view volume when −w ≤ x, y, z ≤ w; the divide
// gives NDC (x/w, y/w, z/w), the cube [−1, 1]³ for points inside. A point with w ≤ 0 is at or
// behind the eye: dividing would put it on the wrong side (or at infinity), so it gets no NDC.
// That is why the near plane is clipped before the divide: a segment from A to B in clip space
// keeps the part where d = z + w ≥ 0 (d is proportional to depth − n), cut at
// t = d_A / (d_A − d_B); linear interpolation is exact in homogeneous coordinates. The other
// five planes can wait until after the divide, where the volume is a cube.
//
// NDC to the viewport: x_d = (x_ndc + 1)·W/2, y_d = (y_ndc + 1)·H/2 (pixels, origin
// bottom-left), when a viewport [W, H] is given.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct Perspective {
    enum class Convention : std::uint8_t { Course, OpenGL };

    struct Input {
        Convention convention = Convention::Course;
        double fov_y_deg = 90;  // vertical field of view, in (0°, 180°)
        double aspect = 1;      // width / height, > 0
        double near = 1, far = 10;  // 0 < near < far
        // The off-axis form (glFrustum) instead of fov_y_deg and aspect: the near rectangle in
        // view x and y at depth `near`, left < right, bottom < top.
        bool has_frustum = false;
        double left = -1, right = 1, bottom = -1, top = 1;
        bool look_at = false;   // eye, center, up given (else the view matrix is the identity)
        glm::dvec3 eye{0, 0, 0}, center{0, 0, 1}, up{0, 1, 0};
        bool has_model = false;
        glm::dmat4 model{1.0};  // world_from_model, affine (last row 0 0 0 1)
        std::vector<glm::dvec3> points;  // model coordinates
        std::vector<std::array<glm::dvec3, 2>> segments;  // for near-plane clipping
        bool has_viewport = false;
        glm::dvec2 viewport{0, 0};  // W, H in pixels, > 0
        bool operator==(const Input&) const = default;
    };

    enum class SegmentStatus : std::uint8_t { Inside, Clipped, Rejected };

    struct Segment {
        SegmentStatus status = SegmentStatus::Inside;
        std::array<glm::dvec4, 2> clip{};  // the endpoints in clip space, before clipping
        double t0 = 0, t1 = 1;             // the kept part, A + t (B − A) (Rejected: unused)
        std::array<glm::dvec4, 2> kept{};  // the kept part's endpoints in clip space
        std::array<glm::dvec3, 2> ndc{};   // ... and in NDC
        bool operator==(const Segment&) const = default;
    };

    struct Result {
        glm::dmat4 model{1.0};       // world_from_model
        glm::dmat4 view{1.0};        // view_from_world
        glm::dmat4 projection{1.0};  // clip_from_view: "matrix"
        glm::dmat4 mvp{1.0};         // clip_from_model = projection · view · model
        std::vector<glm::dvec3> world, eye_coords;  // the points in world and view coordinates
        std::vector<glm::dvec4> clip;
        std::vector<std::optional<glm::dvec3>> ndc;     // none when w ≤ 0
        std::vector<bool> inside;                       // −w ≤ x, y, z ≤ w (and w > 0)
        std::vector<std::optional<glm::dvec2>> device;  // with a viewport and an NDC point
        std::vector<Segment> segments;
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Model,
        View,
        Projection,
        PointView,
        PointClip,
        PointDivide,
        PointDevice,
        SegmentClip,
        SegmentDivide,
        Done
    };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::Model;
        Phase last = Phase::Model;
        int k = -1;  // the point worked last
        int j = -1;  // the segment worked last
        glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1}, eye{0, 0, 0};  // the view frame
        Result r;    // filled as the steps go
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s) { return s.r; }
    static Result result(State&& s) { return std::move(s.r); }
    static void draw(const State& s, Scene& scene);

    // Exam practice (perspective_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The whole pipeline as one straight-line function, for the benchmark's comparison.
    static Result project(const Input& in);

    // The matrices on their own (also used by validate and the tests).
    static glm::dmat4 projection_matrix(const Input& in);
    static glm::dmat4 view_matrix(const Input& in);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
