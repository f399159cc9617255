// Photon mapping: the events and the narration of each step (the picture: photon_map_draw.cpp).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "gi/photon_map.hpp"
#include "rays/quadric.hpp"

namespace cg {

using glm::dvec3;

const Spec& PhotonMap::spec() {
    static const Spec spec{
        "photon-map",
        "Photon mapping: photons from the lights, a kd-tree, and the k nearest",
        "Global illumination",
        {
            "for each light L: n_L photons, each with Φ_p = Φ_L / n_L, in random directions",
            "    trace: a mirror reflects; glass refracts (reflects at total internal reflection)",
            "    diffuse: store (x, ω, Φ_p);  ξ < ρ ? bounce in a cosine direction : absorb   ▷ "
            "Russian roulette",
            "build the kd-tree: each node the median of its photons on their widest axis",
            "k nearest to x: visit a node, keep the k closest in a max-heap;  r² ← its top",
            "    skip the far side of a node when its plane's distance² > r²",
            "E(x) ≈ Σ_p Φ_p / (π r²)",
        },
        {
            {"photon",
             "one photon's path from its light: every specular bounce, the diffuse hits stored, "
             "and Russian roulette's ξ against the survival probability P = ρ"},
            {"photon-batch", "a batch of photons traced at once (after the first 20, one by one)"},
            {"build-node",
             "one kd-tree node: the bounding box of its photons, the widest axis, the median "
             "photon and its splitting plane"},
            {"visit",
             "the k-nearest search visits a node: its photon's d² is offered to the max-heap, "
             "and r² shrinks when a nearer photon replaces the farthest"},
            {"prune",
             "a subtree skipped: its splitting plane is farther than r², so it holds nothing "
             "nearer"},
            {"estimate", "the irradiance from the k nearest photons: E ≈ Σ Φ_p / (π r²)"},
        },
        {},  // no sliders
        {
            .predict = {{"photon", {"stored"}},
                        {"build-node", {"axis", "split"}},
                        {"visit", {"d2", "r2"}},
                        {"estimate", {"E"}}},
            .mistakes =
                {
                    {"visit", "r2", "keep",
                     "forgot to shrink r² after a nearer photon replaced the farthest in the heap"},
                    {"photon", "survived", "not",
                     "read Russian roulette the wrong way round: ξ < P taken as absorbed"},
                    {"prune", "", "event:visit",
                     "searched a subtree whose plane is already farther than r²"},
                },
            .costs = {"visited"},
        },
    };
    return spec;
}

// ---- [narration] ----------------------------------------------------------------------------

namespace {

std::string object_name(const PhotonMap::Input& in, int o) {
    const auto& ob = in.objects[std::size_t(o)];
    const char* m = ob.material == PhotonMap::Material::Mirror  ? "mirror "
                    : ob.material == PhotonMap::Material::Glass ? "glass "
                                                                : "diffuse ";
    return std::string(m) + (ob.shape == PhotonMap::Shape::Sphere ? "sphere" : "plane") + " " +
           std::to_string(o);
}

void narrate_photon(const PhotonMap::State& s, StepInfo& info) {
    const PhotonMap::Input& in = *s.in;
    const PhotonMap::Path& p = s.path;
    info.event = "photon";
    info.line = 1;
    std::string text = "Photon " + std::to_string(p.photon) + " from light " +
                       std::to_string(p.light) + " with Φ_p = " + num(p.power) + ":";
    bool roulette = false;
    double xi = 0, P = 0;
    for (const auto& b : p.bounces) {
        using E = PhotonMap::Event;
        switch (b.event) {
            case E::Reflect:
                text += " reflected by the " + object_name(in, b.object) + " at " + num(b.point, 3) + ";";
                info.line = 2;
                break;
            case E::Refract:
                text += " refracted at the " + object_name(in, b.object) + " at " + num(b.point, 3) + ";";
                info.line = 2;
                break;
            case E::TotalInternal:
                text += " totally internally reflected in the " + object_name(in, b.object) + " at " +
                        num(b.point, 3) + ";";
                info.line = 2;
                break;
            case E::Survive:
            case E::Absorb:
                text += " stored on the " + object_name(in, b.object) + " at " + num(b.point, 3) +
                        ", ξ = " + num(b.xi, 3) + (b.event == E::Survive ? " < " : " ≥ ") +
                        "P = " + num(b.P, 3) +
                        (b.event == E::Survive ? ": survives, bounces diffusely;" : ": absorbed.");
                roulette = true, xi = b.xi, P = b.P;
                info.line = 3;
                break;
            case E::Escape: text += " leaves the scene."; break;
            case E::Limit: text += " stopped after max_bounces bounces."; break;
        }
    }
    text += " " + std::to_string(s.photons.size()) + " photons stored so far.";
    info.narration = std::move(text);
    info.vars = {{"photon", (long long)p.photon},
                 {"light", (long long)p.light},
                 {"Phi_p", p.power},
                 {"bounces", (long long)p.bounces.size()},
                 {"stored", (long long)p.stored}};
    if (roulette) {
        info.vars.push_back({"xi", xi});
        info.vars.push_back({"P", P});
        info.vars.push_back({"survived", xi < P});
        info.math = "\\xi = " + tex(xi, 3) + (xi < P ? " < " : " \\ge ") + "P = \\rho = " + tex(P, 3);
    } else {
        info.math = "\\Phi_p = \\Phi_L / n_L = " + tex(p.power);
    }
    info.vars.push_back({"stored_total", (long long)s.photons.size()});
}

void narrate_batch(const PhotonMap::State& s, StepInfo& info) {
    info.event = "photon-batch";
    info.line = 1;
    info.narration = "Photons " + std::to_string(s.batch_first) + " to " +
                     std::to_string(s.emitted - 1) +
                     " traced in one step (after the first 20 one by one, the rest go in "
                     "batches): " + std::to_string(s.photons.size()) + " photons stored so far, " +
                     std::to_string(s.escaped) + " left the scene, " + std::to_string(s.absorbed) +
                     " absorbed.";
    info.vars = {{"first", (long long)s.batch_first},
                 {"last", (long long)(s.emitted - 1)},
                 {"stored_total", (long long)s.photons.size()},
                 {"escaped", (long long)s.escaped},
                 {"absorbed", (long long)s.absorbed}};
}

const char* axis_name(int a) {
    return a == 0 ? "x" : a == 1 ? "y" : "z";
}

void narrate_node(const PhotonMap::State& s, StepInfo& info) {
    const PhotonMap::Node& n = s.node;
    info.event = "build-node";
    info.line = 4;
    const dvec3 size = n.box_hi - n.box_lo;
    const int median = s.order[std::size_t(n.m)];
    info.narration = "Node of " + std::to_string(n.hi - n.lo) + " photons, box " + num(n.box_lo, 3) +
                     " to " + num(n.box_hi, 3) + ": widest axis " + axis_name(n.axis) + " (" +
                     num(size[n.axis], 3) + "); the median photon " + std::to_string(median) +
                     " splits at " + axis_name(n.axis) + " = " + num(n.split, 4) + ", " +
                     std::to_string(n.m - n.lo) + " photons left, " +
                     std::to_string(n.hi - n.m - 1) + " right.";
    info.math = std::string(axis_name(n.axis)) + " = " + tex(n.split, 4);
    info.vars = {{"node_size", (long long)(n.hi - n.lo)},
                 {"axis", (long long)n.axis},
                 {"split", n.split},
                 {"median", (long long)median},
                 {"left", (long long)(n.m - n.lo)},
                 {"right", (long long)(n.hi - n.m - 1)}};
}

void narrate_query(const PhotonMap::State& s, StepInfo& info) {
    const bool full = int(s.heap.size()) == s.k;
    if (s.at < 0) {
        info.event = "prune";
        info.line = 6;
        info.narration = "Skip photons " + std::to_string(s.range.lo) + " to " +
                         std::to_string(s.range.hi - 1) + " of the tree: their splitting plane is " +
                         num(s.range.bound, 4) + " away squared, more than r² = " + num(s.r2, 4) + ".";
        info.math = tex(s.range.bound, 4) + " > r^2 = " + tex(s.r2, 4);
        info.vars = {{"bound", s.range.bound},
                     {"r2", s.r2},
                     {"skipped", (long long)(s.range.hi - s.range.lo)}};
        return;
    }
    info.event = "visit";
    info.line = 5;
    const std::string what = s.replaced ? "nearer than the farthest kept: it replaces it"
                             : s.taken  ? "kept (the heap is not full yet)"
                                        : "not nearer than r²: not kept";
    info.narration = "Visit photon " + std::to_string(s.at) + ": d² = " + num(s.d2, 4) + ", " + what +
                     "; " + std::to_string(s.heap.size()) + " of k = " + std::to_string(s.k) +
                     " kept" + (full ? ", r² = " + num(s.r2, 4) : std::string()) + ".";
    info.math = "d^2 = |x - x_p|^2 = " + tex(s.d2, 4);
    info.vars = {{"photon", (long long)s.at},
                 {"d2", s.d2},
                 {"taken", s.taken},
                 {"found", (long long)s.heap.size()}};
    if (full) info.vars.push_back({"r2", s.r2});
}

void narrate_estimate(const PhotonMap::State& s, StepInfo& info) {
    info.event = "estimate";
    info.line = 7;
    const double r = std::sqrt(s.r2);
    if (s.degenerate) {
        info.narration = s.heap.empty() ? "No photon was stored: there is nothing to estimate from, "
                                          "E is reported as 0."
                                        : "All k nearest photons lie exactly at x (r = 0): the "
                                          "estimate is undefined, E is reported as 0.";
    } else {
        info.narration = "The " + std::to_string(s.heap.size()) + " nearest photons carry Σ Φ_p = " +
                         num(s.sum_power) + " within r = " + num(r, 4) + ": E ≈ " + num(s.sum_power) +
                         " / (π · " + num(s.r2, 4) + ") = " + num(s.irradiance) + ".";
        info.math = "E \\approx \\frac{\\sum \\Phi_p}{\\pi r^2} = \\frac{" + tex(s.sum_power) +
                    "}{\\pi \\cdot " + tex(s.r2, 4) + "} = " + tex(s.irradiance);
    }
    info.vars = {{"k", (long long)s.heap.size()},
                 {"r", r},
                 {"sum_power", s.sum_power},
                 {"E", s.irradiance}};
}

}  // namespace

void PhotonMap::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Emit:
            if (s.batch_first + 1 == s.emitted && s.batch_first < kOneByOne)
                narrate_photon(s, info);
            else
                narrate_batch(s, info);
            break;
        case Phase::Build: narrate_node(s, info); break;
        case Phase::Query: narrate_query(s, info); break;
        case Phase::Estimate:
        case Phase::Done: narrate_estimate(s, info); break;
    }
}

}  // namespace cg
