#!/usr/bin/env python3
"""A randomised front-end fuzz of `softgrain run` (issue 21): random --set values and random TOML scene files
over every scene's parameters, each run with a short timeout. The only allowed outcomes are

- exit 0 with a complete result whose summary has no non-finite value ("nan", "inf" outside `parameters`),
- exit 2 (refused input) or 3 (diagnosed numerical failure) with a message and no result,
- the timeout's SIGTERM (exit 143: the run was fine, only longer than the fuzz allows),
- exit 4 "out of memory" under the address-space limit the fuzz sets (so that a large but admissible size
  cannot take the machine's memory),

and in every case no hidden partial directory left in --out. Anything else (an abort, a segfault, exit 5, a
leftover) fails, printing the command line to reproduce it. The seed is printed; pass --seed to replay.

Usage: fuzz_cli.py SOFTGRAIN [--runs N] [--seed S] [--timeout SECONDS]"""
import argparse
import os
import json
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

MEMORY_LIMIT = 4 << 30  # bytes of address space per run


def parameters_of(softgrain, scene):
    """(name, default text, allowed text) of each parameter, read from `softgrain describe`."""
    lines = subprocess.run([softgrain, "describe", scene], capture_output=True, text=True, check=True).stdout
    specs = []
    for line in lines.splitlines()[3:]:
        fields = line.split()
        if len(fields) >= 2:
            allowed = re.search(r"\(([^()]*)\)\s*$", line)
            specs.append((fields[0], fields[1], allowed.group(1) if allowed else ""))
    return specs


def hostile_number(rng):
    return rng.choice(["0", "-1", "1e308", "-1e308", "1e-300", "4.9e-324", "nan", "inf", "-inf", "2147483648",
                       "9223372036854775808", "1e999", "0x10", "", "1,5"])


def random_value(rng, default, allowed):
    """A value for one parameter: mostly a plausible change of the default, sometimes a hostile one."""
    if rng.random() < 0.3:
        return hostile_number(rng) if rng.random() < 0.8 else rng.choice(["yes", "[1, 2]", "ünïcode", "a=b"])
    if allowed.startswith("one of"):
        return rng.choice(allowed[len("one of"):].split("|")).strip()
    if default in ("true", "false"):
        return rng.choice(["true", "false"])
    try:
        value = float(default)
    except ValueError:
        return default
    if allowed.startswith("an integer"):
        return str(max(0, int(value * rng.choice([0.5, 1, 2, 3]) + rng.choice([-1, 0, 1]))))
    return repr(value * 10 ** rng.uniform(-2, 2) if value else rng.uniform(-1, 1))


def toml_literal(text):
    """The --set text as a TOML value: numbers and true/false as they are, anything else as a string."""
    if re.fullmatch(r"-?(inf|nan|\d+(\.\d*)?([eE][-+]?\d+)?)|true|false", text):
        return text
    return json.dumps(text)


def leftovers(out):
    return [p.name for p in out.iterdir() if p.name.startswith(".")] if out.exists() else []


def non_finite_results(summary):
    found = []

    def walk(value, path):
        if isinstance(value, str) and value in ("nan", "inf", "-inf"):
            found.append(path)
        elif isinstance(value, list):
            for i, item in enumerate(value):
                walk(item, f"{path}[{i}]")
        elif isinstance(value, dict):
            for key, item in value.items():
                walk(item, f"{path}.{key}")
    for key, value in summary.items():
        if key != "parameters":
            walk(value, key)
    return found


def judge(result, out, scene_dir):
    """The reason this outcome is not allowed, or None."""
    if leftovers(out):
        return f"left {leftovers(out)} in --out"
    code = result.returncode
    if code == 0:
        summary_file = out / scene_dir / "summary.json"
        if not summary_file.exists():
            return "exit 0 without summary.json"
        bad = non_finite_results(json.loads(summary_file.read_text()))
        return f"exit 0 with non-finite results {bad}" if bad else None
    if code in (2, 3):
        if (out / scene_dir).exists():
            return f"exit {code} left a result directory"
        return None if result.stderr.strip() else f"exit {code} without a message"
    if code in (124, 143, -15):  # the fuzz's timeout: SIGTERM, handled by softgrain
        return None
    if code == 4 and "out of memory" in result.stderr:
        return None
    return f"exit {code}: {result.stderr.strip()[-300:]}"


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def sanitized_environment():
    """AddressSanitizer reserves terabytes of address space for its shadow memory, so RLIMIT_AS cannot bound a
    sanitized run: its allocator refuses single allocations above the same limit instead (operator new then
    throws bad_alloc, which softgrain reports as out of memory)."""
    options = [os.environ.get("ASAN_OPTIONS", ""), "allocator_may_return_null=1",
               f"max_allocation_size_mb={MEMORY_LIMIT >> 20}"]
    return dict(os.environ, ASAN_OPTIONS=":".join(o for o in options if o))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("softgrain")
    parser.add_argument("--runs", type=int, default=120)
    parser.add_argument("--seed", type=int, default=random.SystemRandom().randrange(2**32))
    parser.add_argument("--timeout", type=float, default=4.0)
    parser.add_argument("--sanitized", action="store_true",
                        help="softgrain is built with AddressSanitizer (make verify-sanitize)")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    print(f"fuzz_cli: seed {args.seed} (replay with --seed {args.seed}), {args.runs} runs")
    scenes = [line.split()[0] for line in
              subprocess.run([args.softgrain, "list"], capture_output=True, text=True, check=True).stdout.splitlines()]
    specs = {scene: parameters_of(args.softgrain, scene) for scene in scenes}
    failures, outcomes = [], {}
    work = Path(tempfile.mkdtemp(prefix="softgrain-fuzz-"))
    try:
        for k in range(args.runs):
            scene = rng.choice(scenes)
            chosen = rng.sample(specs[scene], min(len(specs[scene]), rng.choice([1, 1, 2, 3])))
            values = {name: random_value(rng, default, allowed) for name, default, allowed in chosen}
            out = work / f"run{k}"
            if rng.random() < 0.3:  # a TOML scene file instead of --set
                scene_file = work / f"fuzz{k}.toml"
                scene_file.write_text(f'scene = "{scene}"\n' + "".join(
                    f"{name} = {toml_literal(text)}\n" for name, text in values.items()))
                command, scene_dir = [args.softgrain, "run", str(scene_file)], scene_file.stem
            else:
                command, scene_dir = [args.softgrain, "run", scene], scene
                for name, text in values.items():
                    command += ["--set", f"{name}={text}"]
            command += ["--quiet", "--out", str(out)]
            try:
                memory = dict(env=sanitized_environment()) if args.sanitized else dict(preexec_fn=limit_memory)
                result = subprocess.run(["timeout", "-s", "TERM", str(args.timeout)] + command, capture_output=True,
                                        text=True, timeout=args.timeout + 30, **memory)
            except subprocess.TimeoutExpired:
                failures.append((command, "did not stop within 30 s of SIGTERM"))
                continue
            outcomes[result.returncode] = outcomes.get(result.returncode, 0) + 1
            problem = judge(result, out, scene_dir)
            if problem:
                failures.append((command, problem))
            shutil.rmtree(out, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("fuzz_cli: exit codes " + ", ".join(f"{code}: {n}" for code, n in sorted(outcomes.items())))
    for command, problem in failures:
        print(f"FAILED: {problem}\n  {' '.join(command)}")
    print(f"fuzz_cli: {len(failures)} of {args.runs} runs not allowed (seed {args.seed})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
