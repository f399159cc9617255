// The timeline: stepping back and forth reproduces the same states and steps, with bounded
// memory, checked against a reference that simply stores every state.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "core/timeline.hpp"

namespace {

// A deterministic test machine: a linear congruential walk that stops after n steps. Its
// state changes at every step, so a replay that went wrong would show.
struct Walk {
    struct Input { long long n = 0; };
    struct Result { unsigned long long value = 0; };
    struct State {
        long long n = 0, i = 0;
        unsigned long long value = 1;
        bool operator==(const State&) const = default;
    };
    static const cg::Spec& spec() {
        static const cg::Spec s{"walk", "test walk", "test", {"x ← a·x + c"}, {{"walk", "one step"}}};
        return s;
    }
    static State start(const Input& in) { return State{in.n, 0, 1}; }
    static void step(State& s, cg::StepInfo* info) {
        if (s.i >= s.n) return;
        s.value = s.value * 6364136223846793005ull + 1442695040888963407ull;
        ++s.i;
        if (info) {
            info->event = "walk";
            info->line = 1;
            info->narration = "step " + std::to_string(s.i) + ": " + std::to_string(s.value);
            info->vars = {{"i", s.i}};
        }
    }
    static bool done(const State& s) { return s.i >= s.n; }
    static Result result(const State& s) { return {s.value}; }
    static void draw(const State&, cg::Scene&) {}
};

std::unique_ptr<cg::Run> walk(long long n) {
    return std::make_unique<cg::RunOf<Walk>>(Walk::start({n}));
}

const Walk::State& state_of(const cg::Timeline& t) {
    return static_cast<const cg::RunOf<Walk>&>(t.current()).state;
}

// The walk with a big state (a payload of `bytes_each` bytes, like a z-buffer's pixels),
// which it reports through bytes(): the timeline must then keep to its byte budget.
struct HeavyWalk : Walk {
    struct Input { long long n = 0; std::size_t bytes_each = 0; };
    struct State {
        Walk::State walk;
        std::vector<unsigned char> payload;
        bool operator==(const State&) const = default;
    };
    static State start(const Input& in) { return {Walk::start({in.n}), std::vector<unsigned char>(in.bytes_each, 7)}; }
    static void step(State& s, cg::StepInfo* info) {
        Walk::step(s.walk, info);
        s.payload[static_cast<std::size_t>(s.walk.i) % s.payload.size()] ^= 1;
    }
    static bool done(const State& s) { return Walk::done(s.walk); }
    static Result result(const State& s) { return Walk::result(s.walk); }
    static std::size_t bytes(const State& s) { return cg::heap_bytes(s.payload); }
    static void draw(const State&, cg::Scene&) {}
};

}  // namespace

TEST_CASE("timeline: forward, back, jump and reset agree with stored states", "[timeline]") {
    const long long n = 1000;
    // Reference: every state and every step, stored.
    std::vector<Walk::State> states{Walk::start({n})};
    std::vector<cg::StepInfo> infos{{}};
    while (!Walk::done(states.back())) {
        Walk::State s = states.back();
        cg::StepInfo info;
        Walk::step(s, &info);
        states.push_back(s);
        infos.push_back(info);
    }

    cg::Timeline t(walk(n));
    std::mt19937_64 rng(7);
    for (int op = 0; op < 20000; ++op) {
        CAPTURE(op, t.index());
        switch (rng() % 6) {
            case 0: case 1: t.forward(); break;
            case 2: case 3: t.back(); break;
            case 4: t.jump(rng() % (n + 50)); break;
            default: if (rng() % 20 == 0) t.reset(); else if (rng() % 20 == 0) t.to_end(); break;
        }
        REQUIRE(t.index() <= static_cast<std::size_t>(n));
        REQUIRE(state_of(t) == states[t.index()]);
        if (t.index() > 0) REQUIRE(*t.last_step() == infos[t.index()]);
        else REQUIRE(t.last_step() == nullptr);
    }
    t.to_end();
    REQUIRE(t.at_end());
    REQUIRE(t.length() == std::size_t(n));
    REQUIRE_FALSE(t.forward());

    SECTION("a fresh jump far past the end lands on the end with its narration") {
        for (std::size_t target : {std::size_t(n), std::size_t(n + 1), std::size_t(n + 500), std::size_t(10 * n)}) {
            cg::Timeline fresh(walk(n));
            fresh.jump(target);
            REQUIRE(fresh.index() == std::size_t(n));
            REQUIRE(state_of(fresh) == states[n]);
            REQUIRE(*fresh.last_step() == infos[n]);
            REQUIRE(fresh.back());
            REQUIRE(*fresh.last_step() == infos[n - 1]);
        }
        for (std::size_t target : {std::size_t(37), std::size_t(500), std::size_t(777)}) {
            cg::Timeline fresh(walk(n));
            fresh.jump(target);
            REQUIRE(state_of(fresh) == states[target]);
            REQUIRE(*fresh.last_step() == infos[target]);
        }
    }

    SECTION("the step log replays the same infos from any point") {
        t.jump(17);
        auto log = t.steps(1, n);
        REQUIRE(log.size() == std::size_t(n));
        for (std::size_t i = 1; i <= std::size_t(n); ++i) REQUIRE(log[i - 1] == infos[i]);
        auto middle = t.steps(400, 420);
        REQUIRE(middle.size() == 21);
        REQUIRE(middle.front() == infos[400]);
    }
}

TEST_CASE("timeline: a million steps keep memory bounded and back-steps cheap", "[timeline]") {
    const long long n = 1'000'000;
    cg::Timeline t(walk(n));
    t.to_end();
    REQUIRE(t.index() == std::size_t(n));
    // Checkpoints plus the window grow like the square root of the length.
    CAPTURE(t.stride(), t.stored_states());
    REQUIRE(t.stored_states() < 6000);
    // Walking all the way back re-simulates each stretch once: total work stays linear.
    Walk::State expected = state_of(t);
    for (int i = 0; i < 5000; ++i) REQUIRE(t.back());
    t.jump(n);
    REQUIRE(state_of(t) == expected);
    REQUIRE(t.stored_states() < 6000);
}

TEST_CASE("timeline: a million steps of a big state keep to the byte budget", "[timeline][limits]") {
    // 1 MB states: a million of them would be a terabyte, and even sqrt-many (~3000) 3 GB.
    const long long n = 1'000'000;
    const std::size_t budget = std::size_t{64} << 20;
    cg::Timeline t(std::make_unique<cg::RunOf<HeavyWalk>>(HeavyWalk::start({n, 1 << 20})), 50'000'000, budget);
    const std::size_t state = cg::RunOf<HeavyWalk>(HeavyWalk::start({1, 1 << 20})).bytes();
    REQUIRE(state > (1u << 20));
    // Over budget by at most the two states always kept (the start and the current one).
    const std::size_t bound = budget + 2 * state;
    for (int i = 0; i < 300; ++i) REQUIRE(t.forward());
    CHECK(t.stored_bytes() <= bound);
    t.to_end();
    REQUIRE(t.index() == std::size_t(n));
    CAPTURE(t.stride(), t.stored_states(), t.stored_bytes());
    CHECK(t.stored_bytes() <= bound);
    CHECK(t.stored_states() <= bound / state + 1);
    // Back and forth still reproduces the states exactly, within the budget.
    const HeavyWalk::State end = static_cast<const cg::RunOf<HeavyWalk>&>(t.current()).state;
    for (int i = 0; i < 100; ++i) REQUIRE(t.back());
    CHECK(static_cast<const cg::RunOf<HeavyWalk>&>(t.current()).state.walk.i == n - 100);
    CHECK(t.stored_bytes() <= bound);
    t.jump(n / 2);
    CHECK(static_cast<const cg::RunOf<HeavyWalk>&>(t.current()).state.walk.i == n / 2);
    CHECK(t.stored_bytes() <= bound);
    t.to_end();
    CHECK(static_cast<const cg::RunOf<HeavyWalk>&>(t.current()).state == end);
    // The accounting matches the states actually kept.
    CHECK(t.stored_bytes() == t.stored_states() * state);
}

TEST_CASE("timeline: a run that is done at the start has no steps", "[timeline]") {
    cg::Timeline t(walk(0));
    REQUIRE(t.at_end());
    REQUIRE(t.length() == std::size_t(0));
    REQUIRE_FALSE(t.forward());
    REQUIRE_FALSE(t.back());
    REQUIRE(t.steps(1, 10).empty());
}

TEST_CASE("timeline: the step limit stops a runaway run", "[timeline]") {
    cg::Timeline t(walk(1'000'000), 500);
    t.to_end();
    REQUIRE(t.index() == 500);
    REQUIRE(t.hit_step_limit());
    REQUIRE_FALSE(t.forward());
}
