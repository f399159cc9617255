// The fuzzers' structure-aware mutator and oracles (tests/fuzz/json_mutator.hpp, oracles.hpp),
// exercised in the normal suite: without libFuzzer, a fixed set of mutations of every
// algorithm's example and lesson presets must mostly pass validation (the fuzzer's acceptance
// rate, issue 25), and every accepted one must keep the oracles.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <map>

#include "fuzz/json_mutator.hpp"
#include "fuzz/oracles.hpp"
#include "core/format.hpp"
#include "io/lesson.hpp"
#include "support/sweep.hpp"

using cg::json;

namespace {

const cg::LessonLibrary& lessons() {
    static const cg::LessonLibrary l = cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::fuzz::registry());
    return l;
}

// The example and the lesson's presets: the fuzz target's seeds.
std::vector<json> seeds(const cg::Algorithm& a) {
    std::vector<json> v{a.example()};
    if (const cg::Lesson* l = lessons().for_algorithm(a.spec->id))
        for (const auto& p : l->presets) v.push_back(p.input);
    return v;
}

bool accepted(const cg::Algorithm& a, const std::string& text) {
    try {
        (void)a.create(cg::parse_json(text));
        return true;
    } catch (const cg::InputError&) {
        return false;
    }
}

}  // namespace

TEST_CASE("json mutator: same seed, same mutant, and mutants differ from their parent", "[fuzz][mutator]") {
    const std::string text = R"({"points": [[0, 0], [1, 2.5], [3, 1]], "mode": "a", "n": 4, "on": true, "e": 1e-3})";
    int changed = 0;
    for (std::uint64_t seed = 1; seed <= 500; ++seed) {
        const auto m = cg::fuzz::mutate_json(text, seed);
        REQUIRE(m);
        CHECK(*m == *cg::fuzz::mutate_json(text, seed));
        const json j = json::parse(*m);  // always JSON again
        changed += j != json::parse(text);
        // Integers stay integers unless the 1-in-10 float path took them.
        if (j.contains("n")) CHECK(j["n"].is_number());
    }
    CHECK(changed >= 400);
    CHECK_FALSE(cg::fuzz::mutate_json("{not json", 1));
}

TEST_CASE("json mutator: crossing grafts a value at a path both documents have", "[fuzz][mutator]") {
    const std::string a = R"({"p": [0, 0], "t": 0.5, "mode": "x"})";
    const std::string b = R"({"p": [5, 6], "t": 0.25, "other": 1})";
    std::map<std::string, int> seen;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        const auto m = cg::fuzz::cross_json(a, b, seed);
        REQUIRE(m);
        const json j = json::parse(*m);
        CHECK(j.contains("mode"));       // a's own fields stay
        CHECK_FALSE(j.contains("other"));  // b's fields a lacks are not added
        if (j["t"] == 0.25) ++seen["t"];
        if (j["p"] == json::array({5, 6})) ++seen["p"];
        if (j["p"][0] == 5 || j["p"][1] == 6) ++seen["p element"];
    }
    CHECK(seen["t"] > 0);
    CHECK(seen["p"] + seen["p element"] > 0);
    CHECK_FALSE(cg::fuzz::cross_json(a, "[1]", 1));
}

TEST_CASE("json mutator: points made coincident and collinear", "[fuzz][mutator]") {
    const std::string text = R"([[0, 0], [4, 0], [0, 3], [5, 5]])";
    int coincident = 0, collinear = 0;
    for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
        const json j = json::parse(*cg::fuzz::mutate_json(text, seed));
        bool points = j.size() == 4;
        for (const json& p : j) points = points && p.size() == 2 && p[0].is_number() && p[1].is_number();
        if (!points) continue;
        for (std::size_t a = 0; a < 4; ++a)
            for (std::size_t b = a + 1; b < 4; ++b) {
                if (j[a] == j[b]) ++coincident;
                for (std::size_t c = b + 1; c < 4; ++c) {
                    auto v = [&](std::size_t i, int k) { return j[i][k].get<double>(); };
                    const double cross = (v(b, 0) - v(a, 0)) * (v(c, 1) - v(a, 1)) - (v(b, 1) - v(a, 1)) * (v(c, 0) - v(a, 0));
                    if (j[a] != j[b] && j[b] != j[c] && j[a] != j[c] && std::fabs(cross) < 1e-9) ++collinear;
                }
            }
    }
    CHECK(coincident > 20);
    CHECK(collinear > 20);
}

// The fuzzer's goal: at least half of the executions reach an algorithm. Measured here on
// twenty mutants of each seed input, as the custom mutator makes them (the first of four
// tries that passes validation); no algorithm may fall below a quarter.
TEST_CASE("json mutator: mutants of every algorithm's seeds mostly pass validation", "[fuzz][mutator]") {
    std::size_t tried = 0, passed = 0;
    for (const cg::Algorithm& a : cg::fuzz::registry().all()) {
        std::size_t t = 0, p = 0;
        std::uint64_t seed = 1;
        for (const json& input : seeds(a)) {
            const std::string text = input.dump();
            for (std::size_t k = 0; k < cg::test::sweep(20); ++k) {
                bool ok = false;
                for (int attempt = 0; attempt < 4 && !ok; ++attempt)
                    ok = accepted(a, *cg::fuzz::mutate_json(text, seed++));
                ++t, p += ok;
            }
        }
        INFO(a.spec->id << ": " << p << " of " << t << " mutants pass validation");
        CHECK(4 * p >= t);
        tried += t, passed += p;
    }
    INFO(passed << " of " << tried << " mutants pass validation");
    CHECK(2 * passed >= tried);
}

// Every accepted input keeps the oracles: on the seeds themselves and on five mutants of
// each (the fuzz target checks the same on every input it runs).
TEST_CASE("fuzz oracles: every algorithm's seeds and their mutants are finite, resumable and silent", "[fuzz][oracles]") {
    for (const cg::Algorithm& a : cg::fuzz::registry().all()) {
        std::uint64_t seed = 1;
        for (const json& input : seeds(a)) {
            std::vector<json> inputs{input};
            for (std::size_t k = 0; k < cg::test::sweep(5); ++k) {
                try {
                    inputs.push_back(cg::parse_json(*cg::fuzz::mutate_json(input.dump(), seed++)));
                } catch (const cg::InputError&) {
                }
            }
            for (const json& in : inputs) {
                INFO(a.spec->id << " on " << in.dump().substr(0, 400));
                cg::fuzz::Outcome o;
                CHECK_NOTHROW(o = cg::fuzz::check_algorithm_input(a, in));
            }
        }
    }
}

TEST_CASE("fuzz oracles: a non-number shown in text is caught, words that contain one are not", "[fuzz][oracles]") {
    using cg::fuzz::oracle_detail::shows_non_number;
    CHECK(shows_non_number("t = nan"));
    CHECK(shows_non_number("t_far = -inf."));
    CHECK(shows_non_number("(INF, 2)"));
    CHECK(shows_non_number("NaN"));
    CHECK_FALSE(shows_non_number("the point at infinity"));
    CHECK_FALSE(shows_non_number("an inflection, nanoseconds, Finance"));
    CHECK_FALSE(shows_non_number("t = ∞"));
    CHECK(cg::fuzz::oracle_detail::non_finite(json::parse(R"({"a": [1, 2]})")).empty());
    json j = {{"a", {1.0, std::nan("")}}};
    CHECK(cg::fuzz::oracle_detail::non_finite(j) == "/a/1");
}

namespace {

// A counter that is broken on purpose, one way at a time, to show each oracle can fail.
enum class Flaw { None, SharedHiddenState, NarrationChangesState, NanInPicture, NanInResult, NanInNarration };

struct Counter final : cg::Run {
    Flaw flaw = Flaw::None;
    int k = 0;
    std::shared_ptr<int> hidden = std::make_shared<int>(0);  // copies share it: not a value

    std::unique_ptr<cg::Run> clone() const override {
        auto c = std::make_unique<Counter>(*this);
        if (flaw != Flaw::SharedHiddenState) c->hidden = std::make_shared<int>(*hidden);
        return c;
    }
    const cg::Spec& spec() const override {
        static const cg::Spec s{"counter", "Counter", "test", {}, {}};
        return s;
    }
    bool done() const override { return k >= 40; }
    void step(cg::StepInfo* info) override {
        ++k;
        if (flaw == Flaw::SharedHiddenState) ++*hidden;
        if (flaw == Flaw::NarrationChangesState && info) ++*hidden;
        if (info) {
            info->event = "count";
            const double v = flaw == Flaw::NanInNarration && k == 7 ? std::nan("") : k + *hidden;
            info->narration = "k is now " + cg::num(v);
            info->vars = {{"k", static_cast<long long>(k)}};
        }
    }
    void draw(cg::Scene& scene) const override {
        scene.points.push_back({{double(k), flaw == Flaw::NanInPicture && k == 3 ? std::nan("") : 0.0}, "", {}});
    }
    bool same_state(const cg::Run& other) const override {
        auto* o = dynamic_cast<const Counter*>(&other);
        return o && o->k == k && *o->hidden == *hidden;
    }
};

cg::Algorithm counter(Flaw flaw) {
    static const cg::Spec s{"counter", "Counter", "test", {}, {}};
    cg::Algorithm a;
    a.spec = &s;
    a.create = [flaw](const json&) {
        auto c = std::make_unique<Counter>();
        c->flaw = flaw;
        return std::unique_ptr<cg::Run>(std::move(c));
    };
    a.result = [flaw](const cg::Run& r) {
        const int k = static_cast<const Counter&>(r).k + *static_cast<const Counter&>(r).hidden;
        return json{{"k", flaw == Flaw::NanInResult ? std::nan("") : double(k)}};
    };
    return a;
}

}  // namespace

TEST_CASE("fuzz oracles: each oracle catches a run broken its way", "[fuzz][oracles]") {
    using cg::fuzz::OracleViolation;
    const json input = json::object();
    CHECK(cg::fuzz::check_algorithm_input(counter(Flaw::None), input).steps == 40);
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(counter(Flaw::SharedHiddenState), input),
                      Catch::Contains("when a copy taken at step 32 is resumed"));
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(counter(Flaw::NarrationChangesState), input),
                      Catch::Contains("without narration"));
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(counter(Flaw::NanInPicture), input),
                      Catch::Contains("after step 3 has a non-finite coordinate in a 2D point"));
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(counter(Flaw::NanInResult), input),
                      Catch::Contains("the result has a non-finite number at /k"));
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(counter(Flaw::NanInNarration), input),
                      Catch::Contains("step 7's narration shows a non-number"));
}

TEST_CASE("fuzz oracles: every algorithm registers its plain function or says why it has none", "[fuzz][oracles]") {
    for (const cg::Algorithm& a : cg::fuzz::registry().all()) {
        INFO(a.spec->id);
        CHECK((a.plain ? 1 : 0) + (a.no_plain.empty() ? 0 : 1) == 1);
        if (!a.plain) CHECK(a.no_plain.size() > 20);  // a reason, not a placeholder
    }
}

TEST_CASE("fuzz oracles: a plain function that disagrees with the run is caught", "[fuzz][oracles]") {
    cg::Algorithm a = counter(Flaw::None);
    a.plain = [](const json&) { return json{{"k", 40.0}}; };
    CHECK(cg::fuzz::check_algorithm_input(a, json::object()).steps == 40);
    a.plain = [](const json&) { return json{{"k", 40.0 + 1e-6}}; };
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(a, json::object()),
                      Catch::Contains("plain function differ at /k"));
    a.plain = [](const json&) { return json{{"k", 40.0 * (1 + 1e-12)}}; };  // within tolerance
    CHECK_NOTHROW(cg::fuzz::check_algorithm_input(a, json::object()));
}

TEST_CASE("fuzz oracles: a check that accepts or refuses otherwise than create is caught", "[fuzz][oracles]") {
    cg::Algorithm a = counter(Flaw::None);
    a.check = [](const json&) {};
    CHECK(cg::fuzz::check_algorithm_input(a, json::object()).steps == 40);
    a.check = [](const json&) { throw cg::InputError("k", "too big"); };
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(a, json::object()),
                      Catch::Contains("create accepts the input but check refuses it (k: too big)"));
    a.create = [](const json&) -> std::unique_ptr<cg::Run> { throw cg::InputError("k", "too small"); };
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(a, json::object()),
                      Catch::Contains("create refuses the input (k: too small) but check says k: too big"));
    a.check = [](const json&) {};
    CHECK_THROWS_WITH(cg::fuzz::check_algorithm_input(a, json::object()),
                      Catch::Contains("but check accepts it"));
}
