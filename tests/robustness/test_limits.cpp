// Long and hostile runs: inputs that would exhaust the machine are refused with a message that
// names the limit, and a run of a million steps with big states keeps to the timeline's budget.
#include <catch2/catch.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/timeline.hpp"
#include "io/registry.hpp"
#include "support/process.hpp"

using cg::json;
using cg::test::cgsandbox;

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// Runs `cgsandbox run id --input FILE` on text and checks a one-line refusal containing `expected`.
void check_refused(const std::string& id, const std::string& text, const std::string& expected) {
    const std::string path = cg::test::write_temp("hostile.json", text);
    auto r = cgsandbox({"run", id, "--input", path});
    std::filesystem::remove(path);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
    CHECK(lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::StartsWith("cgsandbox: " + path + ": ") && Catch::Contains(expected));
}

std::string square(double x, double y, double z) {
    auto v = [&](double a, double b) { return "[" + std::to_string(a) + "," + std::to_string(b) + "," + std::to_string(z) + "]"; };
    return R"({"vertices":[)" + v(x, y) + "," + v(x + 1, y) + "," + v(x + 1, y + 1) + "," + v(x, y + 1) +
           R"(],"color":[0.5,0.5,0.5]})";
}

}  // namespace

TEST_CASE("limits: nesting a million lists deep is refused at the limit of 256", "[robustness][limits]") {
    const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
    check_refused("liang-barsky",
                  R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p1": [4, 6], "p0": )" + deep + "}",
                  "nested more than 256 lists or objects deep (the limit)");
    // The field is named, down to where the limit was hit.
    check_refused("liang-barsky", R"({"p0": )" + deep + "}", "p0[0][0][0]");
    // Lessons and checkpoints go through the same parser.
    CHECK_THROWS_WITH(cg::parse_json(R"({"input": )" + deep + "}"),
                      Catch::StartsWith("input[0][0]") && Catch::Contains("(the limit)"));
}

TEST_CASE("limits: a file of more than ten million values is refused", "[robustness][limits]") {
    std::string text = R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6], "points": [)";
    text.reserve(text.size() + 20'000'010);
    for (int i = 0; i < 10'000'001; ++i) text += i ? ",0" : "0";
    text += "]}";
    check_refused("liang-barsky", text, ": more than 10000000 values in one file (the limit)");
    check_refused("liang-barsky", text, ": points[99999");
}

TEST_CASE("limits: an input file larger than 128 MiB is refused before it fills the memory", "[robustness][limits]") {
    const std::string path = cg::test::output_path("huge-input.json");
    {
        std::ofstream f(path, std::ios::binary);
        const std::string spaces(1 << 20, ' ');
        for (int i = 0; i < 129; ++i) f << spaces;
        f << "{}";
    }
    auto r = cgsandbox({"run", "liang-barsky", "--input", path});
    std::filesystem::remove(path);
    CHECK(r.exit_code == 2);
    CHECK(r.err == "cgsandbox: " + path + ": the file is larger than 128 MiB (the limit for input files)\n");
}

TEST_CASE("limits: more polygons than the hidden-surface limit are refused, naming it", "[robustness][limits]") {
    // Ten million polygons would be refused the same way (and by the file limits above before
    // that); 10 001 shows the count check without writing hundreds of megabytes.
    std::string polygons;
    for (int k = 0; k < 10'001; ++k) polygons += (k ? "," : "") + square(k % 7, k % 5, 1 + k % 11);
    for (const char* id : {"z-buffer", "warnock"}) {
        CAPTURE(id);
        check_refused(id, R"({"width": 8, "height": 8, "polygons": [)" + polygons + "]}",
                      "polygons: at most 10000 polygons (the limit; got 10001)");
    }
}

TEST_CASE("limits: a 10^9-pixel image is refused by every algorithm with a pixel grid", "[robustness][limits]") {
    const std::string tri = R"("triangle": [[1, 1], [5, 1], [3, 4]])";
    check_refused("scan-triangle", R"({"width": 31623, "height": 31623, )" + tri + "}",
                  "width: must be a whole number of pixels from 1 to 4096");
    for (const char* id : {"z-buffer", "warnock"}) {
        CAPTURE(id);
        check_refused(id, R"({"width": 31623, "height": 31623, "polygons": [)" + square(1, 1, 1) + "]}",
                      "width: must be a whole number of pixels from 1 to 1024 (the limit; got 31623)");
    }
}

TEST_CASE("limits: a million z-buffer steps on 12 MB states keep the timeline within its byte budget", "[robustness][limits]") {
    // Pixel by pixel over a 1024 x 1024 screen covered by one polygon: a step per pixel, and every
    // state holds the whole colour and depth buffers.
    const cg::Algorithm& zb = *registry().find("z-buffer");
    const json input = json::parse(R"({"width": 1024, "height": 1024, "granularity": "pixel", "polygons": [
        {"vertices": [[-1, -1, 5], [1025, -1, 5], [1025, 1025, 6], [-1, 1025, 6]], "color": [1, 0, 0]}]})");
    const std::size_t budget = std::size_t{128} << 20;
    cg::Timeline t(zb.create(input), 50'000'000, budget);
    REQUIRE(t.forward());  // the first step clears the buffers: from then on they are full size
    const std::size_t state = t.current().bytes();
    CHECK(state > 12'000'000);
    const std::size_t bound = budget + 2 * state;
    t.to_end();
    CAPTURE(t.index(), t.stride(), t.stored_states(), t.stored_bytes());
    CHECK(t.index() > 1'000'000);
    CHECK(t.current().done());
    CHECK(t.stored_bytes() <= bound);
    for (int i = 0; i < 50; ++i) REQUIRE(t.back());
    t.jump(t.index() / 2);
    CHECK(t.stored_bytes() <= bound);
    // Without the budget the ~sqrt(n) states kept would be 2000+ of these: over 25 GB.
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    CHECK(usage.ru_maxrss < 3L * 1024 * 1024);  // kB: under 3 GB even with sanitizer overheads
}
