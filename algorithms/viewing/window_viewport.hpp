// Window-to-viewport mapping through normalised device coordinates (NDC).
//
// The window is the rectangle of the world we want to see, [xw_min, xw_max] × [yw_min, yw_max];
// the viewport is the rectangle of the device that shows it, [xv_min, xv_max] × [yv_min,
// yv_max]. Each map is a scale and a translation per axis, written as a 3×3 homogeneous
// matrix acting on column vectors (p' = M p, p = (x, y, 1)), so maps compose right to left:
//
//   ndc_from_window:  x_ndc = 2 (x − xw_min)/Lw − 1        [ 2/Lw   0     −(xw_max + xw_min)/Lw ]
//                     y_ndc = 2 (y − yw_min)/Hw − 1        [ 0      2/Hw  −(yw_max + yw_min)/Hw ]
//                                                           [ 0      0      1                     ]
//   device_from_ndc:  x_d = xv_min + (x_ndc + 1) Lv/2      [ Lv/2   0     (xv_max + xv_min)/2 ]
//                     y_d = yv_min + (y_ndc + 1) Hv/2      [ 0      Hv/2  (yv_max + yv_min)/2 ]
//                                                           [ 0      0      1                   ]
//   device_from_window = device_from_ndc · ndc_from_window:
//                     x_d = xv_min + (x − xw_min) Lv/Lw,  y_d = yv_min + (y − yw_min) Hv/Hw
//
// with Lw, Hw the window's width and height and Lv, Hv the viewport's. NDC is the square
// [−1, 1] × [−1, 1]: the window's corners go to (−1, −1) and (1, 1). Device coordinates have
// y up and the origin at the bottom-left, like everything else in the project — unless the
// viewport says otherwise. A screen's pixel rows run downward, so an exam puts the window onto
// a 1024×768 screen with its bottom-left corner at pixel (0, 768) and its top-right at
// (1024, 0). The viewport is therefore given by the images of the window's two corners:
// (xv_min, yv_min) is where the window's (xw_min, yw_min) lands and (xv_max, yv_max) where
// (xw_max, yw_max) lands, and Lv = xv_max − xv_min, Hv = yv_max − yv_min are signed. A negative
// size is a flip (a negative scale); the formulas above hold unchanged. Points outside the
// window are mapped too, outside the viewport: this is a mapping, not clipping. Each point is
// computed with the formula its matrix row stands for (2 (x − xw_min)/Lw − 1 rather than
// m00·x + m02: the same number, rounded less, so the window's corners land exactly on ±1).
//
// Distortion: shapes keep their proportions only when both axes scale alike, |Lv/Lw| = |Hv/Hw|
// (a flip mirrors a shape but does not stretch it), i.e. when the aspect ratios |width/height|
// of window and viewport agree. They are compared
// with a relative tolerance of 1e-9 (so 4/3 typed as 1.3333333333 and computed as 4/3 agree);
// when they differ the run warns ("distortion").
//
// Steps: aspect (aspect-match or distortion), window-to-ndc (the matrix), point-to-ndc per
// point, ndc-to-viewport (the matrix), point-to-device per point, compose (the product).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct WindowViewport {
    static constexpr double kAspectTolerance = 1e-9;  // relative

    struct Rect {
        double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
        bool operator==(const Rect&) const = default;
    };
    // How the viewport was given: kept to tell the student, and to write the input back.
    enum class Form : std::uint8_t {
        Rect,     // {"xmin", "ymin", "xmax", "ymax"} on a y-up device: min < max on both axes
        YDown,    // the same rectangle on a device whose rows run downward ("y_down": true)
        Corners,  // {"corners": [A, B]}: A, B the images of the window's two corners, any order
    };
    struct Input {
        Rect window;  // world coordinates; xmin < xmax, ymin < ymax
        // Device coordinates: (xmin, ymin) is the image of the window's (xmin, ymin) corner and
        // (xmax, ymax) the image of its (xmax, ymax) corner. With Form::Rect a rectangle with
        // min < max; otherwise either order on either axis (a flip), but never zero width/height.
        Rect viewport;
        std::vector<glm::dvec2> points;  // world points to map; may be empty
        Form form = Form::Rect;
        bool operator==(const Input&) const = default;
    };
    struct Result {
        std::vector<glm::dvec2> ndc;     // the points in NDC, [−1, 1]² for points in the window
        std::vector<glm::dvec2> device;  // ... and in device coordinates
        glm::dmat3 ndc_from_window{1.0};
        glm::dmat3 device_from_ndc{1.0};
        glm::dmat3 device_from_window{1.0};  // the product of the two
        bool distorted = false;              // the aspect ratios differ
        double aspect_window = 0, aspect_viewport = 0;  // |width / height|
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t {
        Aspect,
        NdcMatrix,
        ToNdc,
        DeviceMatrix,
        ToDevice,
        Compose,
        Done
    };

    struct State {
        Shared<Input> in;  // never changes during a run: copies of the state share it
        Phase phase = Phase::Aspect;  // the step to take next
        Phase last = Phase::Aspect;   // the step taken last (what narrate tells)
        double aspect_window = 0, aspect_viewport = 0;
        bool distorted = false;
        glm::dmat3 ndc_from_window{1.0}, device_from_ndc{1.0}, device_from_window{1.0};
        int k = -1;                      // the point mapped last in this pass (−1: none yet)
        std::vector<glm::dvec2> ndc;     // mapped so far
        std::vector<glm::dvec2> device;  // mapped so far
        bool operator==(const State&) const = default;
    };
    // The state's heap memory, for the timeline's memory budget (see Run::bytes).
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.ndc) + heap_bytes(s.device);  // the shared input is not counted
    }

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static State begin(Shared<Input> in);  // start() for an input already validated
    static void step(State& s, StepInfo* info);  // advance, then narrate if info is given
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static Result result(State&& s);  // moves the mapped points out (run_to_end)
    static void draw(const State& s, Scene& scene);

    // Exam practice (window_viewport_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same mapping as one straight-line function, for the benchmark's comparison.
    static Result map(const Input& in);

private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
