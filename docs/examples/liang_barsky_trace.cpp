// A student's own Liang-Barsky, printing one JSON line per step for `cgsandbox check`
// (docs/study-modes.md). Build and check it:
//   g++ -std=c++17 liang_barsky_trace.cpp -o lb && ./lb > mine.jsonl
//   cgsandbox check liang-barsky --trace mine.jsonl
// It clips the sandbox's example: (0, 2)–(4, 6) against the window [1, 5] × [1, 4].
#include <algorithm>
#include <cstdio>

// One step: its event and the numbers it computed. Only the variables a line gives are
// checked, so a trace may leave out any of them.
void step(const char* event, double t_enter, double t_leave, double p = 0, double q = 0,
          bool with_pq = false) {
    std::printf("{\"event\": \"%s\", \"variables\": {\"t_enter\": %.17g, \"t_leave\": %.17g", event,
                t_enter, t_leave);
    if (with_pq) std::printf(", \"p_k\": %.17g, \"q_k\": %.17g", p, q);
    std::printf("}}\n");
}

int main() {
    const double xmin = 1, ymin = 1, xmax = 5, ymax = 4;
    const double x0 = 0, y0 = 2, x1 = 4, y1 = 6;
    const double dx = x1 - x0, dy = y1 - y0;
    double t_enter = 0, t_leave = 1;
    step("setup", t_enter, t_leave);
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - xmin, xmax - x0, y0 - ymin, ymax - y0};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            step(q[k] < 0 ? "parallel-outside" : "parallel-inside", t_enter, t_leave, p[k], q[k], true);
            if (q[k] < 0) return step("reject", t_enter, t_leave), 0;
            continue;
        }
        const double r = q[k] / p[k];
        if (p[k] < 0) {
            t_enter = std::max(t_enter, r);
            step("entering", t_enter, t_leave, p[k], q[k], true);
        } else {
            t_leave = std::min(t_leave, r);
            step("leaving", t_enter, t_leave, p[k], q[k], true);
        }
        if (t_enter > t_leave) return step("reject", t_enter, t_leave), 0;
    }
    step("accept", t_enter, t_leave);
}
