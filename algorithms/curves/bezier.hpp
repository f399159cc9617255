// What the curve algorithms share: a small point list, Bézier evaluation, and the colours of the
// construction.
//
// Points are glm::dvec3 everywhere; a 2D curve has z = 0 (its `dim` is 2). Pictures drop z.
// A Bézier curve of degree n has n + 1 control points P_0 .. P_n and
//     P(t) = Σ_i P_i B_i^n(t),   B_i^n(t) = C(n, i) (1 − t)^(n−i) t^i,
// evaluated here by de Casteljau's repeated linear interpolation, which is exact for every t
// (t outside [0, 1] extrapolates the same polynomial).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace cg::curves {

// Degrees above this are refused: the binomials stay exact in a double (C(50, 25) < 2^53),
// the de Casteljau triangle stays small, and a picture with more points is unreadable anyway.
constexpr int kMaxDegree = 50;

// Coordinates beyond this are refused, so that sums, differences and extrapolated points stay
// finite (|t| ≤ kMaxAbsT: 1001^50 · 1e100 < 1e308).
constexpr double kMaxCoordinate = 1e100;
constexpr double kMaxAbsT = 1000;

// A list of points kept inside the object while there are at most N of them, on the heap
// beyond. A cubic's de Casteljau triangle (10 points) then costs no allocation, so building a
// state per evaluation is as cheap as a plain function's stack arrays. Entries past size() are
// never read; equality compares the points in use only.
template <std::size_t N>
class InlinePoints {
  public:
    InlinePoints() = default;
    InlinePoints(std::initializer_list<glm::dvec3> points) { assign(points.begin(), points.end()); }
    explicit InlinePoints(std::span<const glm::dvec3> points) {
        assign(points.begin(), points.end());
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    glm::dvec3* data() { return size_ <= N ? local_.data() : heap_.data(); }
    const glm::dvec3* data() const { return size_ <= N ? local_.data() : heap_.data(); }
    glm::dvec3& operator[](std::size_t i) { return data()[i]; }
    const glm::dvec3& operator[](std::size_t i) const { return data()[i]; }
    glm::dvec3* begin() { return data(); }
    glm::dvec3* end() { return data() + size_; }
    const glm::dvec3* begin() const { return data(); }
    const glm::dvec3* end() const { return data() + size_; }
    std::span<const glm::dvec3> span() const { return {data(), size_}; }
    std::vector<glm::dvec3> to_vector() const { return {begin(), end()}; }

    // Keeps the first min(n, size()) points; new ones are zero.
    void resize(std::size_t n) {
        if (n <= N) {
            if (size_ > N)
                std::copy(heap_.begin(), heap_.begin() + static_cast<std::ptrdiff_t>(n),
                          local_.begin());
            for (std::size_t i = size_; i < n; ++i) local_[i] = glm::dvec3(0);
            heap_.clear();
        } else {
            if (size_ <= N)
                heap_.assign(local_.begin(), local_.begin() + static_cast<std::ptrdiff_t>(size_));
            heap_.resize(n, glm::dvec3(0));
        }
        size_ = static_cast<std::uint32_t>(n);
    }
    void push_back(glm::dvec3 p) {
        resize(size_ + 1);
        data()[size_ - 1] = p;
    }

    friend bool operator==(const InlinePoints& a, const InlinePoints& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end());
    }

  private:
    template <class It>
    void assign(It first, It last) {
        resize(static_cast<std::size_t>(last - first));
        std::copy(first, last, data());
    }

    std::array<glm::dvec3, N> local_;  // the points while size_ ≤ N (uninitialised past size_)
    std::vector<glm::dvec3> heap_;     // the points while size_ > N
    std::uint32_t size_ = 0;
};

// C(n, i), exact for n ≤ kMaxDegree.
double binomial(int n, int i);

// P(t) of the Bézier curve with these control points (at least one), by de Casteljau.
glm::dvec3 bezier_point(std::span<const glm::dvec3> control_points, double t);
// P'(t) = n Σ (P_{i+1} − P_i) B_i^{n−1}(t): the derivative curve ("hodograph") evaluated.
glm::dvec3 bezier_derivative(std::span<const glm::dvec3> control_points, double t);
// `samples` + 1 points of the curve at equal steps of t from t0 to t1, as 2D (z dropped).
std::vector<glm::dvec2> bezier_polyline(std::span<const glm::dvec3> control_points, double t0,
                                        double t1, int samples = 100);

// The largest |coordinate| of the points (0 for none): the scale relative tolerances use.
double coordinate_scale(std::span<const glm::dvec3> points);

// Shades for the levels of a construction (level 1, 2, …) and for curve pieces: distinct on
// white, dark enough for labels, none of them the roles' green (the result) or orange (the
// active test). 0xRRGGBBAA, cycling after eight.
std::uint32_t shade(int k);

// "P₁²": a point's name with Unicode subscript and superscript digits (the viewer's font has
// them). A negative `level` leaves the superscript out.
std::string point_name(int i, int level = -1, const char* letter = "P");
std::string subscript(int n);
std::string superscript(int n);

inline glm::dvec2 xy(glm::dvec3 p) {
    return {p.x, p.y};
}

// Input checks shared by the curve algorithms; each throws InputError naming the field as the
// user wrote it ("control_points[2][1]").
//   points: between min_count and max_count of them, dim 2 or 3, every coordinate finite and
//   within ±kMaxCoordinate, z = 0 when dim is 2.
void validate_points(std::span<const glm::dvec3> points, int dim, const std::string& field,
                     std::size_t min_count, std::size_t max_count = kMaxDegree + 1);
//   t: finite; in [0, 1] unless extrapolating, and then within ±kMaxAbsT.
void validate_t(double t, bool extrapolate, const std::string& field = "t");

}  // namespace cg::curves
