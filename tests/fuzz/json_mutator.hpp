// Structure-aware mutation of JSON inputs (issue 25).
//
// libFuzzer's own mutations flip bytes: on a JSON input almost every one breaks the syntax or
// a field's type, so nearly all executions stop in the reader or the validator and few reach
// an algorithm. These mutations parse the document and change it within its shape, the way a
// student's typo or an unlucky scene would:
//   numbers   nudged (a relative 1e-3, a last-place step), rounded, scaled (×2, ×½, ×−1,
//             ×10, ×0.1), set to a boundary value (0, ±1, ±1e-300, ±1e300, 1e-12) or made
//             equal to another number of the document; integers stay integers
//   arrays    an element duplicated, removed, swapped with another, the order reversed; in
//             a list of points one point moved onto another (coincident) or onto the line
//             through two others (collinear)
//   strings   replaced by another string of the document (an enum's other value, often)
//   booleans  flipped
//   objects   now and then a field dropped (the "missing field" error path stays covered)
// and writes the document back. Crossing two documents grafts the value at a path both have.
// Pure functions of (text, seed): the fuzz targets call them from LLVMFuzzerCustomMutator
// and LLVMFuzzerCustomCrossOver, and the normal test suite measures how often the mutations
// of every algorithm's example still pass validation (tests/robustness/test_json_mutator.cpp).
#pragma once

#include <cmath>
#include <cstring>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "io/json.hpp"

namespace cg::fuzz {

namespace json_mutator_detail {

struct Nodes {
    std::vector<json*> numbers, arrays, strings, booleans, objects;
    std::vector<std::pair<std::string, json*>> paths;  // every node by its JSON pointer
};

inline void collect(json& j, const std::string& path, Nodes& n) {
    n.paths.emplace_back(path, &j);
    if (j.is_number()) n.numbers.push_back(&j);
    else if (j.is_string()) n.strings.push_back(&j);
    else if (j.is_boolean()) n.booleans.push_back(&j);
    else if (j.is_array()) {
        n.arrays.push_back(&j);
        for (std::size_t i = 0; i < j.size(); ++i) collect(j[i], path + "/" + std::to_string(i), n);
    } else if (j.is_object()) {
        n.objects.push_back(&j);
        for (auto& [key, value] : j.items()) collect(value, path + "/" + key, n);
    }
}

template <class T>
T& pick(std::vector<T>& v, Rng& rng) {
    return v[static_cast<std::size_t>(rng.integer(0, static_cast<long long>(v.size()) - 1))];
}

// A point: an array of 2 to 4 numbers.
inline bool is_point(const json& j) {
    if (!j.is_array() || j.size() < 2 || j.size() > 4) return false;
    for (const auto& x : j) if (!x.is_number()) return false;
    return true;
}

inline void mutate_integer(json& n, Rng& rng, Nodes& all) {
    const long long v = n.get<long long>();
    switch (rng.integer(0, 7)) {
        case 0: n = v + 1; break;
        case 1: n = v - 1; break;
        case 2: n = v * 2; break;
        case 3: n = v / 2; break;
        case 4: n = -v; break;
        case 5: n = rng.integer(0, 3); break;
        case 6: n = rng.chance(0.5) ? -1 : 1000000; break;
        default: {  // another integer of the document
            const json& other = *pick(all.numbers, rng);
            if (other.is_number_integer()) n = other;
            else n = v + 1;
        }
    }
}

inline void mutate_float(json& n, Rng& rng, Nodes& all) {
    const double v = n.get<double>();
    static constexpr double kBoundary[] = {0.0, 1.0, -1.0, 1e-300, -1e-300, 1e300, -1e300, 1e-12, 0.5};
    double w = v;
    switch (rng.integer(0, 9)) {
        case 0: case 1: w = v + (v == 0 ? 1e-3 : v * rng.uniform(-1e-3, 1e-3)); break;
        case 2: w = std::nextafter(v, rng.chance(0.5) ? HUGE_VAL : -HUGE_VAL); break;
        case 3: w = rng.chance(0.5) ? std::round(v) : std::round(v * 10) / 10; break;
        case 4: {
            static constexpr double kScale[] = {2.0, 0.5, -1.0, 10.0, 0.1};
            w = v * kScale[rng.integer(0, 4)];
            break;
        }
        case 5: w = kBoundary[rng.integer(0, 8)]; break;
        case 6: case 7: w = pick(all.numbers, rng)->get<double>(); break;  // equal to another
        default: w = rng.uniform(-std::fabs(v) - 1, std::fabs(v) + 1);
    }
    n = std::isfinite(w) ? w : v;
}

inline void mutate_number(json& n, Rng& rng, Nodes& all) {
    // Integer arithmetic only well inside the range: v + 1 or 2v on the largest integers
    // would overflow (undefined behaviour, which the sanitizer build would report as a find).
    constexpr long long kLimit = 1LL << 52;
    const bool small = n.is_number_unsigned()
                           ? n.get<unsigned long long>() < static_cast<unsigned long long>(kLimit)
                           : n.is_number_integer() && n.get<long long>() > -kLimit &&
                                 n.get<long long>() < kLimit;
    if (small && rng.chance(0.9)) mutate_integer(n, rng, all);
    else mutate_float(n, rng, all);
}

inline void mutate_points(json& a, Rng& rng) {
    const long long last = static_cast<long long>(a.size()) - 1;
    const auto i = static_cast<std::size_t>(rng.integer(0, last));
    const auto j = static_cast<std::size_t>(rng.integer(0, last));
    const auto k = static_cast<std::size_t>(rng.integer(0, last));
    if (a[i].size() != a[j].size() || a[i].size() != a[k].size()) return;
    if (rng.chance(0.5)) {  // coincident
        a[k] = a[i];
        return;
    }
    static constexpr double kT[] = {0.5, 2.0, -1.0, 1e-9};
    const double t = rng.chance(0.5) ? kT[rng.integer(0, 3)] : rng.uniform(-2, 3);
    for (std::size_t c = 0; c < a[k].size(); ++c) {  // collinear with i and j
        const double p = a[i][c].get<double>(), q = a[j][c].get<double>();
        if (const double x = p + t * (q - p); std::isfinite(x)) a[k][c] = x;
    }
}

inline void mutate_array(json& a, Rng& rng) {
    if (a.empty()) return;
    bool points = a.size() >= 2;
    for (const auto& e : a) points = points && is_point(e);
    const long long last = static_cast<long long>(a.size()) - 1;
    const auto i = static_cast<std::size_t>(rng.integer(0, last));
    const auto j = static_cast<std::size_t>(rng.integer(0, last));
    switch (rng.integer(0, points ? 5 : 3)) {
        case 0: a.insert(a.begin() + static_cast<long>(i), a[i]); break;  // duplicate
        case 1: a.erase(a.begin() + static_cast<long>(i)); break;
        case 2: std::swap(a[i], a[j]); break;
        case 3: {
            json r = json::array();
            for (auto it = a.rbegin(); it != a.rend(); ++it) r.push_back(*it);
            a = std::move(r);
            break;
        }
        default: mutate_points(a, rng);
    }
}

}  // namespace json_mutator_detail

// `text` changed within its shape; none when it is not a JSON document.
inline std::optional<std::string> mutate_json(const std::string& text, std::uint64_t seed) {
    namespace d = json_mutator_detail;
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception&) {
        return std::nullopt;
    }
    Rng rng(seed);
    const int count = 1 + static_cast<int>(rng.integer(0, 2)) / 2;  // 1, 1 or 2 changes
    for (int c = 0; c < count; ++c) {
        d::Nodes n;
        d::collect(doc, "", n);
        const double kind = rng.uniform(0, 1);
        if (kind < 0.60 && !n.numbers.empty()) d::mutate_number(*d::pick(n.numbers, rng), rng, n);
        else if (kind < 0.82 && !n.arrays.empty()) d::mutate_array(*d::pick(n.arrays, rng), rng);
        else if (kind < 0.90 && !n.strings.empty()) {
            const json other = *d::pick(n.strings, rng);
            *d::pick(n.strings, rng) = other;
        }
        else if (kind < 0.95 && !n.booleans.empty()) {
            json& b = *d::pick(n.booleans, rng);
            b = !b.get<bool>();
        } else if (!n.objects.empty()) {
            json& o = *d::pick(n.objects, rng);
            if (!o.empty()) {
                auto it = o.begin();
                std::advance(it, rng.integer(0, static_cast<long long>(o.size()) - 1));
                o.erase(it.key());
            }
        }
    }
    return doc.dump();
}

// `a` with the value at one path that both documents have replaced by b's; none when either
// is not JSON or they share no path but the root.
inline std::optional<std::string> cross_json(const std::string& a, const std::string& b,
                                             std::uint64_t seed) {
    namespace d = json_mutator_detail;
    json x, y;
    try {
        x = json::parse(a);
        y = json::parse(b);
    } catch (const json::exception&) {
        return std::nullopt;
    }
    d::Nodes nx, ny;
    d::collect(x, "", nx);
    d::collect(y, "", ny);
    std::unordered_map<std::string, json*> in_b(ny.paths.begin(), ny.paths.end());
    std::vector<std::pair<json*, json*>> common;
    for (auto& [path, node] : nx.paths) {
        const auto it = path.empty() ? in_b.end() : in_b.find(path);
        if (it != in_b.end() && node->type() == it->second->type() && *node != *it->second)
            common.emplace_back(node, it->second);
    }
    if (common.empty()) return std::nullopt;
    Rng rng(seed);
    auto [to, from] = d::pick(common, rng);
    *to = *from;
    return x.dump();
}

}  // namespace cg::fuzz

// ---- libFuzzer plumbing ---------------------------------------------------------------------
// A target whose inputs are `prefix` bytes (fuzz_algorithm_input's algorithm byte) and then a
// JSON document gets both hooks with one line: CG_FUZZ_JSON_MUTATOR(prefix, accept).

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace cg::fuzz {

// `accept` (or null) says whether a mutant passes validation: the first of four tries that
// does is kept, else the last. One time in sixteen, and for inputs that are not JSON,
// libFuzzer's own byte mutations run instead, so the reader's syntax errors stay covered.
inline std::size_t mutate_prefixed(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                   unsigned seed, std::size_t prefix,
                                   bool (*accept)(const std::uint8_t*, std::size_t)) {
    Rng rng(seed);
    if (size <= prefix || rng.chance(1.0 / 16)) return LLVMFuzzerMutate(data, size, max_size);
    const std::string head(reinterpret_cast<const char*>(data), prefix);
    const std::string text(reinterpret_cast<const char*>(data) + prefix, size - prefix);
    std::string out;
    for (int attempt = 0; attempt < 4; ++attempt) {
        const auto m = mutate_json(text, rng.next());
        if (!m) return LLVMFuzzerMutate(data, size, max_size);
        if (prefix + m->size() > max_size) continue;
        out = head + *m;
        if (!accept || accept(reinterpret_cast<const std::uint8_t*>(out.data()), out.size())) break;
    }
    if (out.empty()) return LLVMFuzzerMutate(data, size, max_size);
    std::memcpy(data, out.data(), out.size());
    return out.size();
}

// Two inputs with the same prefix (the same algorithm) crossed as JSON; 0 (no crossing) else.
inline std::size_t cross_prefixed(const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b,
                                  std::size_t b_size, std::uint8_t* out, std::size_t max_out,
                                  unsigned seed, std::size_t prefix) {
    if (a_size <= prefix || b_size <= prefix || std::memcmp(a, b, prefix) != 0) return 0;
    const auto m = cross_json(std::string(reinterpret_cast<const char*>(a) + prefix, a_size - prefix),
                              std::string(reinterpret_cast<const char*>(b) + prefix, b_size - prefix), seed);
    if (!m || prefix + m->size() > max_out) return 0;
    std::memcpy(out, a, prefix);
    std::memcpy(out + prefix, m->data(), m->size());
    return prefix + m->size();
}

}  // namespace cg::fuzz

#define CG_FUZZ_JSON_MUTATOR(prefix, accept)                                                      \
    extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,         \
                                                   std::size_t max_size, unsigned int seed) {    \
        return cg::fuzz::mutate_prefixed(data, size, max_size, seed, prefix, accept);             \
    }                                                                                             \
    extern "C" std::size_t LLVMFuzzerCustomCrossOver(                                            \
        const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b, std::size_t b_size,     \
        std::uint8_t* out, std::size_t max_out, unsigned int seed) {                              \
        return cg::fuzz::cross_prefixed(a, a_size, b, b_size, out, max_out, seed, prefix);        \
    }
