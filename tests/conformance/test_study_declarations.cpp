// Every registered algorithm declares what the study modes need (Spec::study), and every
// declaration means something on the algorithm's own inputs: a predictable number is one the
// event's steps report, a mistake shows somewhere, a variant's input runs, algorithms of one
// input kind read each other's inputs and report the fields they are compared on.
#include <catch2/catch.hpp>
#include <map>
#include <set>

#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "study/bug.hpp"
#include "study/compare.hpp"
#include "study/predict.hpp"

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

// The example, the lesson's presets and a few exam problems, recorded.
std::vector<cg::study::Trace> traces_of(const cg::Algorithm& a) {
    static const cg::LessonLibrary lessons = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    std::vector<cg::json> inputs{a.example()};
    if (const cg::Lesson* l = lessons.for_algorithm(a.spec->id))
        for (const auto& p : l->presets) inputs.push_back(p.input);
    if (cg::has_exam(a))
        for (std::uint64_t seed = 0; seed < 8; ++seed) inputs.push_back(a.exam_input(seed));
    std::vector<cg::study::Trace> traces;
    for (const cg::json& in : inputs) traces.push_back(cg::study::record(a, in));
    return traces;
}

bool known_kind(const std::string& kind) {
    static const std::set<std::string> plain{"negate",  "keep",       "transpose",
                                             "reverse", "off-by-one", "not"};
    static const std::set<std::string> with_argument{"swap", "copy", "other", "event"};
    const auto colon = kind.find(':');
    if (colon == std::string::npos) return plain.count(kind) > 0;
    return with_argument.count(kind.substr(0, colon)) > 0 && colon + 1 < kind.size();
}

}  // namespace

TEST_CASE("every algorithm declares predictable steps and plantable mistakes that mean something",
          "[conformance][study]") {
    for (const cg::Algorithm& a : registry().all()) {
        const cg::Spec& spec = *a.spec;
        INFO(spec.id);
        const auto traces = traces_of(a);
        // Every (event, variable) any of the inputs reports.
        std::map<std::string, std::set<std::string>> reported;
        for (const auto& t : traces)
            for (const cg::StepInfo& s : t.steps)
                for (const cg::Var& v : s.vars) reported[s.event].insert(v.name);

        CHECK_FALSE(spec.study.predict.empty());
        std::set<std::string> predicted_events;
        for (const cg::Predictable& p : spec.study.predict) {
            INFO("predict " << p.event);
            CHECK(cg::study::find_event(spec, p.event));
            CHECK(predicted_events.insert(p.event).second);  // listed once
            CHECK(reported.count(p.event));                  // the event happens on some input
            CHECK(p.vars.size() <= 2);
            for (const std::string& v : p.vars) {
                INFO("variable " << v);
                CHECK(reported[p.event].count(v));
            }
        }

        CHECK(spec.study.mistakes.size() >= 2);
        for (std::size_t k = 0; k < spec.study.mistakes.size(); ++k) {
            const cg::Mistake& m = spec.study.mistakes[k];
            INFO("mistake " << m.kind << " of " << m.var << " at " << m.event);
            CHECK(cg::study::find_event(spec, m.event));
            CHECK(known_kind(m.kind));
            CHECK_FALSE(m.description.empty());
            if (m.kind.rfind("event:", 0) == 0)
                CHECK(cg::study::find_event(spec, m.kind.substr(6)));
            else
                CHECK(reported[m.event].count(m.var));
            // It shows on at least one of the algorithm's own inputs.
            bool shows = false;
            for (const auto& t : traces) {
                for (const auto& site : cg::study::bug_sites(spec, t))
                    shows = shows || site.mistake == k;
                if (shows) break;
            }
            CHECK(shows);
        }
        // Some input plants a bug, and the planted step is the first one the working differs at.
        bool planted = false;
        for (const auto& t : traces) {
            if (cg::study::bug_sites(spec, t).empty()) continue;
            const auto bug = cg::study::plant_bug(spec, t, 7);
            for (std::size_t i = 0; i + 1 < bug.step; ++i) {
                CHECK(bug.steps[i].event == t.steps[i].event);
                CHECK(bug.steps[i].vars == t.steps[i].vars);
            }
            CHECK_FALSE((bug.steps[bug.step - 1].event == bug.correct.event &&
                         bug.steps[bug.step - 1].vars == bug.correct.vars));
            planted = true;
            break;
        }
        CHECK(planted);
    }
}

TEST_CASE("variants run, input kinds are shared and readable both ways, costs are result fields",
          "[conformance][study]") {
    std::map<std::string, std::vector<const cg::Algorithm*>> kinds;
    for (const cg::Algorithm& a : registry().all()) {
        const cg::Spec& spec = *a.spec;
        INFO(spec.id);
        const cg::study::Trace t = cg::study::record(a, a.example());
        for (const std::string& c : spec.study.costs) {
            INFO("cost " << c);
            CHECK(t.result.contains(cg::json::json_pointer("/" + c)));
        }
        for (const cg::Variant& v : spec.study.variants) {
            INFO("variant " << v.name);
            const cg::study::Side side = cg::study::parse_side(registry(), spec.id + "@" + v.name);
            // (A misspelt field is refused by the strict reader below.)
            const cg::json in = cg::study::side_input(side, a.example());
            CHECK_NOTHROW(cg::study::record(a, in));
        }
        if (!spec.study.input_kind.empty())
            kinds[spec.study.input_kind].push_back(&a);
        else
            CHECK(spec.study.compare.empty());
    }
    for (const auto& [kind, members] : kinds) {
        INFO("input kind " << kind);
        CHECK(members.size() >= 2);
        for (const cg::Algorithm* a : members)
            for (const cg::Algorithm* b : members) {
                INFO(a->spec->id << " on " << b->spec->id << "'s example");
                CHECK(a->spec->study.compare == b->spec->study.compare);
                const cg::study::Trace t = cg::study::record(*a, b->example());
                for (const std::string& field : a->spec->study.compare)
                    CHECK(t.result.contains(field));
            }
    }
}
