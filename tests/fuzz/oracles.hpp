// What must hold for every accepted input of every registered algorithm (issue 25): the fuzz
// target fuzz_algorithm_input checks it on every input that passes validation, and the normal
// suite on every algorithm's example and mutations of it (tests/robustness/test_fuzz_oracles.cpp).
//
//   finite       every coordinate drawn (2D and 3D) and every number in the result is finite,
//                and no narration, formula or variable reads "nan" or "inf"
//   resumable    a copy of the state taken part-way finishes with the same steps, byte for
//                byte, the same result and the same final state: what the viewer's Back and
//                the timeline's checkpoints rely on (back, then forward, replays the copy)
//   plain        run to the end, the result holds every number of the algorithm's
//                straight-line function's (where it has one) to the tests' tolerance
//   silent       stepping without narration (run to end, the tests' reference runs) reaches
//                the same final state as stepping with it
// A broken oracle throws OracleViolation naming the algorithm, the step and what differs.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene.hpp"
#include "fuzz_support.hpp"

namespace cg::fuzz {

struct OracleViolation : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Outcome {
    bool accepted = false;   // passed validation and ran
    std::size_t steps = 0;   // steps taken (up to kStepCap)
};

namespace oracle_detail {

inline bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }
inline bool finite(glm::dvec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The first non-finite thing a scene would draw, or "".
inline std::string non_finite(const Scene& s) {
    for (const auto& p : s.points) if (!finite(p.p)) return "a 2D point";
    for (const auto& g : s.segments) if (!finite(g.a) || !finite(g.b)) return "a 2D segment";
    for (const auto& p : s.polygons)
        for (auto q : p.points) if (!finite(q)) return "a 2D polygon";
    for (const auto& h : s.half_planes) if (!finite(h.point) || !finite(h.inward)) return "a half-plane";
    for (const auto& l : s.labels) if (!finite(l.p)) return "a 2D label";
    for (const auto& h : s.handles) if (!finite(h.p)) return "a handle";
    for (const auto& g : s.grids) if (!finite(g.origin)) return "a pixel grid's origin";
    for (const auto& p : s.points3) if (!finite(p.p)) return "a 3D point";
    for (const auto& g : s.segments3) if (!finite(g.a) || !finite(g.b)) return "a 3D segment";
    for (const auto& f : s.faces3)
        for (auto q : f.points) if (!finite(q)) return "a 3D face";
    for (const auto& l : s.labels3) if (!finite(l.p)) return "a 3D label";
    for (const auto& f : s.frames3)
        if (!finite(f.origin) || !finite(f.x) || !finite(f.y) || !finite(f.z) || !std::isfinite(f.length))
            return "a 3D frame";
    if (!std::isfinite(s.extent3)) return "the 3D extent";
    return "";
}

// Whether text shows a non-number as a word of its own: "nan", "-nan", "inf", "-inf" (any
// case), not "infinity" or "inflection".
inline bool shows_non_number(std::string_view text) {
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (i > 0 && word(text[i - 1])) continue;
        for (std::string_view bad : {"nan", "inf"}) {
            if (text.size() - i < bad.size()) continue;
            bool same = true;
            for (std::size_t k = 0; k < bad.size(); ++k)
                same = same && std::tolower(static_cast<unsigned char>(text[i + k])) == bad[k];
            const std::size_t end = i + bad.size();
            if (same && (end == text.size() || !word(text[end]))) return true;
        }
    }
    return false;
}

// The path of the first non-finite number in j, or "".
inline std::string non_finite(const json& j, const std::string& path = "") {
    if (j.is_number_float() && !std::isfinite(j.get<double>())) return path.empty() ? "/" : path;
    if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i)
            if (auto p = non_finite(j[i], path + "/" + std::to_string(i)); !p.empty()) return p;
    if (j.is_object())
        for (const auto& [k, v] : j.items())
            if (auto p = non_finite(v, path + "/" + k); !p.empty()) return p;
    return "";
}

// The path of the first difference between a and b, numbers compared to the tests'
// tolerance (relative 1e-9, absolute near 0), or "". An object of b may have fields a lacks:
// a run's result adds what the lesson shows (solid-texture's worked noise point), a plain
// function computes only the numbers.
inline std::string first_difference(const json& a, const json& b, const std::string& path = "") {
    const std::string here = path.empty() ? "/" : path;
    if (a.is_number() && b.is_number()) {
        const double x = a.get<double>(), y = b.get<double>();
        const double scale = std::max({1.0, std::fabs(x), std::fabs(y)});
        return std::fabs(x - y) <= 1e-9 * scale ? "" : here + " (" + a.dump() + " against " + b.dump() + ")";
    }
    if (a.type() != b.type() || (!a.is_object() && a.size() != b.size())) return here;
    if (a.is_array()) {
        for (std::size_t i = 0; i < a.size(); ++i)
            if (auto d = first_difference(a[i], b[i], path + "/" + std::to_string(i)); !d.empty()) return d;
        return "";
    }
    if (a.is_object()) {
        for (const auto& [k, v] : a.items()) {
            if (!b.contains(k)) return path + "/" + k + " (missing)";
            if (auto d = first_difference(v, b[k], path + "/" + k); !d.empty()) return d;
        }
        return "";
    }
    return a == b ? "" : here + " (" + a.dump() + " against " + b.dump() + ")";
}

// FNV-1a: the steps are compared byte for byte through their hashes, so a long run keeps
// eight bytes per step.
inline std::uint64_t hash(const std::string& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    return h;
}

// One narrated step, checked; returns its JSON's hash.
inline std::uint64_t narrated_step(Run& run, std::size_t i, const std::string& who) {
    StepInfo info;
    run.step(&info);
    auto text_ok = [&](const std::string& t, const char* what) {
        if (shows_non_number(t))
            throw OracleViolation(who + ": step " + std::to_string(i) + "'s " + what + " shows a non-number: " + t);
    };
    text_ok(info.narration, "narration");
    text_ok(info.math, "formula");
    const json j = step_to_json(i, info);
    if (j.contains("variables")) {
        // A variable whose whole value is the string "inf" or "-inf" is the project's JSON
        // spelling of an infinite t (ray-aabb's slabs, the grid's t_max): typed so, it grades
        // right in Predict. A non-finite number is still caught below, as a number.
        for (const auto& [name, v] : j["variables"].items())
            if (v != "inf" && v != "-inf") text_ok(name + " = " + v.dump(), "variable");
        if (const std::string at = non_finite(j["variables"]); !at.empty())
            throw OracleViolation(who + ": step " + std::to_string(i) + " has a non-finite variable at " + at);
    }
    return hash(j.dump());
}

inline void check_scene(const Run& run, std::size_t i, const std::string& who) {
    Scene scene;
    run.draw(scene);
    if (const std::string what = non_finite(scene); !what.empty())
        throw OracleViolation(who + ": the picture after step " + std::to_string(i) + " has a non-finite coordinate in " + what);
}

}  // namespace oracle_detail

// Runs `input` as the CLI and the viewer do (create, then narrated steps with their pictures,
// then the result) and checks the oracles above. Only InputError may escape validation.
inline Outcome check_algorithm_input(const Algorithm& a, const json& input) {
    namespace d = oracle_detail;
    const std::string who = a.spec->id;
    // check() (what loading a lesson runs) accepts and refuses what create() does, saying the same.
    std::string checked;  // its error; empty when it accepts
    if (a.check) {
        try {
            a.check(input);
        } catch (const InputError& e) {
            checked = e.what();
        }
    }
    std::unique_ptr<Run> run;
    try {
        run = a.create(input);
    } catch (const InputError& e) {
        if (a.check && checked != e.what())
            throw OracleViolation(who + ": create refuses the input (" + e.what() + ") but check " +
                                  (checked.empty() ? "accepts it" : "says " + checked));
        return {};  // refused, with a message naming the field: fine
    }
    if (!checked.empty())
        throw OracleViolation(who + ": create accepts the input but check refuses it (" + checked + ")");
    if (too_costly(a, input)) return {};  // valid, but minutes to run
    Outcome out{true, 0};
    // A copy at steps 0, 1, 2, 4, 8, …: the last one taken is resumed at the end, so the
    // replay covers at least the second half of the run.
    std::unique_ptr<Run> copy = run->clone();
    std::size_t copied_at = 0;
    std::vector<std::uint64_t> since_copy;
    std::size_t i = 0;
    while (!run->done() && i < kStepCap) {
        if (i > 0 && (i & (i - 1)) == 0) {
            copy = run->clone();
            copied_at = i;
            since_copy.clear();
        }
        ++i;
        since_copy.push_back(d::narrated_step(*run, i, who));
        // The picture of the first steps and then of every 1024th: a big grid's picture costs
        // as much as its pixels, and a viewer draws one step per frame, not thousands.
        if (i <= 64 || i % 1024 == 0) d::check_scene(*run, i, who);
    }
    out.steps = i;
    d::check_scene(*run, i, who);
    std::string result;
    if (run->done()) {
        const json r = a.result(*run);
        if (const std::string at = d::non_finite(r); !at.empty())
            throw OracleViolation(who + ": the result has a non-finite number at " + at);
        result = r.dump();
        // Plain: the straight-line function gives the same result.
        if (a.plain) {
            const json p = a.plain(input);
            if (const std::string at = d::first_difference(p, r); !at.empty())
                throw OracleViolation(who + ": run to the end and the plain function differ at " + at);
        }
    }

    // Resumable: the copy replays the same steps and ends in the same state.
    std::unique_ptr<Run> silent = copy->clone();
    for (std::size_t k = copied_at; k < i; ++k) {
        if (copy->done())
            throw OracleViolation(who + ": a copy taken at step " + std::to_string(copied_at) + " finished early, at step " + std::to_string(k));
        if (d::narrated_step(*copy, k + 1, who) != since_copy[k - copied_at])
            throw OracleViolation(who + ": step " + std::to_string(k + 1) + " differs when a copy taken at step " + std::to_string(copied_at) + " is resumed");
    }
    if (!copy->same_state(*run))
        throw OracleViolation(who + ": a copy taken at step " + std::to_string(copied_at) + " ends in another state");
    if (run->done() && a.result(*copy).dump() != result)
        throw OracleViolation(who + ": a copy taken at step " + std::to_string(copied_at) + " gives another result");

    // Silent: the same steps without narration reach the same state.
    for (std::size_t k = copied_at; k < i && !silent->done(); ++k) silent->step(nullptr);
    if (!silent->same_state(*run))
        throw OracleViolation(who + ": stepping without narration from step " + std::to_string(copied_at) + " ends in another state than with it");
    return out;
}

}  // namespace cg::fuzz
