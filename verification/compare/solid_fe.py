#!/usr/bin/env python3
"""Checks the finite-element reference of compare.solid, data/compare/solid_fe.toml (written by
scripts/fe-solid-compression): a ball (D = 1, E = 1) between two rigid frictionless plates, F~ = F (1 - nu^2)/(E D^2)
against delta~ = delta/D, for Saint Venant-Kirchhoff and compressible neo-Hookean at nu = 0.3 and 0.25.

  solid_fe.py            the stored data against theory (needs only Python >= 3.11, or tomli)
  solid_fe.py --data FILE   another study file (default data/compare/solid_fe.toml)
  solid_fe.py --rerun    reruns `scripts/fe-solid-compression --quick` with /usr/bin/python3 and compares it with
                         the stored study within the quick mesh's error; exits 77 (ctest SKIP_RETURN_CODE) when
                         /usr/bin/python3 cannot import dolfinx

Tolerances, each from theory or from the stored error estimates (error = |F~(finest) - F~(next coarser)|):
 * Hertz limit. Hertz is the leading term of F~ = (1/3) delta~^(3/2) (1 + O(a/R)), a/R = delta~^(1/2) the Hertz contact
   radius over the ball radius: the next corrections (the compliance of the finite ball, which adds O(F/(E R)) to the
   approach; geometric and material nonlinearity, of the order of the contact strain ~ a/R) are all of relative
   order delta~^(1/2). So at the smallest delta~ the check is |F~/F~_Hertz - 1| <= delta~^(1/2) + error/F~_Hertz
   (coefficient 1 on the next order: 0.032 at delta~ = 1e-3); the same bound holds at every delta~ <= 0.01, so
   that the deviation vanishes at least like delta~^(1/2). (Measured coefficients: SVK -0.06 ... +0.03, neo-Hookean
   +0.33 ... +0.46 over 1e-3 <= delta~ <= 1e-2.)
 * Monotonic force: F~ strictly increases along the delta~ grid wherever the solution converged, and every step
   is larger than the sum of the two stored errors (so the increase is resolved).
 * SVK against neo-Hookean at small strain: the two energies have the same second-order (linear-elastic) term,
   so their forces differ at relative order strain ~ delta~^(1/2) and must agree at zero strain. The relative
   difference d = F~_nh/F~_svk - 1 over the six smallest delta~ is fitted by d = d0 + d1 delta~^(1/2); the
   extrapolated d0 must vanish within 3 times the stored relative errors there (plus the fit's own residual).
"""

import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python < 3.11
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "data" / "compare" / "solid_fe.toml"
SCRIPT = ROOT / "scripts" / "fe-solid-compression"
FE_PYTHON = os.environ.get("SOFTGRAIN_FE_PYTHON", "/usr/bin/python3")  # the Debian FEniCSx interpreter
SKIP = 77
CASES = [("svk", 0.3), ("nh", 0.3), ("svk", 0.25), ("nh", 0.25)]

failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def load(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


def cases_of(data):
    return {(c["law"], c["nu"]): c for c in data["case"]}


def hertz(d):
    return d ** 1.5 / 3


def finite(x):
    return isinstance(x, float) and math.isfinite(x)


def check_stored(data):
    cases = cases_of(data)
    check(not data["quick"] and data["levels"] >= 4, f"full study stored ({data['levels']} mesh levels, >= 4)")
    for key in CASES:
        check(key in cases, f"case {key[0]} nu = {key[1]} stored")
    for (law, nu), c in cases.items():
        name = f"{law} nu={nu}"
        d, f, e = c["delta_over_d"], c["force"], c["error"]
        check(all(finite(f[i]) and finite(e[i]) for i in range(len(d)) if d[i] <= 0.2 + 1e-12),
              f"{name}: converged with an error estimate at every delta~ <= 0.2")
        # Hertz limit at the smallest delta~.
        dev0 = f[0] / hertz(d[0]) - 1
        tol0 = math.sqrt(d[0]) + e[0] / hertz(d[0])
        check(abs(dev0) <= tol0, f"{name}: Hertz limit at delta~ = {d[0]:.3g}: F/F_H - 1 = {dev0:+.2e}, "
                                 f"|.| <= delta~^(1/2) + err/F_H = {tol0:.2e}")
        # The deviation vanishes at least as fast as the next order: the same bound at every delta~ <= 0.01.
        ratios = [(f[i] / hertz(d[i]) - 1) / math.sqrt(d[i]) for i in range(len(d)) if d[i] <= 0.01 + 1e-9]
        bad = [(round(d[i], 5), round(ratios[i], 3)) for i in range(len(ratios))
               if abs(ratios[i]) > 1 + e[i] / hertz(d[i]) / math.sqrt(d[i])]
        check(not bad, f"{name}: |F/F_H - 1|/delta~^(1/2) <= 1 (+ errors) at every delta~ <= 0.01: from "
                       f"{ratios[0]:+.3f} to {ratios[-1]:+.3f} {bad}")
        # Monotonic force, resolved by the errors.
        idx = [i for i in range(len(d)) if finite(f[i])]
        steps = [(f[j] - f[i], e[i] + e[j], d[j]) for i, j in zip(idx, idx[1:])]
        bad = [(round(dj, 4), round(df, 8)) for df, tol, dj in steps if not df > tol]
        check(not bad, f"{name}: F~ increases by more than the errors at every step up to delta~ = "
                       f"{d[idx[-1]]:.3g} (violations: {bad})")
    # SVK against neo-Hookean at small strain.
    for nu in sorted({nu for _, nu in CASES}):
        s, n = cases.get(("svk", nu)), cases.get(("nh", nu))
        if not s or not n:
            continue
        d = s["delta_over_d"][:6]
        rel = [n["force"][i] / s["force"][i] - 1 for i in range(6)]
        err = [(n["error"][i] + s["error"][i]) / s["force"][i] for i in range(6)]
        xs = [math.sqrt(x) for x in d]
        mx, my = sum(xs) / 6, sum(rel) / 6
        d1 = sum((x - mx) * (y - my) for x, y in zip(xs, rel)) / sum((x - mx) ** 2 for x in xs)
        d0 = my - d1 * mx
        resid = max(abs(y - d0 - d1 * x) for x, y in zip(xs, rel))
        tol = 3 * max(err) + resid
        check(abs(d0) <= tol, f"nu={nu}: F_nh/F_svk - 1 = d0 + d1 delta~^(1/2) over delta~ <= {d[-1]:.2g}: "
                              f"d0 = {d0:+.2e} (|.| <= 3 max rel. error + fit residual = {tol:.1e}), d1 = {d1:+.3f}")


def check_rerun(data):
    try:
        probe = subprocess.run([FE_PYTHON, "-c", "import dolfinx, gmsh"], capture_output=True)
    except OSError:
        probe = None
    if probe is None or probe.returncode != 0:
        print(f"SKIP: {FE_PYTHON} cannot import dolfinx and gmsh (scripts/install-deps --fe)")
        sys.exit(SKIP)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "quick.toml")
        subprocess.run([FE_PYTHON, str(SCRIPT), "--quick", "--quiet", "--out", out], check=True)
        quick = load(out)
    stored = cases_of(data)
    check(quick["quick"] and quick["levels"] == 1, "the rerun is the quick, single-mesh run")
    for key, q in cases_of(quick).items():
        name = f"{key[0]} nu={key[1]}"
        s = stored[key]
        coarse = s["mesh"][0]
        check(abs(coarse["h_pole"] - q["mesh"][0]["h_pole"]) < 1e-12, f"{name}: quick mesh = stored level 0")
        d, fq, fs, es, f0 = q["delta_over_d"], q["force"], s["force"], s["error"], coarse["force"]
        worst, worst_repro, bad = 0.0, 0.0, []
        for i in range(len(d)):
            if d[i] > 0.2 + 1e-12:
                continue
            # Expected error of the quick (level-0) mesh: its stored distance from the finest level plus the
            # finest level's own error; the tolerance is 1.5 times that.
            tol = 1.5 * (abs(f0[i] - fs[i]) + es[i])
            if not (finite(fq[i]) and abs(fq[i] - fs[i]) <= tol):
                bad.append(f"delta~ = {d[i]:.4g}: quick {fq[i]:.6e}, stored {fs[i]:.6e}, tolerance {tol:.2e}")
                continue
            worst = max(worst, abs(fq[i] - fs[i]) / tol)
            worst_repro = max(worst_repro, abs(fq[i] - f0[i]) / abs(f0[i]))
        check(not bad, f"{name}: quick run within 1.5 x its expected error of the stored values at every "
                       f"delta~ <= 0.2 (largest |diff|/tolerance {worst:.2f}; largest relative change from the "
                       f"stored level 0 {worst_repro:.1e}) {bad}")


def main():
    path = DATA
    if "--data" in sys.argv[1:]:
        path = Path(sys.argv[sys.argv.index("--data") + 1])
    data = load(path)
    if "--rerun" in sys.argv[1:]:
        check_rerun(data)
    else:
        check_stored(data)
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
