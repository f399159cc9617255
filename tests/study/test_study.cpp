// The study modes' library (algorithms/study/): predictions graded as the exam grades, a
// student's trace checked step by step, mistakes planted where they show, runs compared.
// The declarations each algorithm makes are checked in tests/conformance; here the Specs are
// copies with declarations of the test's own, so these tests do not move when a lesson's
// choice of predictable numbers does.
#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "core/rng.hpp"
#include "study/bug.hpp"
#include "study/check.hpp"
#include "study/compare.hpp"
#include "study/predict.hpp"

using namespace cg;
using namespace cg::study;

namespace {

const Registry& registry() {
    static const Registry r = builtin_registry();
    return r;
}

const Algorithm& algorithm(const std::string& id) {
    const Algorithm* a = registry().find(id);
    REQUIRE(a);
    return *a;
}

// The Liang-Barsky example: the segment (0, 2)–(4, 6) against the window [1, 5] × [1, 4].
// Steps: setup; left entering r = 0.25; right leaving r = 1.25; bottom entering r = −0.25;
// top leaving r = 0.5; accept.
Spec lb_spec() {
    Spec s = *algorithm("liang-barsky").spec;
    s.study = {};
    s.study.predict = {{"entering", {"r_k", "t_enter"}}, {"leaving", {"t_leave"}}};
    s.study.mistakes = {
        {"entering", "p_k", "negate", "took p_k = +dx on the left edge"},
        {"entering", "t_enter", "other:r_k", "updated t_enter with min instead of max"},
        {"leaving", "", "event:entering", "read p_k > 0 as entering"},
    };
    return s;
}

std::vector<json> as_lines(const Trace& t) {
    std::vector<json> lines;
    for (std::size_t i = 0; i < t.steps.size(); ++i)
        lines.push_back(step_to_json(i + 1, t.steps[i]));
    return lines;
}

Prediction predict(std::size_t step, std::string event, json vars = json::object()) {
    return Prediction{step, std::move(event), std::move(vars)};
}

}  // namespace

TEST_CASE("record keeps every step and the result, as run --trace prints them", "[study]") {
    const Algorithm& a = algorithm("liang-barsky");
    const Trace t = record(a, a.example());
    REQUIRE(t.steps.size() == 6);
    CHECK(t.steps[1].event == "entering");
    CHECK(std::get<double>(find_var(t.steps[1], "t_enter")->value) == 0.25);
    CHECK(t.steps.back().event == "accept");
    auto run = a.create(a.example());
    while (!run->done()) run->step(nullptr);
    CHECK(t.result == a.result(*run));
    CHECK_THROWS_WITH(record(a, a.example(), 3), Catch::Contains("more than 3 steps"));
    json bad = a.example();
    bad["p0"] = "here";
    CHECK_THROWS_AS(record(a, bad), InputError);
}

TEST_CASE("predictions are graded as the exam grades: the event, and numbers to 3 figures",
          "[study]") {
    const Spec spec = lb_spec();
    const Trace t = record(algorithm("liang-barsky"), algorithm("liang-barsky").example());
    const StepInfo& left = t.steps[1];  // entering: r_1 = 0.25, t_enter = 0.25

    auto g =
        grade_prediction(spec, left, predict(2, "entering", {{"r_k", 0.25}, {"t_enter", 0.25}}));
    CHECK(g.correct);
    CHECK(g.event_correct);
    REQUIRE(g.vars.size() == 2);
    CHECK(g.vars[0].name == "r_k");

    // 3 significant figures: 0.2504 is 0.250, right; 0.252 is not.
    CHECK(grade_prediction(spec, left, predict(2, "entering", {{"r_k", 0.2504}, {"t_enter", 0.25}}))
              .correct);
    g = grade_prediction(spec, left, predict(2, "entering", {{"r_k", 0.252}, {"t_enter", 0.25}}));
    CHECK_FALSE(g.correct);
    CHECK(g.event_correct);
    CHECK(g.why == "r_k = 0.25, not 0.252");

    g = grade_prediction(spec, left, predict(2, "leaving", {{"t_leave", 0.25}}));
    CHECK_FALSE(g.correct);
    CHECK_FALSE(g.event_correct);
    CHECK_THAT(g.why, Catch::StartsWith("the step is entering, not leaving"));

    g = grade_prediction(spec, left, predict(2, "entering", {{"t_enter", 0.25}}));  // r_k missing
    CHECK_FALSE(g.correct);
    CHECK_THAT(g.why, Catch::Contains("r_k = 0.25 (not given)"));

    // An event with nothing declared is graded on its kind alone.
    CHECK(grade_prediction(spec, t.steps[0], predict(1, "setup")).correct);
    CHECK(predictable_vars(spec, "setup").empty());
}

TEST_CASE("a file of predictions: score, the wrong steps, and malformed lines named", "[study]") {
    const Spec spec = lb_spec();
    const Trace t = record(algorithm("liang-barsky"), algorithm("liang-barsky").example());
    std::vector<Prediction> ps{
        predict(3, "leaving", {{"t_leave", 1}}),                    // right
        predict(1, "setup"),                                        // right
        predict(2, "entering", {{"r_k", 0.25}, {"t_enter", 0.3}}),  // a wrong number
        predict(6, "reject"),                                       // the wrong event
    };
    const PredictReport r = grade_predictions(spec, t, ps);
    CHECK(r.steps == 6);
    CHECK(r.right == 2);
    CHECK(r.grades.size() == 4);
    CHECK(r.wrong == std::vector<std::size_t>{2, 6});
    CHECK(r.grades.front().step == 1);  // in step order
    const json j = report_json(r);
    CHECK(j["score"]["right"] == 2);
    CHECK(j["score"]["answered"] == 4);
    const std::string text = report_text(r);
    CHECK_THAT(text,
               Catch::Contains(
                   "score: 2 of 4 predicted steps right (2 of the run's 6 steps not predicted)"));
    CHECK_THAT(text, Catch::Contains("to revisit: steps 2 6"));

    ps.push_back(predict(2, "entering"));
    CHECK_THROWS_WITH(grade_predictions(spec, t, ps), "step 2: predicted twice");
    CHECK_THROWS_WITH(grade_predictions(spec, t, {predict(7, "accept")}),
                      "step 7: the run has only 6 steps");

    CHECK_THROWS_WITH(prediction_from_json(json::array(), "line 1"),
                      Catch::StartsWith("line 1: a prediction is an object"));
    CHECK_THROWS_WITH(prediction_from_json({{"step", 0}, {"event", "setup"}}, "line 2"),
                      Catch::Contains("line 2.step"));
    CHECK_THROWS_WITH(prediction_from_json({{"step", 1}, {"evnt", "setup"}}, "line 3"),
                      Catch::Contains("evnt"));
    CHECK_THROWS_WITH(
        prediction_from_json({{"step", 1}, {"event", "setup"}, {"variables", 3}}, "line 4"),
        Catch::Contains("line 4.variables"));
    const Prediction p = prediction_from_json(
        json::parse(R"({"step": 2, "event": "entering", "variables": {"r_k": 0.25}})"), "x");
    CHECK(p.step == 2);
    CHECK(p.variables["r_k"] == 0.25);
}

TEST_CASE("the questions list every event with its meaning and the numbers it asks", "[study]") {
    const Spec spec = lb_spec();
    const Trace t = record(algorithm("liang-barsky"), algorithm("liang-barsky").example());
    const std::string q = predict_question(spec, 2, &t.steps[0]);
    CHECK_THAT(q, Catch::StartsWith("Step 2. So far: " + t.steps[0].narration));
    CHECK_THAT(q, Catch::Contains("entering: p_k < 0"));
    CHECK_THAT(q, Catch::Contains("(then give r_k, t_enter)"));
    CHECK_THAT(q, !Catch::Contains(t.steps[1].narration));  // the answer is not in the question
    const json j = predict_question_json(spec, 1, nullptr);
    CHECK(j["choices"].size() == spec.events.size());
    CHECK(j["choices"][1]["variables"] == json::array({"r_k", "t_enter"}));
}

TEST_CASE("check: every algorithm's own trace agrees with itself, and one changed number is found",
          "[study][check]") {
    Rng rng(20261203);
    std::size_t tampered = 0;
    for (const Algorithm& a : registry().all()) {
        INFO(a.spec->id);
        const Trace t = record(a, a.example());
        std::vector<json> lines = as_lines(t);
        lines.push_back(t.result);
        CheckReport r = check_trace(*a.spec, t, lines);
        CHECK(r.agree);
        CHECK(r.steps_agreeing == t.steps.size());

        // Ten times: change one number of one step by 1 % (and at least 0.01) and expect the
        // checker to stop exactly there, naming that variable.
        for (int trial = 0; trial < 10; ++trial) {
            std::vector<json> copy = as_lines(t);
            const std::size_t k =
                static_cast<std::size_t>(rng.integer(0, static_cast<long long>(copy.size()) - 1));
            json& vars = copy[k]["variables"];
            std::vector<std::string> numeric;
            for (auto it = vars.begin(); it != vars.end(); ++it)
                if (it.value().is_number()) numeric.push_back(it.key());
            if (numeric.empty()) continue;
            const std::string name = numeric[static_cast<std::size_t>(
                rng.integer(0, static_cast<long long>(numeric.size()) - 1))];
            const double v = vars[name].get<double>();
            vars[name] = v + std::max(0.01 * std::fabs(v), 0.01);
            // An earlier step may report the same variable with the same value: the first
            // difference is then still step k, because earlier steps are untouched.
            r = check_trace(*a.spec, t, copy);
            CHECK_FALSE(r.agree);
            CHECK(r.step == k + 1);
            REQUIRE(r.mismatches.size() == 1);
            CHECK(r.mismatches[0].what == name);
            CHECK(r.event == t.steps[k].event);
            CHECK(r.narration == t.steps[k].narration);
            ++tampered;
        }
    }
    CHECK(tampered > 200);
}

TEST_CASE("check: missing, extra and renumbered steps, renamed variables, unknown events",
          "[study][check]") {
    const Algorithm& a = algorithm("liang-barsky");
    const Trace t = record(a, a.example());
    std::vector<json> lines = as_lines(t);

    std::vector<json> fewer(lines.begin(), lines.end() - 2);
    CheckReport r = check_trace(*a.spec, t, fewer);
    CHECK_FALSE(r.agree);
    CHECK(r.step == 5);
    CHECK(r.mismatches[0].note == "your trace stops after step 4; the run has 6 steps");
    CHECK(r.event == "leaving");

    std::vector<json> more = lines;
    more.push_back(lines.back());
    r = check_trace(*a.spec, t, more);
    CHECK(r.step == 7);
    CHECK(r.mismatches[0].note == "the run ends after step 6; your trace goes on to step 7");

    std::vector<json> renamed = lines;
    renamed[1]["variables"]["T_ENTER"] = renamed[1]["variables"]["t_enter"];
    renamed[1]["variables"].erase("t_enter");
    r = check_trace(*a.spec, t, renamed);
    CHECK(r.step == 2);
    CHECK_THAT(r.mismatches[0].note, Catch::Contains("renamed? the sandbox calls it \"t_enter\""));

    std::vector<json> other = lines;
    other[2]["event"] = "exiting";
    r = check_trace(*a.spec, t, other);
    CHECK(r.step == 3);
    CHECK_THAT(r.mismatches[0].note,
               Catch::Contains(
                   "\"exiting\" is not an event of liang-barsky (its events: setup, entering"));

    std::vector<json> wrong_case = lines;
    wrong_case[2]["event"] = "entering";
    r = check_trace(*a.spec, t, wrong_case);
    CHECK(r.mismatches[0].note == "a different case of the algorithm");

    std::vector<json> renumbered = lines;
    renumbered.erase(renumbered.begin() + 1);  // step 2 left out: line 2 says "index": 3
    r = check_trace(*a.spec, t, renumbered);
    CHECK(r.step == 2);
    CHECK(r.mismatches[0].what == "index");

    // Only what is given is checked: a trace of events alone agrees.
    std::vector<json> bare;
    for (const json& l : lines) bare.push_back({{"event", l["event"]}});
    CHECK(check_trace(*a.spec, t, bare).agree);

    // The result line.
    std::vector<json> with_result = bare;
    with_result.push_back({{"visible", true}, {"t_enter", 0.3}});
    r = check_trace(*a.spec, t, with_result);
    CHECK_FALSE(r.agree);
    CHECK(r.step == 0);
    REQUIRE(r.mismatches.size() == 1);
    CHECK(r.mismatches[0].what == "result/t_enter");
    CHECK_THAT(check_text(*a.spec, r), Catch::StartsWith("all 6 steps agree; the result differs"));

    // A line without an event anywhere but last: not a trace.
    std::vector<json> broken = bare;
    broken.insert(broken.begin() + 1, json{{"index", 2}});
    CHECK_THROWS_WITH(check_trace(*a.spec, t, broken), Catch::StartsWith("line 2: no \"event\""));
}

TEST_CASE("JSON Lines: blank lines skipped, a broken line named by its number", "[study][check]") {
    CHECK(read_json_lines("{\"a\": 1}\n\n  \n{\"b\": 2}").size() == 2);
    CHECK(read_json_lines("").empty());
    CHECK_THROWS_WITH(read_json_lines("{\"a\": 1}\n{oops"), "line 2: not valid JSON");
    CHECK_THROWS_WITH(read_json_lines("[1, 2]"),
                      Catch::StartsWith("line 1: each line must be a JSON object"));
}

namespace {

StepInfo step(std::string event, std::vector<Var> vars) {
    StepInfo s;
    s.event = std::move(event);
    s.vars = std::move(vars);
    s.narration = "n";
    return s;
}

using Rows = std::vector<std::vector<double>>;

}  // namespace

TEST_CASE("each kind of mistake changes what it says, and only visibly", "[study][bug]") {
    Trace t;
    t.steps = {
        step("a", {{"x", 2.0}, {"n", 3LL}, {"ok", true}}),
        step("b", {{"x", 5.0},
                   {"y", 1.0},
                   {"v", std::vector<double>{1, 2, 3}},
                   {"M", Rows{{1, 2}, {3, 4}}},
                   {"S", Rows{{1, 2}, {2, 1}}},
                   {"z", 0.0},
                   {"n", 3LL},
                   {"ok", true},
                   {"s", std::string("left")}}),
    };
    auto planted = [&](std::string var, std::string kind, std::size_t at = 1) {
        return plant(Mistake{at == 0 ? "a" : "b", std::move(var), std::move(kind), "d"}, t, at);
    };
    auto value = [](const std::optional<StepInfo>& s, const std::string& name) {
        REQUIRE(s);
        return to_json(find_var(*s, name)->value);
    };
    CHECK(value(planted("x", "negate"), "x") == -5.0);
    CHECK(value(planted("v", "negate"), "v") == json::array({-1, -2, -3}));
    CHECK_FALSE(planted("z", "negate"));  // −0 shows as 0: nothing to find
    CHECK_FALSE(planted("s", "negate"));  // not a number
    CHECK(value(planted("M", "transpose"), "M") == json::parse("[[1, 3], [2, 4]]"));
    CHECK_FALSE(planted("S", "transpose"));  // symmetric: the same matrix
    CHECK(value(planted("v", "reverse"), "v") == json::array({3, 2, 1}));
    CHECK(value(planted("M", "reverse"), "M") == json::parse("[[3, 4], [1, 2]]"));
    CHECK(value(planted("n", "off-by-one"), "n") == 4);
    CHECK_FALSE(planted("x", "off-by-one"));
    CHECK(value(planted("ok", "not"), "ok") == false);
    CHECK(value(planted("x", "copy:y"), "x") == 1.0);
    CHECK_FALSE(planted("x", "copy:v"));  // another shape
    CHECK_FALSE(planted("x", "copy:nothing"));
    const auto swapped = planted("x", "swap:y");
    CHECK(value(swapped, "x") == 1.0);
    CHECK(value(swapped, "y") == 5.0);
    CHECK(value(planted("x", "keep"), "x") == 2.0);  // the step before's x
    CHECK_FALSE(planted("n", "keep"));               // n did not change: keeping it is right
    CHECK_FALSE(planted("x", "keep", 0));            // no step before
    // "other": x = 5 is max(2, 5) with y… here the candidate is y = 1 and the value before 2:
    // 5 is neither, so min-for-max cannot be told apart.
    CHECK_FALSE(planted("x", "other:y"));
    const auto relabelled = plant(Mistake{"b", "", "event:c", "d"}, t, 1);
    REQUIRE(relabelled);
    CHECK(relabelled->event == "c");
    CHECK_FALSE(plant(Mistake{"b", "", "event:b", "d"}, t, 1));
    CHECK_FALSE(plant(Mistake{"a", "x", "negate", "d"}, t, 1));  // another event
    CHECK_FALSE(plant(Mistake{"b", "x", "negate", "d"}, t, 2));  // past the end
}

TEST_CASE("min for max: the candidate not chosen", "[study][bug]") {
    const Spec spec = lb_spec();
    const Trace t = record(algorithm("liang-barsky"), algorithm("liang-barsky").example());
    // Step 2: t_enter = max(0, 0.25) = 0.25; with min it stays 0.
    auto s = plant(spec.study.mistakes[1], t, 1);
    REQUIRE(s);
    CHECK(std::get<double>(find_var(*s, "t_enter")->value) == 0.0);
    // Step 4: t_enter = max(0.25, −0.25) = 0.25; with min it is −0.25.
    s = plant(spec.study.mistakes[1], t, 3);
    REQUIRE(s);
    CHECK(std::get<double>(find_var(*s, "t_enter")->value) == -0.25);
}

TEST_CASE("a planted bug: the first difference is the planted step, the same seed the same bug",
          "[study][bug]") {
    const Spec spec = lb_spec();
    const Algorithm& a = algorithm("liang-barsky");
    const Trace t = record(a, a.example());
    const auto sites = bug_sites(spec, t);
    // negate p_k: steps 2 and 4; min for max: 2 and 4; entering for leaving: 3 and 5.
    CHECK(sites.size() == 6);
    std::set<std::string> kinds_seen;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const PlantedBug bug = plant_bug(spec, t, seed);
        kinds_seen.insert(bug.mistake.kind);
        // The checker, fed the tampered working, stops exactly at the planted step.
        const CheckReport r = check_trace(spec, t, as_lines(Trace{bug.steps, {}}));
        CHECK(r.step == bug.step);
        CHECK(bug.correct == t.steps[bug.step - 1]);
        for (const StepInfo& s : bug.steps) CHECK(s.narration.empty());
        CHECK_THAT(bug.explanation, Catch::StartsWith("Step " + std::to_string(bug.step)));
        CHECK(plant_bug(spec, t, seed).steps == bug.steps);  // deterministic
        CHECK(grade_bug_answer(spec, bug, bug.step).correct);
        CHECK_FALSE(grade_bug_answer(spec, bug, bug.step == 1 ? 2 : bug.step - 1).correct);
    }
    CHECK(kinds_seen.size() == 3);

    Spec none = spec;
    none.study.mistakes = {{"parallel-outside", "p_k", "negate", "d"}};
    CHECK_THROWS_WITH(plant_bug(none, t, 1),
                      Catch::Contains("none of liang-barsky's planted mistakes shows"));
}

TEST_CASE("a wrong value is carried on while the right one stays the same", "[study][bug]") {
    Spec spec = lb_spec();
    spec.study.mistakes = {{"entering", "t_enter", "other:r_k", "min for max"}};
    const Trace t = record(algorithm("liang-barsky"), algorithm("liang-barsky").example());
    // Planted at step 2 (t_enter 0 instead of 0.25): steps 3–6 keep t_enter = 0.25 in the
    // right run, so the working says 0 throughout.
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const PlantedBug bug = plant_bug(spec, t, seed);
        if (bug.step != 2) continue;
        for (std::size_t k = 1; k < 6; ++k)
            CHECK(std::get<double>(find_var(bug.steps[k], "t_enter")->value) == 0.0);
        CHECK_THAT(bug.explanation,
                   Catch::Contains("t_enter was given as 0, the right value is 0.25"));
        const BugGrade late = grade_bug_answer(spec, bug, 4);
        CHECK_THAT(late.text,
                   Catch::StartsWith("Wrong: step 4 comes after the first wrong step, 2."));
        CHECK_THAT(late.text, Catch::Contains(t.steps[1].narration));
        return;
    }
    FAIL("no seed planted the bug at step 2");
}

TEST_CASE("compare one algorithm on two inputs: the first differing step and the results",
          "[study][compare]") {
    const Algorithm& a = algorithm("liang-barsky");
    const Side side{&a, nullptr, "liang-barsky"};
    json edited = a.example();
    edited["p1"] = json::array({4, 2});  // level with p0 = (0, 2): dy is 0 from step 1
    const Trace ta = record(a, a.example()), tb = record(a, edited);
    Comparison c = compare(side, ta, side, tb);
    CHECK_FALSE(c.agree);
    REQUIRE(c.first_step);
    CHECK(*c.first_step == 1);
    CHECK_THAT(c.first_step_note, Catch::StartsWith("dy: 4 against 0"));
    const json j = comparison_json(side, side, c);
    CHECK(j["agree"] == false);
    CHECK(j["first_step"]["step"] == 1);
    CHECK(j["difference_count"].get<std::size_t>() == c.difference_count);

    c = compare(side, ta, side, record(a, a.example()));
    CHECK(c.agree);
    CHECK_FALSE(c.first_step);
    CHECK(c.differences.empty());
}

TEST_CASE("compare two algorithms of one input kind on their shared fields, costs side by side",
          "[study][compare]") {
    Algorithm z = algorithm("z-buffer"), w = algorithm("warnock"), lb = algorithm("liang-barsky");
    Spec zs = *z.spec, ws = *w.spec;
    zs.study.input_kind = ws.study.input_kind = "test-scene";
    zs.study.compare = ws.study.compare = {"ids"};
    zs.study.costs = {"compares", "writes"};
    ws.study.costs = {"areas", "classifications"};
    z.spec = &zs;
    w.spec = &ws;
    const Side sz{&z, nullptr, "z-buffer"}, sw{&w, nullptr, "warnock"},
        sl{&lb, nullptr, "liang-barsky"};
    CHECK_NOTHROW(check_comparable(sz, sw));
    CHECK_THROWS_WITH(check_comparable(sz, sl),
                      Catch::Contains("compare needs two algorithms that share an input kind"));

    const json scene = w.example();
    const Trace tz = record(z, scene), tw = record(w, scene);
    const Comparison c = compare(sz, tz, sw, tw);
    // Both are exact on this scene (see test_warnock / test_z_buffer): the same visible polygon
    // in every pixel.
    CHECK(c.agree);
    CHECK(c.costs["z-buffer"].contains("compares"));
    CHECK(c.costs["warnock"]["areas"] == tw.result["areas"]);
    CHECK_FALSE(comparison_json(sz, sw, c).contains("first_step"));

    // A pixel changed by hand on one side is listed by its place.
    Trace moved = tw;
    moved.result["ids"][2][3] = 7;
    const Comparison d = compare(sz, tz, sw, moved);
    CHECK_FALSE(d.agree);
    REQUIRE(d.differences.size() == 1);
    CHECK(d.differences[0].where == "/ids/2/3");
    CHECK(d.differences[0].b == 7);
}

TEST_CASE("sides: ID and ID@VARIANT, a variant setting one input field", "[study][compare]") {
    CHECK_THROWS_WITH(parse_side(registry(), "no-such"),
                      Catch::Contains("unknown algorithm \"no-such\""));
    CHECK_THROWS_WITH(parse_side(registry(), "liang-barsky@fast"),
                      Catch::Contains("liang-barsky has no variant \"fast\""));
    const Side s = parse_side(registry(), "liang-barsky");
    CHECK(s.variant == nullptr);
    const Variant v{"phong", "/model", "\"phong\""};
    const Side p{&algorithm("phong-lighting"), &v, "phong-lighting@phong"};
    const json in = side_input(p, algorithm("phong-lighting").example());
    CHECK(in["model"] == "phong");
    CHECK(side_input(s, json{{"a", 1}}) == json{{"a", 1}});
}
