// Flat, Gouraud and Phong shading of a triangle mesh (the course's "Shading"): where the
// lighting model of phong-lighting is evaluated, and what is interpolated between.
//
//   flat     one lighting evaluation per triangle, at its centroid with its face normal; every
//            pixel of the triangle gets that colour (the surface looks faceted).
//   Gouraud  lighting at the vertices (with the vertex normals); the colours are interpolated
//            along the edges to each scanline and along the span to each pixel centre.
//   Phong    the vertex normals are interpolated instead; at every pixel the normal is
//            re-normalised and the lighting evaluated there.
// Every evaluation is PhongLighting::shade (rays/phong_lighting.hpp), with the lesson's eye,
// lights and material, Phong or Blinn-Phong.
//
// Conventions.
//   - Screen space, as the hidden-surface algorithms have it (hsr/screen_scene.hpp): a vertex
//     is (x, y, z) with x, y in pixels (y up) and z its depth, smaller z nearer the viewer. The
//     eye and the lights are points (directions) in the same space, so an eye in front of the
//     mesh has a smaller z than it.
//   - Coverage is scan-triangle's exactly (raster/triangle_spans.hpp): pixel (i, j) belongs to a
//     triangle when its centre (i + ½, j + ½) is inside by the top-left rule, so triangles that
//     share an edge never share a pixel.
//   - The surface point at a pixel is P = (i + ½, j + ½, z) with z interpolated from the
//     vertices' depths: all interpolation is linear in screen space, by the barycentric
//     coordinates λ of the pixel centre in the triangle's (x, y) projection (edge then span,
//     as the course does it, gives the same numbers).
//   - Overlaps are resolved by a depth test in the z-buffer's convention (hsr/z_buffer.hpp):
//     depth cleared to +∞, triangles drawn in index order, a pixel written only when its z is
//     strictly smaller than the depth there (at equal z the earlier triangle stays). Phong
//     evaluates the lighting only for pixels that pass the test.
//   - Face normals: n_f = (P1 − P0) × (P2 − P0), turned to face the viewer (its z made
//     negative: a counter-clockwise triangle on the screen is flipped), whatever the winding.
//     Vertex normals are the given ones, normalised, or else the area-weighted average of the
//     face normals around the vertex: Σ n_f over the faces with area on the screen (the cross
//     product's length is twice the face's area, so the sum weighs each face by its area),
//     then normalised — vertex-normals' area weighting, VertexNormals::area_weighted
//     (affine/vertex_normals.hpp). A vertex whose average comes out zero is an error naming it.
//   - Phong: the normal at a pixel is normalise(Σ λ_k n_k) of the unit vertex normals; where
//     that sum is zero (opposite normals given at the vertices) the face normal is used.
//   - Colours are reported unclamped, as the lighting computes them (Gouraud interpolates the
//     unclamped vertex colours); the picture clamps each channel to [0, 1] for display.
//   - Degenerate triangles (zero area on the screen, orient2d = 0, including repeated indices)
//     cover nothing and add nothing to the vertex normals.
//   - Limits: width and height 1 … kMaxSize and width × height ≤ kMaxPixels; at most
//     kMaxVertices vertices and kMaxTriangles triangles, whose bounding boxes (clipped to the
//     image) hold at most kMaxWork pixels in all, so no run takes more than seconds.
//
// Steps: the vertex normals (Gouraud and Phong); the vertex colours (Gouraud); per triangle its
// set-up (flat: its one evaluation); per scanline of it one span, with the interpolated
// quantities at the span's ends; once for the chosen pixel, its whole computation; done.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"
#include "raster/scan_triangle.hpp"
#include "raster/triangle_spans.hpp"
#include "rays/phong_lighting.hpp"

namespace cg {

struct Shading {
    static constexpr long long kMaxSize = ScanTriangle::kMaxSize;  // pixels per side
    static constexpr long long kMaxPixels = 1LL << 20;  // width × height (the z-buffer's 1024²)
    static constexpr long long kMaxVertices = 100'000;
    static constexpr long long kMaxTriangles = 100'000;
    static constexpr double kMaxWork = double(1LL << 24);  // pixels in the clipped bounding boxes
    static constexpr double kMaxCoordinate = ScanTriangle::kMaxCoordinate;  // |x|, |y|, |z|
    static constexpr double kMaxLightCoordinate = 1e100;  // |coordinate| of the eye, a light
    // The picture's uncovered pixels: a dark slate, as a frame buffer's clear colour, so that
    // white (clamped) pixels stand out as well as black ones.
    static constexpr std::uint32_t kBackground = 0x2a3447ffu;

    enum class Model : std::uint8_t { Flat, Gouraud, Phong };
    using Color = glm::dvec3;

    struct Mesh {
        std::vector<glm::dvec3> vertices;  // (x, y, z): pixels, pixels, depth
        std::vector<glm::dvec3> normals;   // none, or one per vertex (any length > 0)
        std::vector<std::array<long long, 3>> triangles;  // indices into vertices
        bool operator==(const Mesh&) const = default;
    };
    struct Input {
        long long width = 0, height = 0;  // the image, in pixels
        Mesh mesh;
        Model model = Model::Phong;
        // The lighting: eye, ambient, material, lights and the reflection model (Phong or
        // Blinn-Phong); its point and normal are not used.
        PhongLighting::Input lighting;
        bool has_pixel = false;            // the pixel to show in full; else a default (start)
        std::array<long long, 2> pixel{};  // (i, j)
        bool operator==(const Input&) const = default;
    };

    // One pixel of the image.
    struct Sample {
        Color color{0.0};                                    // unclamped
        double z = std::numeric_limits<double>::infinity();  // the depth buffer
        int triangle = -1;                                   // who wrote it; −1: uncovered
        bool operator==(const Sample&) const = default;
    };

    // The image, a row per shared block: copying a state (a checkpoint, a snapshot) shares the
    // rows, and a step copies only the row it writes when that row is shared.
    class Image {
      public:
        void reset(int width, int height);
        const Sample& at(int i, int j) const { return (*rows_[j])[i]; }
        std::vector<Sample>& row_for_writing(int j);  // unshares row j first
        int width() const { return width_; }
        int height() const { return static_cast<int>(rows_.size()); }
        bool operator==(const Image& o) const;
        std::size_t bytes() const {  // what a copy adds: the row pointers and one row
            return rows_.capacity() * sizeof(rows_[0]) + std::size_t(width_) * sizeof(Sample);
        }

      private:
        int width_ = 0;
        std::vector<std::shared_ptr<std::vector<Sample>>> rows_;
    };

    struct Result {
        Model model = Model::Phong;
        int width = 0, height = 0;
        Image image;                       // row 0 at the bottom
        std::vector<glm::dvec3> normals;   // Gouraud, Phong: unit vertex normals (0: unused)
        std::vector<Color> vertex_colors;  // Gouraud: per vertex (0 where unused)
        std::vector<bool> lit;             // Gouraud, Phong: the vertex is used (has area)
        long long evaluations = 0;         // lighting evaluations
        std::array<int, 2> pixel{};        // the chosen pixel
        bool rgb = false;                  // the lighting had colours (else every channel equal)
        const Sample& at(int i, int j) const { return image.at(i, j); }
        bool operator==(const Result&) const = default;
    };

    // The triangle being drawn.
    struct Face {
        int k = -1;                     // its index
        std::array<int, 3> idx{};       // its vertices' indices
        std::array<glm::dvec3, 3> p{};  // its vertices
        raster::TriangleSetup setup;    // sorted, orient, slopes, scanlines (clipped)
        double area2 = 0;        // (p1 − p0) × (p2 − p0) in (x, y): twice the signed area
        glm::dvec3 normal{0.0};  // unit, facing the viewer (z ≤ 0)
        Color flat{0.0};         // flat: its colour
        bool operator==(const Face& o) const {
            return k == o.k && idx == o.idx && p == o.p && setup.v == o.setup.v &&
                   setup.m == o.setup.m && setup.orient == o.setup.orient &&
                   setup.j_begin == o.setup.j_begin && setup.j_end == o.setup.j_end &&
                   area2 == o.area2 && normal == o.normal && flat == o.flat;
        }
    };

    // What the picture compares the run with: every model's finished image, made on the first
    // draw and shared by every copy of the state. It is a function of the input alone, so it
    // takes no part in a state's equality.
    struct Comparison {
        std::once_flag once;
        std::array<std::vector<std::uint32_t>, 3> rgba;  // per Model: 0xRRGGBBAA
        std::array<std::vector<double>, 3> profile;      // per Model: the chosen row's intensity
    };
    struct ComparisonCache {
        std::shared_ptr<Comparison> p = std::make_shared<Comparison>();
        bool operator==(const ComparisonCache&) const { return true; }
    };

    enum class Phase : std::uint8_t { Normals, VertexColors, Triangle, Span, Pixel, Finish, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Normals;  // the step to take next
        Phase last = Phase::Normals;   // the step taken last (what narrate tells)
        int pixel_i = 0, pixel_j = 0;  // the chosen pixel
        // Computed once, then shared by the copies: unit vertex normals (Gouraud, Phong),
        // whether a vertex belongs to a triangle with area, the vertex colours (Gouraud).
        Shared<std::vector<glm::dvec3>> normals;
        Shared<std::vector<bool>> lit;
        Shared<std::vector<Color>> vertex_colors;
        Face face;  // the triangle being drawn
        int j = 0;  // the scanline done last
        double x_left = 0, x_right = 0;
        int i_first = 0, i_end = 0;   // its pixels (clipped to the image)
        int written = 0, hidden = 0;  // this span's pixels that passed / failed the depth test
        // The chosen pixel, when the span just drawn covers it.
        bool pixel_won = false;
        double pixel_z = 0, pixel_z_old = 0;
        int pixel_owner_old = -1;
        Image image;
        long long evaluations = 0;
        long long covered = 0;  // pixels written, overwrites included
        ComparisonCache comparison;
        bool operator==(const State&) const = default;
    };
    static std::size_t bytes(const State& s) { return s.image.bytes(); }

    static const Spec& spec();
    static void validate(const Input& in);  // throws InputError naming the field
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);  // shares the image's rows with the state
    static void draw(const State& s, Scene& scene);  // shading_draw.cpp
    static std::string model_name(Model m);           // "flat", "Gouraud", "Phong"

    // Exam practice (shading_exam.cpp).
    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // The same shading as one straight-line function, for the benchmark's comparison.
    static Result render(const Input& in);

    static const char* model_id(Model m);  // "flat", "gouraud", "phong"

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
