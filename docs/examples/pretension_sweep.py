"""A pretension sweep (docs/python.md): pay every line's top segment out and
in, and plot the pretension against the largest fairlead tension and the
offset of a load case.

    PYTHONPATH=build/python python3 docs/examples/pretension_sweep.py [PROJECT] [CASE] [POINTS] [PLOT]
"""
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import numpy as np

import spiral

project_file = sys.argv[1] if len(sys.argv) > 1 else "scenarios/deepwater-fps.yaml"
case = sys.argv[2] if len(sys.argv) > 2 else "lc1-survival-collinear-0deg"
points = int(sys.argv[3]) if len(sys.argv) > 3 else 9
plot_file = sys.argv[4] if len(sys.argv) > 4 else "pretension_sweep.png"

p = spiral.load(project_file)
top = {name: line.segments[-1].length for name, line in p.lines.items()}  # m, as written
payouts_m = np.linspace(-10.0, 10.0, points)  # negative hauls in
pretension_kN, max_tension_kN, offset_m = [], [], []
for payout in payouts_m:
    for name, line in p.lines.items():
        line.segments[-1].length = top[name] + payout
    pretension_kN.append(p.statics().fairlead_tension_N.mean() / 1e3)  # hull at rest, still water
    eq = p.equilibrium(case=case)
    max_tension_kN.append(eq.fairlead_tension_N.max() / 1e3)
    offset_m.append(eq.offset["horizontal_m"])

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
left.plot(pretension_kN, max_tension_kN, "o-")
left.set(xlabel="mean pretension, kN", ylabel=f"largest fairlead tension in {case}, kN")
right.plot(pretension_kN, offset_m, "o-")
right.set(xlabel="mean pretension, kN", ylabel=f"static offset in {case}, m")
fig.savefig(plot_file, dpi=120)
for payout, t0, offset in zip(payouts_m, pretension_kN, offset_m):
    print(f"payout {payout:+6.2f} m: pretension {t0:8.1f} kN, offset {offset:6.2f} m")
