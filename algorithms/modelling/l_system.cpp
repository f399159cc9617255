// Sections: [rewriting] [turtle] [spec] [validate] [advance] [narrate] [result and compute]
//           [draw]
#include "modelling/l_system.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/format.hpp"
#include "transforms/rotation_common.hpp"

namespace cg {

namespace {

using Input = LSystem::Input;
using Phase = LSystem::Phase;
using State = LSystem::State;
using Turtle = LSystem::Turtle;
using Tally = LSystem::Tally;

enum Line {
    kLineAxiom = 1,
    kLineRewrite,
    kLineTurtleStart,
    kLineDraw,
    kLineMove,
    kLineTurn,
    kLinePush,
    kLinePop,
    kLineReport
};

constexpr int kAscii = 128;

// The production of each symbol as an index into in.rules (−1: the symbol copies itself).
std::array<int, kAscii> rule_table(const Input& in) {
    std::array<int, kAscii> t;
    t.fill(-1);
    for (std::size_t k = 0; k < in.rules.size(); ++k)
        t[static_cast<unsigned char>(in.rules[k].symbol) & 127] = int(k);
    return t;
}

std::string thousands(long long v) {
    std::string s = std::to_string(v < 0 ? -v : v);
    for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), ",");
    return (v < 0 ? "-" : "") + s;
}

}  // namespace

// ---- [rewriting] ----------------------------------------------------------------------------

// The growth counts: c_g(t) is how many t the string holds after g generations, and
// c_g+1(t) = Σ_s c_g(s) · (how many t the production of s holds) — a matrix–vector product.
// While every c_g(s) ≤ kMaxLength and a production ≤ kMaxRule symbols, no sum overflows.
std::vector<long long> LSystem::growth(const Input& in) {
    const auto table = rule_table(in);
    std::vector<long long> count(kAscii, 0);
    for (char c : in.axiom) ++count[static_cast<unsigned char>(c) & 127];
    std::vector<long long> lengths{(long long)in.axiom.size()};
    // For each symbol with a production, how many of each symbol the production holds.
    std::vector<std::array<long long, kAscii>> occ(in.rules.size());
    for (std::size_t k = 0; k < in.rules.size(); ++k) {
        occ[k].fill(0);
        for (char c : in.rules[k].replacement) ++occ[k][static_cast<unsigned char>(c) & 127];
    }
    for (int g = 1; g <= in.generations; ++g) {
        if (lengths.back() > kMaxLength) break;
        std::vector<long long> next(kAscii, 0);
        for (int s = 0; s < kAscii; ++s) {
            if (count[s] == 0) continue;
            if (table[s] < 0) {
                next[s] += count[s];
                continue;
            }
            const auto& o = occ[std::size_t(table[s])];
            for (int t = 0; t < kAscii; ++t) next[t] += count[s] * o[t];
        }
        count = std::move(next);
        long long total = 0;
        for (long long c : count) total += c;
        lengths.push_back(total);
    }
    return lengths;
}

std::string LSystem::rewrite(const Input& in, const std::string& word) {
    const auto table = rule_table(in);
    std::size_t size = 0;
    for (char c : word) {
        const int r = table[static_cast<unsigned char>(c) & 127];
        size += r < 0 ? 1 : in.rules[std::size_t(r)].replacement.size();
    }
    std::string out;
    out.reserve(size);
    for (char c : word) {
        const int r = table[static_cast<unsigned char>(c) & 127];
        if (r < 0)
            out += c;
        else
            out += in.rules[std::size_t(r)].replacement;
    }
    return out;
}

// ---- [turtle] -------------------------------------------------------------------------------

bool LSystem::draws(const Input& in, char c) {
    return in.draw.find(c) != std::string::npos;
}

double LSystem::heading_of(const Input& in, const Turtle& t) {
    double h = std::fmod(in.heading + double(t.turns) * in.angle, 360.0);
    if (h < 0) h += 360.0;
    if (h >= 360.0) h -= 360.0;
    return h == 0 ? 0.0 : h;  // no −0
}

glm::dvec2 LSystem::direction(const Input& in, const Turtle& t) {
    const rot::CosSin cs = rot::cos_sin_deg(in.heading + double(t.turns) * in.angle);
    return {cs.c, cs.s};
}

void LSystem::interpret(const Input& in, char c, Turtle& t, std::vector<Turtle>& stack,
                        Tally& tally) {
    switch (c) {
        case '+':
            ++t.turns;
            ++tally.turns;
            return;
        case '-':
            --t.turns;
            ++tally.turns;
            return;
        case '[':
            stack.push_back(t);
            ++tally.pushes;
            tally.max_depth = std::max(tally.max_depth, int(stack.size()));
            return;
        case ']':
            if (!stack.empty()) {  // always, for a validated input
                t = stack.back();
                stack.pop_back();
            }
            return;
        default:
            break;
    }
    const bool line = draws(in, c);
    if (!line && c != 'f') {
        ++tally.ignored;
        return;
    }
    t.p += in.step * direction(in, t);
    ++(line ? tally.segments : tally.moves);
    tally.lo = glm::min(tally.lo, t.p);
    tally.hi = glm::max(tally.hi, t.p);
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& LSystem::spec() {
    static const Spec spec{
        "l-system",
        "L-systems: parallel rewriting, then the turtle draws the plant",
        "Modelling",
        {
            "w ← ω   (the axiom)",
            "repeat n times: w ← the concatenation of P(a) for every symbol a of w   ▷ all at "
            "once; P(a) = a without a production",
            "turtle at (0, 0), heading h₀; an empty stack",
            "F: p ← p + step·(cos h, sin h), drawing a line",
            "f: p ← p + step·(cos h, sin h), without drawing",
            "+: h ← h + δ (left);  −: h ← h − δ (right)",
            "[: push (p, h)",
            "]: (p, h) ← pop   ▷ back to where the branch started",
            "report the string's length, the end position and heading",
        },
        {
            {"rewrite", "one generation: every symbol replaced at once by its production"},
            {"draw", "F: the turtle moves forward one step, drawing a line"},
            {"move", "f: the turtle moves forward one step without drawing"},
            {"turn", "+ or −: the turtle turns left or right by the angle"},
            {"push", "[: the turtle's position and heading saved on the stack"},
            {"pop", "]: the turtle jumps back to the position and heading saved last"},
            {"skip", "a symbol the turtle ignores (it only steers the rewriting)"},
            {"batch", "many symbols read in one step (after the first few, one at a time)"},
            {"summary", "the string's length, the end position and heading, what was drawn"},
        },
        {},  // no sliders
        {
            .predict = {{"rewrite", {"length"}},
                        {"draw", {"x", "y"}},
                        {"turn", {"heading"}},
                        {"push", {"depth"}},
                        {"pop", {"x", "y"}}},
            .mistakes =
                {
                    {"turn", "turn", "negate",
                     "turned clockwise for + and counter-clockwise for −: the picture mirrored"},
                    {"pop", "x", "keep",
                     "did not restore the saved position at ]: the next branch starts at the "
                     "tip of the last one"},
                    {"rewrite", "length", "keep",
                     "rewrote the string in place, left to right, and stopped at its old end"},
                },
            .variants = {{"angle 25°", "/angle", "25"}, {"angle 20°", "/angle", "20"}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_symbols(const std::string& field, const std::string& w) {
    for (std::size_t i = 0; i < w.size(); ++i) {
        const auto c = static_cast<unsigned char>(w[i]);
        if (c < 0x21 || c > 0x7e)
            throw InputError(field, "symbol " + std::to_string(i) +
                                        " is not a printable ASCII character (byte " +
                                        std::to_string(int(c)) +
                                        "): symbols are F, f, +, -, [, ], letters and the like "
                                        "(the Unicode minus − is read as -)");
    }
}

void check_brackets(const std::string& field, const std::string& w) {
    long long depth = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (w[i] == '[') ++depth;
        if (w[i] == ']' && --depth < 0)
            throw InputError(field, "unbalanced brackets: the ] at symbol " + std::to_string(i) +
                                        " closes no [");
    }
    if (depth > 0)
        throw InputError(field, "unbalanced brackets: " + std::to_string(depth) + " [ " +
                                    (depth == 1 ? "is" : "are") + " never closed");
}

}  // namespace

void LSystem::validate(const Input& in) {
    check_symbols("axiom", in.axiom);
    check_brackets("axiom", in.axiom);
    if ((long long)in.axiom.size() > kMaxLength)
        throw InputError("axiom", "has " + thousands((long long)in.axiom.size()) +
                                      " symbols; at most " + thousands(kMaxLength) +
                                      " are rewritten and drawn");
    for (std::size_t k = 0; k < in.rules.size(); ++k) {
        const Rule& r = in.rules[k];
        const std::string f = "rules." + std::string(1, r.symbol);
        check_symbols("rules", std::string(1, r.symbol));
        if (r.symbol == '[' || r.symbol == ']')
            throw InputError(f,
                             "brackets have no productions: they save and restore the "
                             "turtle, and copy themselves");
        for (std::size_t j = 0; j < k; ++j)
            if (in.rules[j].symbol == r.symbol)
                throw InputError(f,
                                 "has two productions: the system is deterministic, one "
                                 "production per symbol");
        check_symbols(f, r.replacement);
        check_brackets(f, r.replacement);
        if ((long long)r.replacement.size() > kMaxRule)
            throw InputError(f, "has " + thousands((long long)r.replacement.size()) +
                                    " symbols; a production has at most " +
                                    std::to_string(kMaxRule));
    }
    check_symbols("draw", in.draw);
    for (char c : in.draw)
        if (c == 'f' || c == '+' || c == '-' || c == '[' || c == ']')
            throw InputError("draw", std::string("'") + c +
                                         "' already means something to the turtle; list the "
                                         "symbols that draw a line (F, G, A, …)");
    if (in.generations < 0 || in.generations > kMaxGenerations)
        throw InputError("generations", "must be 0 to " + std::to_string(kMaxGenerations) +
                                            " (got " + std::to_string(in.generations) + ")");
    if (!std::isfinite(in.angle) || std::fabs(in.angle) > 360)
        throw InputError(
            "angle", "must be a finite angle in degrees, −360 to 360 (got " + given(in.angle) + ")");
    if (!std::isfinite(in.heading) || std::fabs(in.heading) > 360)
        throw InputError("heading", "must be a finite angle in degrees, −360 to 360 (got " +
                                        given(in.heading) + ")");
    if (!(in.step > 0 && in.step <= kMaxStep))
        throw InputError("step",
                         "must be a length above 0 and at most 1e6 (got " + given(in.step) + ")");
    // The limit, from the growth counts: refused before a single symbol is rewritten.
    const std::vector<long long> len = growth(in);
    if (len.back() > kMaxLength) {
        const int g = int(len.size()) - 1;
        throw InputError("generations",
                         "the string would have " + thousands(len.back()) +
                             " symbols after generation " + std::to_string(g) + "; at most " +
                             thousands(kMaxLength) + " are rewritten and drawn (" +
                             (g - 1 == 0 ? std::string("no generation fits")
                                         : "at most " + std::to_string(g - 1) + " generation" +
                                               (g - 1 == 1 ? "" : "s")) +
                             " for this system)");
    }
}

LSystem::State LSystem::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

namespace {
std::size_t batch_size(std::size_t length) {
    if (length <= std::size_t(LSystem::kStepped)) return 1;
    const std::size_t rest = length - LSystem::kStepped;
    return (rest + LSystem::kBatches - 1) / LSystem::kBatches;
}
}  // namespace

LSystem::State LSystem::begin(Shared<Input> shared) {
    const Input& in = *shared;
    State s;
    s.in = std::move(shared);
    s.word = Shared<std::string>(in.axiom);
    s.before = s.word;
    s.lengths.reserve(std::size_t(in.generations) + 1);
    s.lengths.push_back((long long)in.axiom.size());
    s.phase = in.generations > 0 ? Phase::Rewrite
              : in.axiom.empty() ? Phase::Summary
                                 : Phase::Turtle;
    s.batch = batch_size(in.axiom.size());
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void LSystem::advance(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Rewrite: {
            s.before = s.word;
            s.word = Shared<std::string>(rewrite(in, *s.word));
            ++s.generation;
            s.lengths.push_back((long long)s.word->size());
            s.last = Phase::Rewrite;
            if (s.generation == in.generations) {
                s.phase = s.word->empty() ? Phase::Summary : Phase::Turtle;
                s.batch = batch_size(s.word->size());
            }
            return;
        }
        case Phase::Turtle: {
            const std::string& w = *s.word;
            const std::size_t count = s.next < std::size_t(kStepped) ? 1 : s.batch;
            const std::size_t end = std::min(w.size(), s.next + count);
            s.previous = s.turtle;
            s.from = s.next;
            for (; s.next < end; ++s.next) interpret(in, w[s.next], s.turtle, s.stack, s.tally);
            s.last = Phase::Turtle;
            if (s.next == w.size()) s.phase = Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

// The string as the narration shows it: whole when short, else its first `limit` symbols.
std::string shown(const std::string& w, std::size_t limit = 120) {
    if (w.empty()) return "(empty)";
    if (w.size() <= limit) return w;
    return w.substr(0, limit) + "… (" + thousands((long long)w.size()) + " symbols in all)";
}

std::string deg_text(double d) {
    return num(d) + "°";
}

void narrate_rewrite(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::string& before = *s.before;
    const std::string& w = *s.word;
    info.event = "rewrite";
    info.line = kLineRewrite;
    // The productions that fired this generation, as the course writes them.
    std::string used;
    const auto table = rule_table(in);
    std::array<bool, kAscii> seen{};
    for (char c : before) {
        const auto u = static_cast<unsigned char>(c) & 127;
        if (seen[u] || table[u] < 0) continue;
        seen[u] = true;
        const std::string& r = in.rules[std::size_t(table[u])].replacement;
        used += (used.empty() ? "" : ", ") + std::string(1, c) + " → " +
                (r.empty() ? std::string("(nothing)") : shown(r, 40));
    }
    const long long grew = (long long)w.size() - (long long)before.size();
    info.narration =
        "Generation " + std::to_string(s.generation) + ": every symbol of the string (" +
        thousands((long long)before.size()) + (before.size() == 1 ? " symbol" : " symbols") +
        ") is replaced at once — " +
        (used.empty() ? std::string("no symbol has a production, so each copies itself")
                      : used + "; a symbol without a production copies itself") +
        ". The string now has " + thousands((long long)w.size()) + " symbols (" +
        (grew >= 0 ? "+" : "") + thousands(grew) + "): " + shown(w) + ".";
    info.math = "|w_{" + std::to_string(s.generation) + "}| = " + std::to_string(w.size());
    info.vars = {{"generation", (long long)s.generation},
                 {"length", (long long)w.size()},
                 {"string", shown(w, 200)}};
}

std::string at(glm::dvec2 p) {
    return num(p);
}

void turtle_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.vars.push_back({"x", s.turtle.p.x});
    info.vars.push_back({"y", s.turtle.p.y});
    info.vars.push_back({"heading", LSystem::heading_of(in, s.turtle)});
    info.vars.push_back({"depth", (long long)s.stack.size()});
}

void narrate_symbol(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const char c = (*s.word)[s.from];
    const std::string pos = "Symbol " + std::to_string(s.from + 1) + " of " +
                            thousands((long long)s.word->size()) + ", '" + std::string(1, c) +
                            "': ";
    const double h0 = LSystem::heading_of(in, s.previous);
    const double h1 = LSystem::heading_of(in, s.turtle);
    info.vars = {{"symbol", std::string(1, c)}};
    if (c == '+' || c == '-') {
        const bool left = c == '+';
        info.event = "turn";
        info.line = kLineTurn;
        info.narration = pos + "turn " + (left ? "left (counter-clockwise)" : "right (clockwise)") +
                         " by δ = " + deg_text(in.angle) + ": heading " + deg_text(h0) + " → " +
                         deg_text(h1) + ".";
        info.math = "h = " + tex(h0) + (left ? " + " : " - ") + tex(in.angle) + " = " + tex(h1);
        info.vars.push_back({"turn", left ? in.angle : -in.angle});
        info.vars.push_back({"heading", h1});
        return;
    }
    if (c == '[') {
        info.event = "push";
        info.line = kLinePush;
        info.narration = pos + "push the turtle's state — position " + at(s.turtle.p) +
                         ", heading " + deg_text(h1) + " — on the stack (depth now " +
                         std::to_string(s.stack.size()) + "): a branch starts here.";
        turtle_vars(s, info);
        return;
    }
    if (c == ']') {
        info.event = "pop";
        info.line = kLinePop;
        info.narration = pos + "the branch ends at " + at(s.previous.p) +
                         "; pop: the turtle jumps back to " + at(s.turtle.p) + ", heading " +
                         deg_text(h1) + ", saved at the matching [ (depth now " +
                         std::to_string(s.stack.size()) + ").";
        turtle_vars(s, info);
        return;
    }
    const bool line = LSystem::draws(in, c);
    if (!line && c != 'f') {
        info.event = "skip";
        info.line = kLineTurtleStart;
        info.narration = pos +
                         "no meaning for the turtle (it only steers the rewriting): "
                         "skipped. The turtle stays at " +
                         at(s.turtle.p) + ", heading " + deg_text(h1) + ".";
        turtle_vars(s, info);
        return;
    }
    info.event = line ? "draw" : "move";
    info.line = line ? kLineDraw : kLineMove;
    const glm::dvec2 d = LSystem::direction(in, s.previous);
    info.narration = pos + (line ? "move forward " : "move forward without drawing ") +
                     num(in.step) + " along heading " + deg_text(h0) + ": " + at(s.previous.p) +
                     " + " + num(in.step) + "·" + num(d) + " = " + at(s.turtle.p) +
                     (line ? ", drawing a line." : ".");
    info.math = "p = " + tex(s.previous.p) + " + " + tex(in.step) + "\\,(" + tex(d.x) + ", " +
                tex(d.y) + ") = " + tex(s.turtle.p);
    turtle_vars(s, info);
}

void narrate_batch(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "batch";
    info.line = kLineDraw;
    const std::size_t first = s.from + 1, last = s.next;
    info.narration =
        "Symbols " + thousands((long long)first) + "–" + thousands((long long)last) + " of " +
        thousands((long long)s.word->size()) + " in one step (the first " +
        std::to_string(LSystem::kStepped) + " were read one at a time; the rest go in batches of " +
        thousands((long long)s.batch) + "): " + thousands(s.tally.segments) +
        " lines drawn so far, " + thousands(s.tally.pushes) +
        " branches started. The turtle is at " + at(s.turtle.p) + ", heading " +
        deg_text(LSystem::heading_of(in, s.turtle)) + ", with " + std::to_string(s.stack.size()) +
        " state" + (s.stack.size() == 1 ? "" : "s") + " on the stack.";
    info.vars = {{"symbols", std::vector<double>{double(first), double(last)}},
                 {"segments", s.tally.segments}};
    turtle_vars(s, info);
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Tally& t = s.tally;
    info.event = "summary";
    info.line = kLineReport;
    std::string lengths;
    for (std::size_t g = 0; g < s.lengths.size(); ++g)
        lengths += (g ? ", " : "") + thousands(s.lengths[g]);
    info.narration = "After " + std::to_string(in.generations) + " generation" +
                     (in.generations == 1 ? "" : "s") + " the string has " +
                     thousands((long long)s.word->size()) + " symbols (lengths " + lengths +
                     "). The turtle drew " + thousands(t.segments) + " lines (total length " +
                     num(double(t.segments) * in.step) + "), " + "moved " + thousands(t.moves) +
                     " times without drawing, turned " + thousands(t.turns) + " times, branched " +
                     thousands(t.pushes) + " times (deepest stack " + std::to_string(t.max_depth) +
                     "), and ends at " + at(s.turtle.p) + ", heading " +
                     deg_text(LSystem::heading_of(in, s.turtle)) + ".";
    info.math = "p_{end} = " + tex(s.turtle.p);
    info.vars = {{"length", (long long)s.word->size()},
                 {"segments", t.segments},
                 {"x", s.turtle.p.x},
                 {"y", s.turtle.p.y},
                 {"heading", LSystem::heading_of(in, s.turtle)},
                 {"max_depth", (long long)t.max_depth}};
}

}  // namespace

void LSystem::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Rewrite:
            narrate_rewrite(s, info);
            break;
        case Phase::Turtle:
            if (s.next - s.from == 1)
                narrate_symbol(s, info);
            else
                narrate_batch(s, info);
            break;
        case Phase::Summary:
        case Phase::Done:
            narrate_summary(s, info);
            break;
    }
}

void LSystem::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

LSystem::Result LSystem::result(const State& s) {
    Result r;
    r.lengths = s.lengths;
    r.word = *s.word;
    r.tally = s.tally;
    r.end = s.turtle.p;
    r.end_heading = heading_of(*s.in, s.turtle);
    r.path_length = double(s.tally.segments) * s.in->step;
    return r;
}

LSystem::Result LSystem::compute(const Input& in) {
    Result r;
    std::string w = in.axiom;
    r.lengths.push_back((long long)w.size());
    for (int g = 0; g < in.generations; ++g) {
        w = rewrite(in, w);
        r.lengths.push_back((long long)w.size());
    }
    Turtle t;
    std::vector<Turtle> stack;
    for (char c : w) interpret(in, c, t, stack, r.tally);
    r.word = std::move(w);
    r.end = t.p;
    r.end_heading = heading_of(in, t);
    r.path_length = double(r.tally.segments) * in.step;
    return r;
}

// ---- [draw] ---------------------------------------------------------------------------------

namespace {

// The lines of w[0 … end) as polylines (a new one after every move, push or pop), symbols
// [from, end) in `recent` instead of `done`.
void trace_lines(const Input& in, const std::string& w, std::size_t from, std::size_t end,
                 Scene& scene, Style done, Style recent) {
    LSystem::Turtle t;
    std::vector<LSystem::Turtle> stack;
    LSystem::Tally tally;
    Polygon2 line{{}, done, false, false};
    auto flush = [&] {
        if (line.points.size() >= 2) scene.polygons.push_back(line);
        line.points.clear();
    };
    for (std::size_t i = 0; i < end; ++i) {
        if (i == from) {
            flush();
            line.style = recent;
        }
        const char c = w[i];
        const glm::dvec2 p = t.p;
        LSystem::interpret(in, c, t, stack, tally);
        if (t.p == p && c != '[' && c != ']') continue;  // a turn or an ignored symbol
        if (LSystem::draws(in, c)) {
            if (line.points.empty()) line.points.push_back(p);
            line.points.push_back(t.p);
        } else {
            flush();
        }
    }
    flush();
}

// n as a subscript: w₁₂.
std::string subscript(int n) {
    static const char* const digits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
    std::string out;
    for (char c : std::to_string(n)) out += digits[c - '0'];
    return out;
}

}  // namespace

// During the rewriting: the current generation's string drawn whole in grey, so the growth
// shows, and its first symbols as a label. During the turtle's walk: the lines drawn so far in
// green, this step's in orange, the turtle as a point with an arrow along its heading, and the
// positions saved on the stack as blue points numbered by depth. A system that draws nothing gets
// a chart of its string's length per generation.
void LSystem::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const std::string& w = *s.word;
    // A system whose symbols never draw (Lindenmayer's algae) shows what it is about instead:
    // the string's length generation by generation, beside its current string.
    bool ever_draws = std::any_of(in.axiom.begin(), in.axiom.end(),
                                  [&](char c) { return draws(in, c); });
    for (const Rule& r : in.rules)
        for (char c : r.replacement) ever_draws = ever_draws || draws(in, c);
    if (s.next == 0) {  // rewriting, or the walk not yet begun: the whole string, in grey
        trace_lines(in, w, w.size(), w.size(), scene, {Role::Subject, 1.5f}, {});
        scene.labels.push_back({{0, -0.6 * in.step},
                                "w" + subscript(s.generation) + " = " + shown(w, 60),
                                {Role::Neutral}});
    } else {
        trace_lines(in, w, s.from, s.next, scene, {Role::Kept, 1.5f}, {Role::Active, 2.5f});
    }
    const glm::dvec2 d = direction(in, s.turtle);
    scene.points.push_back({s.turtle.p, "turtle", {Role::Active}, 6.0f});
    scene.segments.push_back(
        {s.turtle.p, s.turtle.p + 0.8 * in.step * d, "", {Role::Active, 2.0f}, true});
    for (std::size_t k = 0; k < s.stack.size(); ++k) {
        const Turtle& t = s.stack[k];
        scene.points.push_back(
            {t.p, s.stack.size() <= 16 ? std::to_string(k + 1) : "", {Role::Window}, 4.0f});
        if (k + 1 == s.stack.size())
            scene.segments.push_back(
                {t.p, t.p + 0.5 * in.step * direction(in, t), "", {Role::Window, 1.5f}, true});
    }
    if (ever_draws) return;
    if (s.next > 0)  // the string stays in view: it is all there is to see
        scene.labels.push_back({{0, -0.6 * in.step},
                                "w" + subscript(s.generation) + " = " + shown(w, 60),
                                {Role::Neutral}});
    Panel& chart = add_chart(scene, "the string's length per generation",
                             Axis{"generation n", -0.5, double(in.generations) + 0.5},
                             Axis{"|wₙ| (symbols)", 0, 0, false, true});
    chart.weight = 1.5;  // as wide as the world: it holds the turtle alone
    std::vector<glm::dvec2> lengths;
    for (std::size_t g = 0; g < s.lengths.size(); ++g)
        lengths.push_back({double(g), double(s.lengths[g])});
    add_line(chart, lengths, {Role::Kept, 2.0f});
    add_dots(chart, lengths, {Role::Kept, 2.0f});
    const glm::dvec2 now = lengths.back();
    chart.points.push_back({now,
                            "|w" + subscript(int(s.lengths.size()) - 1) +
                                "| = " + std::to_string(s.lengths.back()),
                            {Role::Active},
                            6.0f});
}

}  // namespace cg
