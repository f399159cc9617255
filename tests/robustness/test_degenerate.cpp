// Degenerate input, algorithm by algorithm, in process and through the CLI as a user reaches
// it: one shared harness (degenerate.hpp) over one table per algorithm (tables/<id>.json), plus
// sweeps that put NaN, infinities and huge and tiny magnitudes into every numeric field of each
// table's base input (in process, the CLI checked to agree on each table's first field).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/scene.hpp"
#include "io/registry.hpp"
#include "robustness/degenerate.hpp"
#include "support/process.hpp"
#include "support/sweep.hpp"

using cg::json;
using cg::test::cgsandbox;

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

const std::vector<cg::test::Table>& tables() {
    static const std::vector<cg::test::Table> t = cg::test::load_tables();
    return t;
}

json base_of(const cg::test::Table& t) {
    if (!t.base.is_null()) return t.base;
    const cg::Algorithm* a = registry().find(t.id);
    return a ? a->example() : json::object();
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }
bool finite(glm::dvec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Where a scene has a non-finite coordinate ("" when it has none).
std::string scene_problem(const cg::Scene& s) {
    for (const auto& p : s.points) if (!finite(p.p)) return "points";
    for (const auto& g : s.segments) if (!finite(g.a) || !finite(g.b)) return "segments";
    for (const auto& p : s.polygons)
        for (auto q : p.points) if (!finite(q)) return "polygons";
    for (const auto& h : s.half_planes) if (!finite(h.point) || !finite(h.inward)) return "half_planes";
    for (const auto& l : s.labels) if (!finite(l.p)) return "labels";
    for (const auto& h : s.handles) if (!finite(h.p)) return "handles";
    for (const auto& p : s.points3) if (!finite(p.p)) return "points3";
    for (const auto& g : s.segments3) if (!finite(g.a) || !finite(g.b)) return "segments3";
    for (const auto& f : s.faces3)
        for (auto q : f.points) if (!finite(q)) return "faces3";
    for (const auto& l : s.labels3) if (!finite(l.p)) return "labels3";
    return "";
}

// Runs an accepted input in process as the viewer does: every step narrated and drawn. Returns
// what is wrong ("" when nothing): a non-finite number in a step's variables, the picture or
// the result, or a run that does not end. The result, when asked for, goes to *result.
std::string run_clean(const cg::Algorithm& a, const json& input, json* result = nullptr) {
    auto run = a.create(input);
    constexpr std::size_t kCap = 200'000;
    std::size_t steps = 0;
    for (; !run->done() && steps < kCap; ++steps) {
        cg::StepInfo info;
        run->step(&info);
        auto bad = cg::test::non_finite(cg::step_to_json(steps + 1, info));
        if (!bad.empty()) return "step " + std::to_string(steps + 1) + ": " + bad.front() + " is not finite";
        cg::Scene scene;
        run->draw(scene);
        if (auto p = scene_problem(scene); !p.empty())
            return "step " + std::to_string(steps + 1) + ": the picture's " + p + " are not finite";
    }
    if (!run->done()) return "no end after " + std::to_string(kCap) + " steps";
    const json r = a.result(*run);
    if (result) *result = r;
    auto bad = cg::test::non_finite(r);
    return bad.empty() ? "" : "result" + bad.front() + " is not finite";
}

// What `cgsandbox run` reports for an input text after "cgsandbox: FILE: " ("" when it runs).
std::string run_error(const cg::Algorithm& a, const std::string& text) {
    try {
        a.create(cg::parse_json(text));
        return "";
    } catch (const cg::InputError& e) {
        return e.what();
    }
}

// The same input through the CLI agrees with the in-process outcome (`error`, "" when it runs):
// exactly that error after "cgsandbox: FILE: " and exit 2, or one line of result and exit 0.
// Returns what it printed on stdout.
std::string check_cli_agrees(const cg::Algorithm& a, const std::string& text, const std::string& error) {
    const std::string path = cg::test::write_temp("cli.json", text);
    auto r = cgsandbox({"run", a.spec->id, "--input", path});
    CAPTURE(r.exit_code, r.out, r.err);
    if (error.empty()) {
        CHECK(r.exit_code == 0);
        CHECK(r.err.empty());
        CHECK(lines(r.out) == 1);
    } else {
        CHECK(r.exit_code == 2);
        CHECK(r.out.empty());
        CHECK(r.err == "cgsandbox: " + path + ": " + error + "\n");
    }
    return r.out;
}

// A row's stated result against what a run gave, saying where they differ.
void check_result(const json& expected, const json& actual) {
    std::string why;
    CHECK(cg::test::matches(expected, actual, why));
    CAPTURE(why);
    CHECK(why.empty());
}

}  // namespace

TEST_CASE("robustness: every registered algorithm has a degenerate-input table", "[robustness]") {
    std::set<std::string> have;
    for (const auto& t : tables()) {
        CAPTURE(t.file);
        CHECK(registry().find(t.id) != nullptr);  // a table for an algorithm that is not registered
        CHECK(have.insert(t.id).second);          // two tables for one algorithm
        CHECK(t.file.ends_with("/" + t.id + ".json"));
    }
    for (const cg::Algorithm& a : registry().all()) {
        INFO("add tests/robustness/tables/" << a.spec->id << ".json (format: tests/robustness/degenerate.hpp)");
        CHECK(have.count(a.spec->id) == 1);
    }
}

TEST_CASE("robustness: every table row is well formed and the tables cover the required kinds", "[robustness]") {
    for (const auto& t : tables()) {
        CAPTURE(t.file);
        std::set<std::string> kinds, names;
        REQUIRE(t.rows.is_array());
        for (const json& row : t.rows) {
            CAPTURE(row.dump());
            CHECK(row.value("name", "") != "");
            CHECK(names.insert(row.value("name", "")).second);
            const std::string kind = row.value("kind", "");
            CHECK(std::find(cg::test::kKinds.begin(), cg::test::kKinds.end(), kind) != cg::test::kKinds.end());
            kinds.insert(kind);
            REQUIRE(row.contains("expect"));
            const json& e = row["expect"];
            const bool error = e.contains("error") && e["error"].is_string() && !e["error"].get<std::string>().empty();
            const bool result = e.contains("result") && e["result"].is_object() && !e["result"].empty();
            CHECK(error != result);  // exactly one, and not empty
            for (auto it = row.begin(); it != row.end(); ++it)
                CHECK(std::set<std::string>{"name", "kind", "set", "raw", "remove", "input", "text", "expect"}.count(it.key()) == 1);
        }
        for (const std::string& k : cg::test::kRequiredKinds) {
            CAPTURE(k);
            CHECK(kinds.count(k) == 1);
        }
    }
}

// Every row runs in process, through the same steps as `cgsandbox run`; every third row of each
// table (the first included) also goes through the CLI, whose exit code, stdout and stderr must
// say the same. A process start costs about 0.01 s, but under ASan with leak checking about
// 0.11 s: all 1,800 rows through the CLI took 246 s of the sanitizer suite's 13 minutes.
TEST_CASE("robustness: degenerate rows give their stated outcome, in process and through the CLI", "[robustness]") {
    for (const auto& t : tables()) {
        const cg::Algorithm* a = registry().find(t.id);
        if (!a) continue;  // reported by the test above
        const json base = base_of(t);
        for (std::size_t i = 0; i < t.rows.size(); ++i) {
            const json& row = t.rows[i];
            const std::string name = row.value("name", "");
            // One INFO per row, not a DYNAMIC_SECTION: Catch2 runs a test case once per section,
            // walking every row each time (1,800 rows: 3 million formatted names and table copies).
            INFO(t.id << ": " << name);
            const std::string text = cg::test::row_text(base, row);
            CAPTURE(text);
            const json& e = row["expect"];
            const std::string error = run_error(*a, text);
            if (e.contains("error")) {
                CHECK(lines(error) == 0);
                CHECK_THAT(error, Catch::Contains(e["error"].get<std::string>()));
            } else {
                CHECK(error == "");
                if (!error.empty()) continue;
                // Run as the viewer runs it: what it shows at every step is finite too.
                json result;
                CHECK(run_clean(*a, cg::parse_json(text), &result) == "");
                check_result(e["result"], result);
            }
            // Every third row through the CLI too (every ninth under the sanitizers, where a
            // process start with leak checking costs 0.1 s).
            if (i % (cg::test::kSanitized ? 9 : 3) != 0) continue;
            const std::string out = check_cli_agrees(*a, text, error);
            if (e.contains("result") && lines(out) == 1) check_result(e["result"], json::parse(out));
        }
    }
}

// The sweeps put a value into every numeric field of every table's base input: thousands of
// inputs. They run in process, through the same steps as `cgsandbox run` (parse the text, create
// the run, step it to the end), so that they cost microseconds each rather than a process start
// (under ASan about 0.1 s each, minutes in all). For each table the first field's inputs also go
// through the CLI, which must print exactly the in-process error after "cgsandbox: FILE: " and
// exit 2, or print a result and exit 0: the two paths are the same one.

TEST_CASE("robustness: NaN and infinities in every numeric field are refused, naming the field", "[robustness][sweep]") {
    for (const auto& t : tables()) {
        const cg::Algorithm* a = registry().find(t.id);
        if (!a) continue;
        const json base = base_of(t);
        const auto leaves = cg::test::numeric_leaves(base);
        // Only an input made of text has no number to sweep: affine-combination's numbers are
        // inside its expressions (its table has the NaN, overflow and magnitude rows).
        CAPTURE(t.id);
        if (t.id == "affine-combination") CHECK(leaves.empty());
        else REQUIRE(!leaves.empty());
        for (std::size_t k = 0; k < leaves.size(); ++k)
            for (const char* raw : {"NaN", "1e999", "-1e999"}) {
                const auto& leaf = leaves[k];
                CAPTURE(t.id, leaf.path, raw);
                const std::string text = cg::test::splice_raw(base, leaf.pointer, raw);
                const std::string error = run_error(*a, text);
                const std::string why = std::string(raw) == "NaN" ? "not valid JSON" : "not valid JSON: number overflow";
                CHECK_THAT(error, Catch::StartsWith(leaf.path + ": " + why));
                CHECK(lines(error) == 0);
                if (k == 0) check_cli_agrees(*a, text, error);
            }
    }
}

// Huge and tiny magnitudes are legal JSON, so each algorithm decides: it either runs to a result
// whose every number (and every step's, and the picture's) is finite, or refuses with one line
// that names the field changed, or the field it is checked against (its enclosing list or
// object, or a sibling such as window.xmax for window.xmin).
TEST_CASE("robustness: huge and tiny magnitudes in every numeric field give a finite result or an error naming a field", "[robustness][sweep]") {
    std::size_t accepted = 0, refused = 0;
    for (const auto& t : tables()) {
        const cg::Algorithm* a = registry().find(t.id);
        if (!a) continue;
        const json base = base_of(t);
        const auto leaves = cg::test::numeric_leaves(base);
        for (std::size_t k = 0; k < leaves.size(); ++k)
            for (const char* raw : {"1e300", "-1e300", "1e-300"}) {
                const auto& leaf = leaves[k];
                CAPTURE(t.id, leaf.path, raw);
                const std::string text = cg::test::splice_raw(base, leaf.pointer, raw);
                const std::string error = run_error(*a, text);
                CAPTURE(error);
                if (error.empty()) {
                    ++accepted;
                    CHECK(run_clean(*a, cg::parse_json(text)) == "");
                } else {
                    ++refused;
                    CHECK(lines(error) == 0);
                    // "FIELD: reason" with FIELD the first path segment of the leaf's (its
                    // top-level field) or deeper.
                    const std::string top = leaf.path.substr(0, leaf.path.find_first_of(".["));
                    CHECK_THAT(error, Catch::StartsWith(top));
                }
                if (k == 0) check_cli_agrees(*a, text, error);
            }
    }
    WARN("magnitude sweep: " << accepted << " accepted with finite results, " << refused << " refused");
}
