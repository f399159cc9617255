// Sections: [spec] [validate] [advance] [narrate] [plain]; the picture is in backface_cull_draw.cpp
#include "hsr/backface_cull.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

enum Line { kLineLoop = 1, kLineNormal, kLineView, kLineTest, kLineCull, kLineKeep, kLineDone };

std::string face_name(int k) {
    return "F" + std::to_string(k);
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& BackfaceCull::spec() {
    static const Spec spec{
        "backface-cull",
        "Back-face culling",
        "Hidden Surface Removal",
        {
            "for each face F_k = (P_0, …, P_{m−1}), counter-clockwise seen from outside:",
            "    N ← Newell's normal Σ (y_i − y_{i+1})(z_i + z_{i+1}), …  (points outward)",
            "    V ← P_0 − eye (perspective)  or  V ← view direction (parallel)",
            "    if N·V > 0:",
            "        cull F_k                        ▷ it faces away from the viewer",
            "    else: keep F_k                      ▷ N·V = 0 (edge-on) is kept",
            "done: draw only the kept faces",
        },
        {
            {"culled", "N·V > 0: the face points away from the viewer and is dropped"},
            {"kept", "N·V < 0: the face points towards the viewer and is kept"},
            {"edge-on",
             "N·V = 0: the face is seen exactly edge-on; by the course's test it is kept"},
            {"done", "every face decided: the kept faces go on to hidden-surface removal"},
        },
        {},  // no sliders
        {
            .predict = {{"culled", {"N·V"}}, {"kept", {"N·V"}}},
            .mistakes = {
                {"culled", "N", "negate", "took the vertices clockwise: the normal points inwards"},
                {"culled", "V", "negate",
                 "took V from the polygon to the eye instead of eye to polygon"},
                {"kept", "", "event:culled", "culled when N·V < 0: the test turned round"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

glm::dvec3 BackfaceCull::newell(const Input& in, const std::vector<int>& f) {
    glm::dvec3 n{0, 0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) {
        // Read in place: copied into locals, GCC (inlining this into the state machine's step)
        // moved each vertex through the stack in 16-byte pieces and stalled reading it back
        // (a failed store-to-load forwarding; 30% of run_to_end's time).
        const glm::dvec3& a = in.vertices[static_cast<std::size_t>(f[i])];
        const glm::dvec3& b = in.vertices[static_cast<std::size_t>(f[(i + 1) % f.size()])];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

glm::dvec3 BackfaceCull::view_vector(const Input& in, const std::vector<int>& f) {
    return in.perspective ? in.vertices[static_cast<std::size_t>(f[0])] - in.eye : in.view_dir;
}

void BackfaceCull::validate(const Input& in) {
    // Within ±1e50 and 0 or at least 1e-50 in size: Newell's normals (products of two
    // coordinates), their squared lengths and N·V then neither overflow nor underflow.
    auto check_range = [](glm::dvec3 p, const std::string& field) {
        for (int c = 0; c < 3; ++c) {
            const double v = p[c];
            const std::string at = field + "[" + std::to_string(c) + "]";
            if (std::fabs(v) > 1e50) throw InputError(at, "must be within ±1e50 (got " + given(v) + ")");
            if (v != 0 && std::fabs(v) < 1e-50)
                throw InputError(at, "must be 0 or at least 1e-50 in size (got " + given(v) + ")");
        }
    };
    auto finite3 = [](glm::dvec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    if (in.vertices.empty()) throw InputError("vertices", "needs at least 3 vertices, got none");
    if (in.vertices.size() > kMaxVertices)
        throw InputError("vertices", "at most " + std::to_string(kMaxVertices) + " vertices, got " +
                                         std::to_string(in.vertices.size()));
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        if (!finite3(in.vertices[i]))
            throw InputError("vertices[" + std::to_string(i) + "]",
                             "every coordinate must be a finite number");
        check_range(in.vertices[i], "vertices[" + std::to_string(i) + "]");
    }
    if (in.faces.empty()) throw InputError("faces", "needs at least one face, got none");
    if (in.faces.size() > kMaxFaces)
        throw InputError("faces", "at most " + std::to_string(kMaxFaces) + " faces, got " +
                                      std::to_string(in.faces.size()));
    if (in.perspective && !finite3(in.eye))
        throw InputError("eye", "every coordinate must be a finite number");
    if (in.perspective) check_range(in.eye, "eye");
    if (!in.perspective) {
        if (!finite3(in.view_dir))
            throw InputError("view_dir", "every coordinate must be a finite number");
        check_range(in.view_dir, "view_dir");
        if (in.view_dir == glm::dvec3(0, 0, 0))
            throw InputError("view_dir", "is the zero vector: a viewing direction needs a length");
    }
    for (std::size_t k = 0; k < in.faces.size(); ++k) {
        const auto& f = in.faces[k];
        auto field = [k] { return "faces[" + std::to_string(k) + "]"; };  // built only for an error
        if (f.size() < 3)
            throw InputError(
                field(), "a face needs at least 3 vertex indices, got " + std::to_string(f.size()));
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f[i] < 0 || static_cast<std::size_t>(f[i]) >= in.vertices.size())
                throw InputError(field() + "[" + std::to_string(i) + "]",
                                 "vertex index " + std::to_string(f[i]) +
                                     " is out of range (0 to " +
                                     std::to_string(in.vertices.size() - 1) + ")");
            for (std::size_t j = 0; j < i; ++j)
                if (f[j] == f[i])
                    throw InputError(field() + "[" + std::to_string(i) + "]",
                                     "vertex " + std::to_string(f[i]) +
                                         " is repeated (also at position " + std::to_string(j) +
                                         ")");
        }
        // Size of the face: its longest distance from P_0, for relative tolerances.
        const glm::dvec3 p0 = in.vertices[static_cast<std::size_t>(f[0])];
        double size = 0;
        for (int i : f)
            size = std::max(size, glm::length(in.vertices[static_cast<std::size_t>(i)] - p0));
        const glm::dvec3 n = newell(in, f);
        const double len = glm::length(n);
        if (!(len > 1e-12 * size * size))
            throw InputError(
                field(), "is degenerate: its vertices enclose no area (collinear or coincident)");
        const glm::dvec3 u = n / len;
        const glm::dvec3 c = [&] {
            glm::dvec3 s{0, 0, 0};
            for (int i : f) s += in.vertices[static_cast<std::size_t>(i)];
            return s / static_cast<double>(f.size());
        }();
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double d =
                std::fabs(glm::dot(u, in.vertices[static_cast<std::size_t>(f[i])] - c));
            if (d > 1e-6 * size)
                throw InputError(field() + "[" + std::to_string(i) + "]",
                                 "the face is not planar: vertex " + std::to_string(f[i]) +
                                     " lies " + given(d, 3) +
                                     " off the face's plane (tolerance 1e-6 of its size)");
        }
    }
}

BackfaceCull::State BackfaceCull::start(const Input& in) { return start(Shared<Input>(in)); }

BackfaceCull::State BackfaceCull::start(Shared<Input> in) {
    validate(*in);
    State s;
    const std::size_t faces = in->faces.size();
    s.in = std::move(in);
    s.r.culled.reserve(faces);
    s.r.normals.reserve(faces);
    s.r.dots.reserve(faces);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void BackfaceCull::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Face: {  // Normal, view vector, and the sign of N·V for one face
            const auto& f = s.in->faces[static_cast<std::size_t>(s.k)];
            s.n = newell(*s.in, f);
            s.v = view_vector(*s.in, f);
            s.ndotv = glm::dot(s.n, s.v);
            const double len = glm::length(s.n);
            const glm::dvec3 u = s.n / len;
            const bool cull = s.ndotv > 0;
            s.r.culled.push_back(cull);
            s.r.normals.push_back(u);
            s.r.dots.push_back(s.ndotv / len);
            (cull ? s.culled : s.kept) += 1;
            if (++s.k == static_cast<int>(s.in->faces.size())) s.phase = Phase::Finish;
            return;
        }
        case Phase::Finish:  // Every face decided
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

void BackfaceCull::narrate(const State& s, StepInfo& info) {
    info = {};
    if (s.last == Phase::Face) {
        const int k = s.k - 1;
        const auto& f = s.in->faces[static_cast<std::size_t>(k)];
        const glm::dvec3 p0 = s.in->vertices[static_cast<std::size_t>(f[0])];
        const std::string F = face_name(k);
        const std::string vtext = s.in->perspective ? "V = P_0 − eye = " + num(p0, 4) + " − " +
                                                         num(s.in->eye, 4) + " = " + num(s.v, 4)
                                                   : "V = view direction " + num(s.v, 4);
        const std::string head = F + ": Newell's normal N = " + num(s.n, 4) + ", " + vtext +
                                 ", N·V = " + num(s.ndotv, 4);
        const std::string vtex = s.in->perspective ? "V = P_0 - E = " + tex(p0, 4) + " - " +
                                                        tex(s.in->eye, 4) + " = " + tex(s.v, 4)
                                                  : "V = " + tex(s.v, 4);
        std::string rel;
        if (s.ndotv > 0) {
            info.event = "culled";
            info.line = kLineCull;
            info.narration = head + " > 0, so it faces away from the viewer: culled.";
            rel = " > 0";
        } else if (s.ndotv < 0) {
            info.event = "kept";
            info.line = kLineKeep;
            info.narration = head + " < 0, so it faces the viewer: kept.";
            rel = " < 0";
        } else {
            info.event = "edge-on";
            info.line = kLineKeep;
            info.narration =
                head +
                ": the face is seen exactly edge-on, and since only N·V > 0 is culled it is kept.";
        }
        info.math = "N = " + tex(s.n, 4) + ",\\quad " + vtex +
                    ",\\quad N \\cdot V = " + tex(s.ndotv, 4) + rel;
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"N", vec(s.n)});
        info.vars.push_back({"V", vec(s.v)});
        info.vars.push_back({"N·V", s.ndotv});
        info.vars.push_back({"culled", s.ndotv > 0});
    } else {
        info.event = "done";
        info.line = kLineDone;
        info.narration = "All " + std::to_string(s.in->faces.size()) +
                         " faces decided: " + std::to_string(s.culled) + " culled, " +
                         std::to_string(s.kept) + " kept for drawing.";
        info.math = "\\text{culled} = " + std::to_string(s.culled) +
                    ",\\quad \\text{kept} = " + std::to_string(s.kept);
    }
    info.vars.push_back({"culled_count", static_cast<long long>(s.culled)});
    info.vars.push_back({"kept_count", static_cast<long long>(s.kept)});
}

void BackfaceCull::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [plain] --------------------------------------------------------------------------------

[[gnu::flatten]] BackfaceCull::Result BackfaceCull::cull(const Input& in) {
    validate(in);
    Result r;
    r.culled.reserve(in.faces.size());
    r.normals.reserve(in.faces.size());
    r.dots.reserve(in.faces.size());
    for (const auto& f : in.faces) {
        const glm::dvec3 n = newell(in, f);
        const double d = glm::dot(n, view_vector(in, f));
        const double len = glm::length(n);
        r.culled.push_back(d > 0);
        r.normals.push_back(n / len);
        r.dots.push_back(d / len);
    }
    return r;
}

}  // namespace cg
