// The cost comparison of the hidden-surface algorithms, plotted: the counts that
// `cgsandbox complexity hsr` prints, against the growth the course states for each —
// the painter's pair tests like n², Warnock's classifications like p·n in the worst case, the
// z-buffer's depth compares like p_c + n. Shown under the Algorithm tab for the HSR
// algorithms; computed once per session, on demand (a few hundred milliseconds). For the
// acceleration structures the same plot shows `cgsandbox complexity accel`: tests per ray for
// brute force, the BVH and the uniform grid against n, with n and log2 n as guides.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "accel/complexity.hpp"
#include "hsr/complexity.hpp"
#include "viewer/im_colour.hpp"
#include "viewer/palette.hpp"
#include "viewer/panels.hpp"

namespace cg::viewer {

namespace {

constexpr long long kSide = 32;  // the screen: 32 × 32 pixels
constexpr int kTrials = 3;

template <class Row>
struct Series {
    const char* name;
    std::uint32_t rgba;
    double (*value)(const Row&);
    bool dashed;
};

double per_trial(long long v, const hsr::ComplexityRow& r) { return static_cast<double>(v) / r.trials; }

const Series<hsr::ComplexityRow> kSeries[] = {
    {"painter's pair tests", 0xd62728ff,
     [](const hsr::ComplexityRow& r) { return per_trial(r.painter_pair_tests, r); }, false},
    {"Warnock classifications", 0x1f77b4ff,
     [](const hsr::ComplexityRow& r) { return per_trial(r.classifications, r); }, false},
    {"z-buffer depth compares", 0x2ca02cff,
     [](const hsr::ComplexityRow& r) { return per_trial(r.compares, r); }, false},
    {"n²", 0xd62728ff, [](const hsr::ComplexityRow& r) { return double(r.n) * r.n; }, true},
    {"p·n", 0x1f77b4ff, [](const hsr::ComplexityRow& r) { return double(r.p) * r.n; }, true},
    {"p_c + n", 0x2ca02cff,
     [](const hsr::ComplexityRow& r) { return per_trial(r.p_c, r) + r.n; }, true},
};

// The acceleration structures: mean tests per ray on random scenes (accel/complexity.hpp).
const Series<accel::ComplexityRow> kAccelSeries[] = {
    {"BVH: box tests", 0x1f77b4ff,
     [](const accel::ComplexityRow& r) { return r.per_ray(r.bvh_box_tests); }, false},
    {"BVH: primitive tests", 0x17becfff,
     [](const accel::ComplexityRow& r) { return r.per_ray(r.bvh_primitive_tests); }, false},
    {"grid: cells visited", 0x2ca02cff,
     [](const accel::ComplexityRow& r) { return r.per_ray(r.grid_cells); }, false},
    {"grid: primitive tests", 0x9467bdff,
     [](const accel::ComplexityRow& r) { return r.per_ray(r.grid_primitive_tests); }, false},
    {"O(n): n, brute force's tests", 0xd62728ff,
     [](const accel::ComplexityRow& r) { return double(r.n); }, true},
    {"O(log n): log2 n", 0x555555ff,
     [](const accel::ComplexityRow& r) { return std::log2(double(r.n)); }, true},
};

// n as a tick label: 1e3, 1e4, … for a power of ten from 1000 on (longer numbers overlap).
std::string n_label(int n) {
    const int e = static_cast<int>(std::lround(std::log10(std::max(n, 1))));
    return n >= 1000 && std::pow(10.0, e) == n ? "1e" + std::to_string(e) : std::to_string(n);
}

// A log-log plot: x = n, y = count, each series a polyline; dashed ones are the course's bounds.
template <class Row, std::size_t N>
void plot(const std::vector<Row>& rows, const Series<Row> (&series)[N]) {
    const float width = ImGui::GetContentRegionAvail().x, height = width * 0.75f;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(width, height));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32_WHITE);
    const float left = 34, bottom = 18, pad = 6;
    double ymax = 1;
    for (const auto& r : rows)
        for (const Series<Row>& s : series) ymax = std::max(ymax, s.value(r));
    const double xmin = std::log10(std::max(1, rows.front().n)), xmax = std::log10(rows.back().n);
    const double ytop = std::ceil(std::log10(ymax));
    auto to_screen = [&](double n, double v) {
        const double x = (std::log10(n) - xmin) / std::max(xmax - xmin, 1e-9);
        const double y = std::log10(std::max(v, 1.0)) / std::max(ytop, 1.0);
        return ImVec2(origin.x + left + static_cast<float>(x) * (width - left - pad),
                      origin.y + height - bottom - static_cast<float>(y) * (height - bottom - pad));
    };
    // Decades on y, the measured n on x.
    for (int d = 0; d <= static_cast<int>(ytop); ++d) {
        const ImVec2 a = to_screen(rows.front().n, std::pow(10.0, d));
        dl->AddLine(ImVec2(origin.x + left, a.y), ImVec2(origin.x + width - pad, a.y),
                    im_colour(kGridMajor));
        const std::string label = "1e" + std::to_string(d);
        dl->AddText(ImVec2(origin.x + 2, a.y - 7), im_colour(kTickLabel), label.c_str());
    }
    for (const auto& r : rows) {
        const ImVec2 a = to_screen(r.n, 1);
        dl->AddLine(ImVec2(a.x, origin.y + pad), ImVec2(a.x, a.y), im_colour(kGridMinor));
        dl->AddText(ImVec2(a.x - 4, a.y + 2), im_colour(kTickLabel), n_label(r.n).c_str());
    }
    for (const Series<Row>& s : series) {
        for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
            const ImVec2 a = to_screen(rows[i].n, s.value(rows[i]));
            const ImVec2 b = to_screen(rows[i + 1].n, s.value(rows[i + 1]));
            if (!s.dashed) {
                dl->AddLine(a, b, im_colour(s.rgba), 2.5f);
                dl->AddCircleFilled(a, 3.0f, im_colour(s.rgba));
                dl->AddCircleFilled(b, 3.0f, im_colour(s.rgba));
            } else {
                for (float t = 0; t < 1; t += 0.2f) {
                    const float u = std::min(t + 0.1f, 1.0f);
                    dl->AddLine(ImVec2(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t),
                                ImVec2(a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u),
                                im_colour(with_alpha(s.rgba, 0x90)), 1.5f);
                }
            }
        }
    }
}

template <class Row, std::size_t N>
void legend(const Series<Row> (&series)[N]) {
    for (const Series<Row>& item : series) {
        ImGui::PushStyleColor(ImGuiCol_Text, im_vec4(darker(item.rgba, 0.85f)));
        ImGui::TextUnformatted((std::string(item.dashed ? "- - " : "—— ") + item.name).c_str());
        ImGui::PopStyleColor();
    }
}

void draw_accel_costs(Session& s) {
    if (!ImGui::CollapsingHeader("What each structure costs")) return;
    if (s.accel_costs.empty()) {
        // n = 10 … 10⁵ primitives, 300 rays each (about half a second; 10⁶ is the CLI's).
        s.accel_costs = accel::complexity({10, 100, 1000, 10000, 100000}, 300, 1, 0);
    }
    ImGui::TextWrapped(
        "Mean tests per ray on random scenes of n spheres and triangles in a cube "
        "(300 rays), log-log; dashed: the guides O(n) and O(log n). Measure up "
        "to 10^6 with `cgsandbox complexity accel`.");
    plot(s.accel_costs, kAccelSeries);
    legend(kAccelSeries);
    if (ImGui::BeginTable("accel costs", 5,
                          ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
        for (const char* h : {"n", "BVH box", "BVH prim.", "grid cells", "grid prim."})
            ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (const auto& r : s.accel_costs) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn(), ImGui::TextUnformatted(n_label(r.n).c_str());
            for (int k = 0; k < 4; ++k)
                ImGui::TableNextColumn(), ImGui::Text("%.1f", kAccelSeries[k].value(r));
        }
        ImGui::EndTable();
    }
}

}  // namespace

void draw_costs_panel(Session& s) {
    if (s.algorithm && s.algorithm->spec->topic == "Bounding Boxes and Spatial Subdivision") {
        draw_accel_costs(s);
        return;
    }
    if (!s.algorithm || s.algorithm->spec->topic != "Hidden Surface Removal") return;
    if (!ImGui::CollapsingHeader("What each algorithm costs")) return;
    if (s.hsr_costs.empty()) {
        // Random scenes on a 32 × 32 screen, n = 1 … 32 polygons, three scenes each.
        s.hsr_costs = hsr::complexity({kSide}, {1, 2, 4, 8, 16, 32}, kTrials, 1);
    }
    ImGui::TextWrapped("Counts of each algorithm's basic operation on random scenes (32 × 32 "
                       "pixels, mean of %d), log-log; dashed: the growth the course states.",
                       kTrials);
    plot(s.hsr_costs, kSeries);
    legend(kSeries);
    if (ImGui::BeginTable("costs", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
        for (const char* h : {"n", "pair tests", "classif.", "compares"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (const auto& r : s.hsr_costs) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn(), ImGui::Text("%d", r.n);
            ImGui::TableNextColumn(), ImGui::Text("%.0f", kSeries[0].value(r));
            ImGui::TableNextColumn(), ImGui::Text("%.0f", kSeries[1].value(r));
            ImGui::TableNextColumn(), ImGui::Text("%.0f", kSeries[2].value(r));
        }
        ImGui::EndTable();
    }
}

}  // namespace cg::viewer
