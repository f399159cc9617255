// Keyframes exam problems, four keys one second apart with small integer values:
//   half the time, the value halfway through a segment by linear and by Catmull–Rom
//     (u = ½: h00 = h01 = ½, h10 = ⅛, h11 = −⅛, so p = (p_i + p_{i+1})/2 + (m_i − m_{i+1})/8);
//   a quarter, the tangent at an inner key by Catmull–Rom and by Kochanek–Bartels (T, C, B);
//   a quarter, which of the three interpolations is C1 at the keys (KB with the given T, C, B;
//     sometimes the keys lie on a line, and then linear is C1 too).
// One value problem in ten has every key equal (everything is flat, the answer the key's value).
#include "animation/keyframes.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

enum class Kind { Value, Tangent, C1 };

Kind kind_of(const Keyframes::Input& in) {
    if (!in.has_query) return Kind::C1;
    for (const auto& k : in.keys)
        if (k.t == in.query) return Kind::Tangent;
    return Kind::Value;
}

}  // namespace

Keyframes::Input Keyframes::exam_input(Rng& rng) {
    const double tcbs[] = {-0.5, 0, 0.5};
    Input in;
    in.dim = 1;
    in.dt = 0.25;
    const double pick = rng.uniform(0, 1);
    const Kind kind = pick < 0.5 ? Kind::Value : pick < 0.75 ? Kind::Tangent : Kind::C1;
    const bool flat = kind == Kind::Value && rng.chance(0.1);
    const bool line = kind == Kind::C1 && rng.chance(0.2);
    const double slope = double(rng.integer(-2, 2));
    const double T = kind == Kind::Value ? 0 : tcbs[rng.integer(0, 2)];
    const double C = kind == Kind::Value ? 0 : tcbs[rng.integer(0, 2)];
    const double B = kind == Kind::Value ? 0 : tcbs[rng.integer(0, 2)];
    const double base = double(rng.integer(0, 4));
    for (int i = 0; i < 4; ++i) {
        Key k;
        k.t = i;
        k.value.x = flat ? base : line ? base + slope * i : double(rng.integer(0, 8));
        k.tension = T;
        k.continuity = C;
        k.bias = B;
        in.keys.push_back(k);
    }
    in.interpolation =
        kind == Kind::Value ? Interpolation::CatmullRom : Interpolation::KochanekBartels;
    if (kind == Kind::Value) {
        in.has_query = true;
        in.query = double(rng.integer(0, 2)) + 0.5;
    } else if (kind == Kind::Tangent) {
        in.has_query = true;
        in.query = double(rng.integer(1, 2));
    }
    return in;
}

std::string Keyframes::question(const Input& in) {
    std::string keys;
    for (std::size_t i = 0; i < in.keys.size(); ++i)
        keys += (i ? ", " : "") + std::string("(") + num(in.keys[i].t) + ", " +
                num(in.keys[i].value.x) + ")";
    const std::string head = "A scalar channel is keyed at (t, value) = " + keys + ". ";
    const Key& k = in.keys.front();
    const std::string tcb = "tension T = " + num(k.tension) +
                            ", continuity C = " + num(k.continuity) + ", bias B = " + num(k.bias);
    switch (kind_of(in)) {
        case Kind::Value:
            return head + "Give its value at t = " + num(in.query) +
                   " by linear interpolation (linear) and by a Catmull–Rom spline (catmull_rom), "
                   "whose tangent at a key is (p_{i+1} − p_{i−1})/2 and at the first and last key "
                   "the slope of its one segment.";
        case Kind::Tangent:
            return head + "Give the tangent (the velocity, value per second) at the key t = " +
                   num(in.query) +
                   " of a Catmull–Rom spline (catmull_rom_velocity) and the leaving tangent of a "
                   "Kochanek–Bartels spline with " +
                   tcb +
                   " (kochanek_bartels_velocity): m⁺ = (1−T)[(1+C)(1+B)(p_i − p_{i−1}) + "
                   "(1−C)(1−B)(p_{i+1} − p_i)]/2.";
        case Kind::C1:
            break;
    }
    return head +
           "Which of these is C1 (a continuous velocity) at every key: linear "
           "interpolation (linear), the Catmull–Rom spline (catmull_rom), the "
           "Kochanek–Bartels spline with " +
           tcb + " at every key (kochanek_bartels)? Answer yes or no for each.";
}

std::vector<std::string> Keyframes::answer_fields(const Input& in) {
    switch (kind_of(in)) {
        case Kind::Value:
            return {"at/linear", "at/catmull_rom"};
        case Kind::Tangent:
            return {"at/catmull_rom_velocity", "at/kochanek_bartels_velocity"};
        case Kind::C1:
            break;
    }
    return {"c1_at_keys/linear", "c1_at_keys/catmull_rom", "c1_at_keys/kochanek_bartels"};
}

}  // namespace cg
