// Marching-cubes exam problems: one cube with corners 0 = (0, 0, 0) … 7 = (0, 1, 1) (the bottom
// square counter-clockwise, then the top one), eight small corner values and an iso value; the
// case index from the corner signs and the crossing points by linear interpolation on the edges
// whose corners differ, in edge order 0 … 11. Mostly one to three inside corners (the shapes
// drawn in lecture notes); about one in five has a saddle face, one in eight a corner exactly
// at iso (outside by the convention f < iso, so a crossing lands on that corner). Never case 0
// or 255: the surface always passes through the cube.
#include <cmath>

#include "core/format.hpp"
#include "modelling/marching_cubes.hpp"

namespace cg {

MarchingCubes::Input MarchingCubes::exam_input(Rng& rng) {
    Input in;
    in.field = Field::Grid;
    in.iso = rng.chance(0.7) ? 0 : double(rng.integer(1, 4));
    for (;;) {
        double f[8];
        const double kind = rng.uniform(0, 1);
        int inside = 0;  // which corners are inside
        if (kind < 0.2) {
            inside = rng.chance(0.5) ? 0b00000101 : 0b01000001;  // a saddle face (or two)
            if (rng.chance(0.5)) inside |= 1 << 4;
        } else {
            const int n = int(rng.integer(1, 3));
            for (int k = 0; k < n; ++k) inside |= 1 << rng.integer(0, 7);
        }
        for (int k = 0; k < 8; ++k) {
            double d = double(rng.integer(1, 6));
            if (rng.chance(0.3)) d -= 0.5;
            f[k] = (inside >> k & 1) ? in.iso - d : in.iso + d;
        }
        if (rng.chance(0.125)) {
            const int k = int(rng.integer(0, 7));
            if (!(inside >> k & 1)) f[k] = in.iso;  // exactly on the threshold: outside
        }
        int index = 0;
        for (int k = 0; k < 8; ++k) index |= int(f[k] < in.iso) << k;
        if (index == 0 || index == 255) continue;
        // values[k][j][i]: layer z = 0 holds corners 0, 1 (row y = 0) and 3, 2 (row y = 1).
        in.values = {{{f[0], f[1]}, {f[3], f[2]}}, {{f[4], f[5]}, {f[7], f[6]}}};
        // Not the rare rows that add a centre point: the answer is the crossings alone.
        if (march(sample(in), 0, 0, 0, in.iso).row->centres) continue;
        return in;
    }
}

std::string MarchingCubes::question(const Input& in) {
    const auto& v = in.values;
    // at(): an input given as a formula has no values, and the question is not for it.
    const double f[8] = {v.at(0).at(0).at(0), v.at(0).at(0).at(1), v.at(0).at(1).at(1),
                         v.at(0).at(1).at(0), v.at(1).at(0).at(0), v.at(1).at(0).at(1),
                         v.at(1).at(1).at(1), v.at(1).at(1).at(0)};
    std::string values;
    for (int k = 0; k < 8; ++k) values += (k ? ", f" : "f") + std::to_string(k) + " = " + num(f[k]);
    return "A marching-cubes cube has corners 0 = (0, 0, 0), 1 = (1, 0, 0), 2 = (1, 1, 0), "
           "3 = (0, 1, 0), 4 = (0, 0, 1), 5 = (1, 0, 1), 6 = (1, 1, 1), 7 = (0, 1, 1) with field "
           "values " + values + ", and iso = " + num(in.iso) +
           ". A corner is inside when f < iso; bit k of the case index is 1 when corner k is "
           "inside (case = Σ b_k·2^k). The edges are 0: 0–1, 1: 1–2, 2: 3–2, 3: 0–3, 4: 4–5, "
           "5: 5–6, 6: 7–6, 7: 4–7, 8: 0–4, 9: 1–5, 10: 2–6, 11: 3–7. Give the case index "
           "(cases/0/0/0) and the points where the surface crosses the edges whose two corners "
           "differ, by linear interpolation, as [x, y, z] points in edge order (vertices).";
}

std::vector<std::string> MarchingCubes::answer_fields() {
    return {"cases/0/0/0", "vertices"};
}

}  // namespace cg
