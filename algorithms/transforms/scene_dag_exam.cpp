// Scene-DAG exam problems: a robot arm of two or three joints in the xy plane — a shoulder
// placed at a small integer point and turned about z, an elbow (and sometimes a wrist) one to
// three units along the previous link and turned again, and a hand (a box) at the end — with
// angles that a student multiplies by hand (0°, ±30°, ±45°, ±60°, ±90°, 180°). The question asks
// for the hand's world matrix: the product of the matrices along its path.
#include "core/format.hpp"
#include "transforms/scene_dag.hpp"

namespace cg {

SceneDag::Input SceneDag::exam_input(Rng& rng) {
    static constexpr double kAngles[] = {0, 30, -30, 45, -45, 60, -60, 90, -90, 180, 90, 30};
    auto angle = [&] { return kAngles[rng.integer(0, std::size(kAngles) - 1)]; };
    auto len = [&] { return static_cast<double>(rng.integer(1, 3)); };
    Input in;
    const bool wrist = rng.chance(0.5);
    Node shoulder;
    shoulder.name = "shoulder";
    shoulder.translate = {static_cast<double>(rng.integer(-2, 2)),
                          static_cast<double>(rng.integer(0, 2)), 0};
    shoulder.has_rotate = true;
    shoulder.axis = {0, 0, 1};
    shoulder.angle_deg = angle();
    shoulder.children = {"elbow"};
    Node elbow;
    elbow.name = "elbow";
    elbow.translate = {len(), 0, 0};
    elbow.has_rotate = true;
    elbow.axis = {0, 0, 1};
    elbow.angle_deg = angle();
    elbow.children = {wrist ? "wrist" : "hand"};
    in.nodes = {shoulder, elbow};
    if (wrist) {
        Node w;
        w.name = "wrist";
        w.translate = {len(), 0, 0};
        w.has_rotate = true;
        w.axis = {0, 0, 1};
        w.angle_deg = angle();
        w.children = {"hand"};
        in.nodes.push_back(w);
    }
    Node hand;
    hand.name = "hand";
    hand.translate = {1, 0, 0};
    hand.box = true;
    in.nodes.push_back(hand);
    in.root = "shoulder";
    return in;
}

std::string SceneDag::question(const Input& in) {
    std::string q =
        "A robot arm is modelled as a hierarchy (column vectors, right-handed, each node's "
        "matrix M = T R S is applied in its parent's frame, rotations counter-clockwise about "
        "the given axis): ";
    std::string path;
    for (std::size_t i = 0; i < in.nodes.size(); ++i) {
        const Node& n = in.nodes[i];
        path += (path.empty() ? "" : "/") + n.name;
        q += (i ? "; " : "") + n.name + ": M = T" + num(n.translate);
        if (n.has_rotate) q += " R(" + num(n.angle_deg) + "° about " + num(n.axis) + ")";
        q += n.children.empty() ? " (a box)" : " (child: " + n.children[0] + ")";
    }
    return q + ". The DAG is traversed from " + in.root +
           " with a matrix stack (push, top ← top · M, draw, pop). Give the world matrix of the "
           "hand, the top of the stack when its box is drawn, as draws: [{\"path\": \"" + path +
           "\", \"matrix\": 4×4 rows}].";
}

std::vector<std::string> SceneDag::answer_fields() {
    return {"draws"};
}

}  // namespace cg
