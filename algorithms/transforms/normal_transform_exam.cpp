// Normal-transform exam problems: a non-uniform scale, a shear, a rotation or a uniform scale
// (the last two keep L n a normal), or a scale after a rotation, all with small integer or
// half entries so that the inverse transpose is a short decimal; a small integer normal.
#include <array>

#include "core/format.hpp"
#include "transforms/normal_transform.hpp"

namespace cg {

namespace {

// Rows.
constexpr std::array<std::array<double, 9>, 10> kMatrices = {{
    {2, 0, 0, 0, 1, 0, 0, 0, 1},
    {1, 0, 0, 0, 4, 0, 0, 0, 1},
    {1, 0, 0, 0, 0.5, 0, 0, 0, 1},
    {1, 0, 0, 0, 1, 0, 0, 0, 4},
    {1, 1, 0, 0, 1, 0, 0, 0, 1},
    {1, 0, 0, 2, 1, 0, 0, 0, 1},
    {1, 0, 1, 0, 1, 0, 0, 0, 1},
    {0, -1, 0, 1, 0, 0, 0, 0, 1},  // rotation about z by 90°
    {2, 0, 0, 0, 2, 0, 0, 0, 2},   // uniform scale
    {0, -2, 0, 1, 0, 0, 0, 0, 1},  // scale x by 2 after rotating by 90°
}};
constexpr std::array<std::array<double, 3>, 7> kNormals = {
    {{1, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 1}, {1, 2, 0}, {-1, 1, 0}}};

}  // namespace

NormalTransform::Input NormalTransform::exam_input(Rng& rng) {
    Input in;
    const auto& m = kMatrices[static_cast<std::size_t>(rng.integer(0, kMatrices.size() - 1))];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) in.linear[c][r] = m[static_cast<std::size_t>(3 * r + c)];
    const auto& n = kNormals[static_cast<std::size_t>(rng.integer(0, kNormals.size() - 1))];
    in.normal = {n[0], n[1], n[2]};
    return in;
}

std::string NormalTransform::question(const Input& in) {
    std::string m = "[";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m += (c ? " " : "") + num(in.linear[c][r]);
        m += r < 2 ? "; " : "]";
    }
    return "A surface has the normal n = " + num(in.normal) + ". It is transformed by the linear "
           "map L = " + m + " (rows, acting on column vectors). Give the normal matrix (L⁻¹)ᵀ "
           "(inverse_transpose, rows), the transformed normal N n (normal, not normalised), and "
           "say whether transforming n by L itself would still give a normal (naive_ok).";
}

std::vector<std::string> NormalTransform::answer_fields() {
    return {"inverse_transpose", "normal", "naive_ok"};
}

}  // namespace cg
