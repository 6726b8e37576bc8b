"""The Python API in one go (docs/python.md): load, edit, the analyses, save.

    PYTHONPATH=build/python python3 docs/examples/quickstart.py [PROJECT] [DURATION_S]
"""
import sys

import spiral

project_file = sys.argv[1] if len(sys.argv) > 1 else "scenarios/deepwater-fps.yaml"
duration_s = float(sys.argv[2]) if len(sys.argv) > 2 else 3600.0

p = spiral.load(project_file)  # validated; errors raise spiral.InputError with file:line:col
p.lines["L3"].segments[1].length += 2.0  # edit the model in memory (re-validated on use)
s = p.statics(offset=[10, 0, 0, 0, 0, 0])  # per-line results; s.fairlead_tension_N is a numpy array
print("fairlead tensions at 10 m surge, kN:", (s.fairlead_tension_N / 1e3).round(1))

eq = p.equilibrium(case="lc1-survival-collinear-0deg")  # offsets, per-line and per-riser results
print(f"lc1 offset {eq.offset['horizontal_m']:.2f} m, worst riser utilization "
      f"{eq.column('risers', 'utilization').max():.3f}")

K = p.stiffness(case="lc1-survival-collinear-0deg")  # 6x6 numpy array
print(f"surge stiffness {K[0, 0] / 1e3:.1f} kN/m")

z = p.soz(model="catenary", step_deg=5)  # zones as arrays (direction, allowable offset, governing criterion)
tightest = z.platform["allowable_offset_m"].argmin()
print(f"tightest zone: {z.platform['allowable_offset_m'][tightest]:.1f} m towards {z.directions_deg[tightest]:.0f} deg "
      f"({z.platform['governing_riser'][tightest]}: {z.platform['governing_criterion'][tightest]})")

ts = p.analyze(case="lc1-survival-collinear-0deg", level="sc-enhanced", duration=duration_s, seed=1)
print(f"surge: max {ts.surge_m.max():.2f} m, 3-h MPM {ts.channel('surge_m')['mpm_max_3h']['weibull']:.2f} m")

opt = p.optimize(objective="max_soz_margin")
print(f"optimization: {opt['status']}, largest offset / SOZ {opt['objective']['start']:.3f} -> "
      f"{opt['objective']['best']:.3f}")

p.save("variant.yaml")  # writes a valid project file: the original text, L3's length changed
