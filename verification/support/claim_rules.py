#!/usr/bin/env python3
"""The rules that turn a claim's value into PASS, FAIL or UNDECIDED (scripts/reproduce, evaluate_claims).

A claim on an ensemble mean with a `standard_error` is decided only where the band of two standard errors around
its value lies on one side of the tolerance's edge: a mean that a draw of packings could move across the edge
is UNDECIDED, whichever side it lies on, and so is a mean without a spread (one packing). Exact values, no
tolerance: the cases are built on either side of the edge by a margin far above round-off.
"""
import importlib.machinery
import importlib.util
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def load_reproduce():
    loader = importlib.machinery.SourceFileLoader("reproduce", str(ROOT / "scripts" / "reproduce"))
    spec = importlib.util.spec_from_loader("reproduce", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def figure_with(exponent, standard_error, scales=("default",)):
    """One run whose summary holds an ensemble mean and its standard error; one claim on it: 1 within 0.1."""
    records = [{"summary": {"pressure_exponent": exponent, "pressure_exponent_standard_error": standard_error},
                "exit_code": 0, "parameters": {"model": "shell"}}]
    figure = {"claim": [{"text": "exponent 1", "source": "test", "reference": 1.0, "abs_tol": 0.1, "why": "test",
                         "ours": "run(model='shell')['pressure_exponent']",
                         "standard_error": "run(model='shell')['pressure_exponent_standard_error']",
                         "scales": list(scales)}]}
    return figure, records


def main():
    reproduce = load_reproduce()
    failures = []

    def expect(exponent, standard_error, status, scale="default"):
        figure, records = figure_with(exponent, standard_error)
        claim = reproduce.evaluate_claims(figure, records, scale, {})[0]
        line = f"mean {exponent}, SE {standard_error}, scale {scale}: {claim['status']}"
        print(line + (f" ({claim['undecided_because']})" if claim.get("undecided_because") else ""))
        if claim["status"] != status:
            failures.append(f"{line}, expected {status}")

    # The edge is |ours - 1| = 0.1. Two SE = 0.04 beside a distance of 0.067 decides; 0.06 beside 0.05 does not.
    expect(0.967, 0.02, "PASS")       # band [0.927, 1.007] inside the tolerance
    expect(0.85, 0.02, "FAIL")        # band [0.81, 0.89] outside it
    expect(0.95, 0.03, "UNDECIDED")   # passes, but the band [0.89, 1.01] reaches across 0.9
    expect(0.87, 0.03, "UNDECIDED")   # fails, but the band [0.81, 0.93] reaches across 0.9
    expect(0.967, None, "UNDECIDED")  # one packing: no spread (the scene writes null)
    expect(0.967, math.nan, "UNDECIDED")
    expect(0.85, 0.02, "UNDECIDED", scale="smoke")  # a scale the claim does not list decides nothing
    # Without standard_error the claim is decided by its value alone, as before.
    figure, records = figure_with(0.95, 0.03)
    del figure["claim"][0]["standard_error"]
    status = reproduce.evaluate_claims(figure, records, "default", {})[0]["status"]
    if status != "PASS":
        failures.append(f"a claim without standard_error at 0.95 is {status}, expected PASS")
    for failure in failures:
        print("FAIL:", failure)
    print(f"claim_rules: {'FAIL' if failures else 'PASS'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
