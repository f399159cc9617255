# A student's own Liang-Barsky, printing one JSON line per step for `cgsandbox check`
# (docs/study-modes.md):
#   python3 liang_barsky_trace.py > mine.jsonl
#   cgsandbox check liang-barsky --trace mine.jsonl
# It clips the sandbox's example: (0, 2)-(4, 6) against the window [1, 5] x [1, 4].
import json

def step(event, **variables):
    # Only the variables a line gives are checked, so a trace may leave out any of them.
    print(json.dumps({"event": event, "variables": variables}))

xmin, ymin, xmax, ymax = 1, 1, 5, 4
x0, y0, x1, y1 = 0, 2, 4, 6
dx, dy = x1 - x0, y1 - y0
t_enter, t_leave = 0.0, 1.0
step("setup", dx=dx, dy=dy, t_enter=t_enter, t_leave=t_leave)

def clip():
    global t_enter, t_leave
    for p, q in [(-dx, x0 - xmin), (dx, xmax - x0), (-dy, y0 - ymin), (dy, ymax - y0)]:
        if p == 0:
            step("parallel-outside" if q < 0 else "parallel-inside", p_k=p, q_k=q)
            if q < 0:
                return "reject"
            continue
        r = q / p
        if p < 0:
            t_enter = max(t_enter, r)
            step("entering", p_k=p, q_k=q, r_k=r, t_enter=t_enter)
        else:
            t_leave = min(t_leave, r)
            step("leaving", p_k=p, q_k=q, r_k=r, t_leave=t_leave)
        if t_enter > t_leave:
            return "reject"
    return "accept"

step(clip(), t_enter=t_enter, t_leave=t_leave)
