#include "npr/npr_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg::npr {

namespace {

// Reverses any face whose Newell normal points towards `inside(centroid)`, so that every face
// is counter-clockwise from outside whichever way the parametrisation happened to run.
template <class Inside>
void orient(Mesh& m, Inside inside) {
    for (auto& f : m.faces) {
        glm::dvec3 c{0, 0, 0};
        for (int i : f) c += m.vertices[static_cast<std::size_t>(i)];
        c /= static_cast<double>(f.size());
        if (glm::dot(newell(m.vertices, f), c - inside(c)) < 0) std::reverse(f.begin(), f.end());
    }
}

}  // namespace

Mesh generate(const std::string& shape, int segments) {
    using std::numbers::pi;
    Mesh m;
    m.shape = shape;
    m.segments = segments;
    const int n = segments, rings = segments / 2;
    if (shape == "sphere") {
        // North pole, rings 1 .. rings − 1 at polar angle θ = π i/rings from +y, south pole.
        m.vertices.push_back({0, 1, 0});
        for (int i = 1; i < rings; ++i) {
            const double th = pi * i / rings;
            for (int k = 0; k < n; ++k) {
                const double ph = 2 * pi * k / n;
                m.vertices.push_back(
                    {std::sin(th) * std::cos(ph), std::cos(th), -std::sin(th) * std::sin(ph)});
            }
        }
        const int south = static_cast<int>(m.vertices.size());
        m.vertices.push_back({0, -1, 0});
        auto at = [n](int i, int k) { return 1 + (i - 1) * n + (k % n); };
        for (int k = 0; k < n; ++k) m.faces.push_back({0, at(1, k), at(1, k + 1)});
        for (int i = 1; i + 1 < rings; ++i)
            for (int k = 0; k < n; ++k)
                m.faces.push_back({at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1)});
        for (int k = 0; k < n; ++k) m.faces.push_back({at(rings - 1, k), south, at(rings - 1, k + 1)});
        orient(m, [](glm::dvec3) { return glm::dvec3{0, 0, 0}; });
    } else {  // "torus": u around the ring, v around the tube
        const double R = 1, r = 0.4;
        const int tube = rings;
        for (int i = 0; i < n; ++i) {
            const double u = 2 * pi * i / n;
            for (int j = 0; j < tube; ++j) {
                const double v = 2 * pi * j / tube;
                m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u), r * std::sin(v),
                                      -(R + r * std::cos(v)) * std::sin(u)});
            }
        }
        auto at = [n, tube](int i, int j) { return (i % n) * tube + (j % tube); };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < tube; ++j)
                m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        // Outside of the tube: away from the nearest point of the tube's centre circle.
        orient(m, [R](glm::dvec3 c) { return R * glm::normalize(glm::dvec3{c.x, 0, c.z}); });
    }
    return m;
}

glm::dvec3 newell(const std::vector<glm::dvec3>& v, const std::vector<int>& f) {
    glm::dvec3 n{0, 0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) {
        const glm::dvec3& a = v[static_cast<std::size_t>(f[i])];
        const glm::dvec3& b = v[static_cast<std::size_t>(f[(i + 1) % f.size()])];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

void validate(const Mesh& m) {
    if (m.vertices.size() < 3)
        throw InputError("vertices", "needs at least 3 vertices, got " + std::to_string(m.vertices.size()));
    if (m.vertices.size() > kMaxVertices)
        throw InputError("vertices", "at most " + std::to_string(kMaxVertices) + " vertices, got " +
                                         std::to_string(m.vertices.size()));
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = m.vertices[i][c];
            const std::string at = "vertices[" + std::to_string(i) + "][" + std::to_string(c) + "]";
            if (!std::isfinite(x)) throw InputError(at, "must be a finite number");
            // Newell's products of two coordinates then neither overflow nor underflow.
            if (std::fabs(x) > 1e50) throw InputError(at, "must be within ±1e50 (got " + given(x) + ")");
            if (x != 0 && std::fabs(x) < 1e-50)
                throw InputError(at, "must be 0 or at least 1e-50 in size (got " + given(x) + ")");
        }
    if (m.faces.empty()) throw InputError("faces", "needs at least one face, got none");
    if (m.faces.size() > kMaxFaces)
        throw InputError("faces", "at most " + std::to_string(kMaxFaces) + " faces, got " +
                                      std::to_string(m.faces.size()));
    std::size_t corners = 0;
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        const auto& f = m.faces[k];
        auto field = [k] { return "faces[" + std::to_string(k) + "]"; };
        if (f.size() < 3)
            throw InputError(field(), "a face needs at least 3 vertex indices, got " +
                                          std::to_string(f.size()));
        if (f.size() > 256)
            throw InputError(field(), "at most 256 vertices a face, got " + std::to_string(f.size()));
        corners += f.size();
        if (corners > 4 * kMaxFaces)
            throw InputError(field(), "the faces list more than " + std::to_string(4 * kMaxFaces) +
                                          " corners in all");
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f[i] < 0 || static_cast<std::size_t>(f[i]) >= m.vertices.size())
                throw InputError(field() + "[" + std::to_string(i) + "]",
                                 "vertex index " + std::to_string(f[i]) + " is out of range (0 to " +
                                     std::to_string(m.vertices.size() - 1) + ")");
            for (std::size_t j = 0; j < i; ++j)
                if (f[j] == f[i])
                    throw InputError(field() + "[" + std::to_string(i) + "]",
                                     "vertex " + std::to_string(f[i]) +
                                         " is repeated (also at position " + std::to_string(j) + ")");
        }
        const glm::dvec3 p0 = m.vertices[static_cast<std::size_t>(f[0])];
        double size = 0;
        for (int i : f) size = std::max(size, glm::length(m.vertices[static_cast<std::size_t>(i)] - p0));
        const glm::dvec3 n = newell(m.vertices, f);
        const double len = glm::length(n);
        if (!(len > 1e-12 * size * size))
            throw InputError(field(), "is degenerate: its vertices enclose no area (collinear or coincident)");
        const glm::dvec3 u = n / len;
        glm::dvec3 c{0, 0, 0};
        for (int i : f) c += m.vertices[static_cast<std::size_t>(i)];
        c /= static_cast<double>(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double d = std::fabs(glm::dot(u, m.vertices[static_cast<std::size_t>(f[i])] - c));
            if (d > 1e-6 * size)
                throw InputError(field() + "[" + std::to_string(i) + "]",
                                 "the face is not planar: vertex " + std::to_string(f[i]) + " lies " +
                                     given(d, 3) + " off the face's plane (tolerance 1e-6 of its size)");
        }
    }
}

std::pair<glm::dvec3, double> bounds(const Mesh& m) {
    glm::dvec3 lo = m.vertices[0], hi = m.vertices[0];
    for (const auto& p : m.vertices) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return {(lo + hi) / 2.0, std::max(glm::length(hi - lo), 1e-9)};
}

}  // namespace cg::npr
