// The state machines' cost against their plain functions, from one `cgbench` run's JSON
// (`--benchmark_out`): every benchmark named ..._Plain... is paired with the same name with
// _StateMachine in its place, or, when there is none, with the one-thread variant's name less
// its "/1" (BM_RayTracer_Plain/1/real_time ↔ BM_RayTracer_StateMachine/real_time). Medians
// when the run repeated (--benchmark_repetitions), the single figure otherwise; CPU time, or
// wall time for the benchmarks measured in real time. `make bench` prints this table last.
//
//   cgbench_ratios FILE.json [LIMIT]    exit 1 if a ratio passes LIMIT (default: report only)
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

struct Figure {
    double time = 0;  // in the benchmark's own unit
    std::string unit;
};

// run_name → figure: the median of a repeated run, or the single iteration row; `order`
// lists the names as the run met them.
std::map<std::string, Figure> read_figures(const nlohmann::json& doc, std::vector<std::string>& order) {
    std::map<std::string, Figure> single, median;
    std::set<std::string> seen;
    for (const auto& b : doc.at("benchmarks")) {
        const std::string name = b.value("run_name", b.value("name", ""));
        const bool real = name.find("real_time") != std::string::npos;
        const Figure f{b.at(real ? "real_time" : "cpu_time").get<double>(), b.value("time_unit", "ns")};
        if (seen.insert(name).second) order.push_back(name);
        if (b.value("run_type", "iteration") != "aggregate")
            single.emplace(name, f);
        else if (b.value("aggregate_name", "") == "median")
            median[name] = f;
    }
    for (auto& [name, f] : median) single[name] = f;
    return single;
}

double in_ms(const Figure& f) {
    const double scale = f.unit == "ns" ? 1e-6 : f.unit == "us" ? 1e-3 : f.unit == "s" ? 1e3 : 1;
    return f.time * scale;
}

// The state machine's benchmark for a plain one, or "" if it has none.
std::string partner(const std::string& plain, const std::map<std::string, Figure>& figures) {
    const auto at = plain.find("_Plain");
    std::string sm = plain;
    sm.replace(at, 6, "_StateMachine");
    if (figures.count(sm)) return sm;
    // The one-thread run of a benchmark that also runs on two: drop its "/1".
    for (std::size_t p = sm.find('/'); p != std::string::npos; p = sm.find('/', p + 1))
        if (sm.compare(p, 3, "/1/") == 0 || (sm.compare(p, 2, "/1") == 0 && p + 2 == sm.size())) {
            std::string less = sm;
            less.erase(p, 2);
            if (figures.count(less)) return less;
        }
    return "";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: cgbench_ratios FILE.json [LIMIT]\n");
        return 2;
    }
    std::ifstream file(argv[1]);
    if (!file) {
        std::fprintf(stderr, "cgbench_ratios: cannot read %s\n", argv[1]);
        return 2;
    }
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(file);
        std::vector<std::string> order;
        const auto figures = read_figures(doc, order);
        const double limit = argc > 2 ? std::stod(argv[2]) : 0;
        int pairs = 0, over = 0;
        double worst = 0;
        std::printf("\nState machine run to the end against the plain function (%s):\n\n",
                    figures.empty() ? "no figures" : "medians where repeated");
        std::printf("| benchmark | plain | state machine | ratio |\n|---|---|---|---|\n");
        for (const auto& name : order) {
            if (name.find("_Plain") == std::string::npos) continue;
            const std::string sm = partner(name, figures);
            if (sm.empty()) continue;
            const double a = in_ms(figures.at(name)), b = in_ms(figures.at(sm));
            const double ratio = b / a;
            ++pairs;
            worst = std::max(worst, ratio);
            const bool bad = limit > 0 && ratio > limit;
            over += bad;
            std::printf("| %s | %.3g ms | %.3g ms | %.2f×%s |\n", name.c_str(), a, b, ratio,
                        bad ? " ⚠" : "");
        }
        std::printf("\n%d pairs, the highest ratio %.2f×", pairs, worst);
        if (limit > 0) std::printf(", %d over %.2f×", over, limit);
        std::printf("\n");
        return over ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cgbench_ratios: %s: %s\n", argv[1], e.what());
        return 2;
    }
}
