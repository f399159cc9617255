// Form factor, JSON:
//   input  {"from": patch, "to": patch,
//           "hemicube": {"resolution": R (even, 2..128; default 8), "samples": m (1..8, default
//           3)}, "monte_carlo": {"rays": N (1..10^6, default 1000), "seed": s (default 1)},
//           "enclosure": [patch, ...] (optional: the rest of a closed enclosure, for the row sum)}
//   patch  {"type": "rectangle", "corner": [x, y, z], "edge_u": [..], "edge_v": [..]}
//            (normal u × v; the edges perpendicular)
//        | {"type": "disc", "center": [..], "normal": [..], "radius": r}
//        | {"type": "triangle", "points": [[..], [..], [..]]}   (normal (p1 − p0) × (p2 − p0))
//        | {"type": "point", "center": [..], "normal": [..]}     (a differential area dA; "from"
//        only)
//   result {"area_from", "area_to", "analytic": F | null, "analytic_case", "hemicube",
//           "monte_carlo", "monte_carlo_std_error",
//           "errors": {"hemicube", "monte_carlo", "monte_carlo_in_std_errors"} (null without
//           analytic), "reciprocity": {"A_i_F_ij", "F_ji_expected", "F_ji_analytic",
//           "F_ji_hemicube",
//                           "F_ji_monte_carlo"} | null (for a point),
//           "row_sum": {"analytic", "hemicube", "monte_carlo", "hemicube_terms",
//                       "monte_carlo_terms"} | null (without an enclosure)}
#include <limits>

#include "io/registry.hpp"
#include "radiosity/form_factor.hpp"
#include "radiosity/patch_json.hpp"

namespace cg {

namespace {

json opt(const std::optional<double>& v) {
    return v ? json(*v) : json(nullptr);
}

}  // namespace

template <>
struct JsonIo<FormFactor> {
    static FormFactor::Input input(const json& j) {
        Reader r(j);
        r.only({"from", "to", "hemicube", "monte_carlo", "enclosure"});
        FormFactor::Input in;
        in.from = read_patch(r.object("from"));
        in.to = read_patch(r.object("to"));
        if (r.has("hemicube")) {
            const Reader h = r.object("hemicube");
            h.only({"resolution", "samples"});
            if (h.has("resolution"))
                in.resolution = int(h.integer("resolution", 2, FormFactor::kMaxResolution,
                                            "an even number of cells from 2 to 128"));
            if (h.has("samples"))
                in.samples = int(h.integer("samples", 1, FormFactor::kMaxSamples, "from 1 to 8"));
        }
        if (r.has("monte_carlo")) {
            const Reader m = r.object("monte_carlo");
            m.only({"rays", "seed"});
            if (m.has("rays"))
                in.rays = m.integer("rays", 1, FormFactor::kMaxRays, "from 1 to 1000000");
            if (m.has("seed"))
                in.seed = std::uint64_t(m.integer("seed", 0, std::numeric_limits<long long>::max(),
                                                "a non-negative integer"));
        }
        if (r.has("enclosure")) {
            const json& list = r.get("enclosure");
            if (!list.is_array())
                throw InputError(r.field("enclosure"),
                                 "must be a list of patches, got " + describe(list));
            if (list.size() > FormFactor::kMaxEnclosure)
                throw InputError(r.field("enclosure"),
                                 "has " + std::to_string(list.size()) + " patches; at most " +
                                     std::to_string(FormFactor::kMaxEnclosure));
            for (std::size_t i = 0; i < list.size(); ++i)
                in.enclosure.push_back(
                    read_patch(Reader(list[i], element(r.field("enclosure"), i))));
        }
        return in;
    }

    static json input_json(const FormFactor::Input& in) {
        json j{{"from", patch_json(in.from)},
               {"to", patch_json(in.to)},
               {"hemicube", {{"resolution", in.resolution}, {"samples", in.samples}}},
               {"monte_carlo", {{"rays", in.rays}, {"seed", in.seed}}}};
        if (!in.enclosure.empty()) {
            json e = json::array();
            for (const Patch& p : in.enclosure) e.push_back(patch_json(p));
            j["enclosure"] = e;
        }
        return j;
    }

    static json result(const FormFactor::Result& r) {
        json errors{{"hemicube", opt(r.error_hemicube)},
                    {"monte_carlo", opt(r.error_monte_carlo)},
                    {"monte_carlo_in_std_errors", nullptr}};
        if (r.error_monte_carlo && r.monte_carlo_std_error > 0)
            errors["monte_carlo_in_std_errors"] = *r.error_monte_carlo / r.monte_carlo_std_error;
        json recip = nullptr;
        if (r.reciprocity) {
            const auto& q = *r.reciprocity;
            recip = json{{"A_i_F_ij", q.a_i_f_ij},
                         {"F_ji_expected", q.f_ji_expected},
                         {"F_ji_analytic", opt(q.f_ji_analytic)},
                         {"F_ji_hemicube", q.f_ji_hemicube},
                         {"F_ji_monte_carlo", q.f_ji_monte_carlo}};
        }
        json rows = nullptr;
        if (r.row_sum) {
            const auto& q = *r.row_sum;
            rows = json{{"analytic", opt(q.analytic)},
                        {"hemicube", q.hemicube},
                        {"monte_carlo", q.monte_carlo},
                        {"hemicube_terms", q.hemicube_terms},
                        {"monte_carlo_terms", q.monte_carlo_terms}};
        }
        return json{{"area_from", r.area_from},
                    {"area_to", r.area_to},
                    {"analytic", opt(r.analytic)},
                    {"analytic_case", r.analytic_case},
                    {"hemicube", r.hemicube},
                    {"monte_carlo", r.monte_carlo},
                    {"monte_carlo_std_error", r.monte_carlo_std_error},
                    {"errors", errors},
                    {"reciprocity", recip},
                    {"row_sum", rows}};
    }

    static json example() {
        // Two unit squares facing each other at distance 1, a floor and a ceiling (y up; Howell
        // C-11: F = 0.19982).
        return json{{"from",
                     {{"type", "rectangle"},
                      {"corner", {0, 0, 0}},
                      {"edge_u", {1, 0, 0}},
                      {"edge_v", {0, 0, -1}}}},
                    {"to",
                     {{"type", "rectangle"},
                      {"corner", {0, 1, 0}},
                      {"edge_u", {0, 0, -1}},
                      {"edge_v", {1, 0, 0}}}},
                    {"hemicube", {{"resolution", 8}, {"samples", 3}}},
                    {"monte_carlo", {{"rays", 1000}, {"seed", 1}}}};
    }
};

Algorithm form_factor_algorithm() {
    return make_algorithm<FormFactor>(
        [](const FormFactor::Input& in) { return FormFactor::compute(in); });
}

}  // namespace cg
