// Marching-squares exam problems: one cell with corners (0, 0), (1, 0), (1, 1), (0, 1), four
// small corner values and an iso value; the case index from the corner signs and the crossing
// points by linear interpolation on the edges whose corners differ. About one in four is a
// saddle (case 5 or 10, decided by the centre average), one in eight has a corner exactly at
// iso (outside by the convention f < iso, so a crossing lands on that corner). Never case 0 or
// 15: the contour always passes through the cell.
#include <cmath>

#include "core/format.hpp"
#include "modelling/marching_squares.hpp"

namespace cg {

MarchingSquares::Input MarchingSquares::exam_input(Rng& rng) {
    Input in;
    in.field = Field::Grid;
    in.iso = rng.chance(0.7) ? 0 : double(rng.integer(1, 4));
    for (;;) {
        double f[4];
        const double kind = rng.uniform(0, 1);
        for (double& v : f) {
            // Values a few units from iso, never equal to it (except the degenerate corner).
            double d = double(rng.integer(1, 6));
            if (rng.chance(0.3)) d -= 0.5;
            v = in.iso + (rng.chance(0.5) ? d : -d);
        }
        if (kind < 0.25) {  // a saddle: flip the signs into 0101 or 1010
            const bool five = rng.chance(0.5);
            for (int k = 0; k < 4; ++k) {
                const bool inside = (k % 2 == 0) == five;
                const double d = std::fabs(f[k] - in.iso);
                f[k] = inside ? in.iso - d : in.iso + d;
            }
        } else if (kind < 0.375) {
            f[rng.integer(0, 3)] = in.iso;  // exactly on the threshold: outside
        }
        int index = 0;
        for (int k = 0; k < 4; ++k) index |= int(f[k] < in.iso) << k;
        if (index == 0 || index == 15) continue;
        // Rows from the bottom: row 0 holds corners 0 and 1, row 1 corners 3 and 2.
        in.values = {{f[0], f[1]}, {f[3], f[2]}};
        return in;
    }
}

std::string MarchingSquares::question(const Input& in) {
    const auto& v = in.values;  // at(): a formula's input has none; the question is not for it
    return "A marching-squares cell has corners 0 = (0, 0), 1 = (1, 0), 2 = (1, 1) and "
           "3 = (0, 1) with field values f0 = " + num(v.at(0).at(0)) +
           ", f1 = " + num(v.at(0).at(1)) + ", f2 = " + num(v.at(1).at(1)) +
           ", f3 = " + num(v.at(1).at(0)) + ", and iso = " + num(in.iso) +
           ". A corner is inside when f < iso; bit k of the case index is 1 when corner k is "
           "inside (case = b0 + 2·b1 + 4·b2 + 8·b3). Give the case index (cases/0/0) and the "
           "points where the contour crosses the cell's edges by linear interpolation "
           "(crossings), as [x, y] points in the order bottom, right, top, left, only for the "
           "edges whose two corners differ.";
}

std::vector<std::string> MarchingSquares::answer_fields() {
    return {"cases/0/0", "crossings"};
}

}  // namespace cg
