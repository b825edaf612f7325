#!/usr/bin/python3
"""Fuzz test of the parameter input: bad input never crashes.

Usage: fuzz_parameters.py PNEUMA SOURCE_DIR [--seconds 120] [--seed N]
                          [--case K] [--cpu-limit 120] [--timeout 900]
                          [--work DIR]

Mutates the shipped parameter files (SOURCE_DIR/parameter_files/*.prm and
SOURCE_DIR/tests/*.prm) for a fixed wall time: entries the file sets, or
any entry of `pneuma --print-parameters-json`, get values of the wrong
kind, out of range, empty, huge or not finite (through --set), or the
file's text is cut, lines are dropped, repeated or swapped. Each run is
cut short (Checkpoint/Stop after step = 2, at most two global refinements,
Newton/Maximum iterations = 6, so that an input that fails does so after
few iterations) and must
- exit with 0, 1 or 2 (never 3, a signal or a hang), on 1 rank or, for
  every eighth input, on 2. A hang is judged by CPU time, which does not
  depend on how busy the machine is: every process of a run may use
  --cpu-limit seconds of CPU (120; RLIMIT_CPU, then SIGXCPU), and a run
  that sleeps (a deadlock without spinning) is stopped after --timeout
  seconds of wall time (900);
- write no NaN or inf into any output (history.csv, summary.json, every
  VTU read back with VTK, tests/check_outputs_finite.py);
- with exit 1, print its message and leave no output but a summary.json
  that records the error.
Case K of seed S is the same input on every machine; the seed is fixed
(46) unless --seed or FUZZ_SEED gives another, so every run tries a prefix
of the same sequence of inputs. It is printed first, and a failure prints
the command that repeats it (--seed S --case K). Exits 1 if any input
failed; prints how many inputs it tried.
"""
import argparse
import glob
import json
import math
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_outputs_finite  # noqa: E402

# Values of the wrong kind, out of range, empty, huge, not finite.
WRONG = ["", " ", "abc", "true", "no", "-1", "0", "-0", "1e300", "-1e300",
         "1e-300", "nan", "inf", "-inf", "NaN", "1e20", "4294967296",
         "-2147483649", "18446744073709551616", "3.5", "1,2", "1, 2, 3, 4",
         "1;2;3", "0: xyz", "x", "t", "sin(", "1/0", "sqrt(-1)", "#", "\\",
         "a=b", "0x10", "1e", ".", "-", "{}", "[]", "'", '"', "9" * 400,
         "é", "1e308*10", "-1e-320", "0,0,0; 0,0,0", "t*1e300",
         "if(t<0.5,1,nan)", "log(t)", "1: sphere 0,0,0"]
# Entries that place or silence the run (set last by the fuzzer).
FIXED = ("Output/Directory", "Output/Test output", "Output/Quiet",
         "Checkpoint/Stop after step", "Newton/Maximum iterations")
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


def entries(text):
    """The (path, value) of every 'set' line of .prm text."""
    stack, result = [], []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("subsection "):
            stack.append(line[11:].strip())
        elif line == "end" and stack:
            stack.pop()
        elif line.startswith("set ") and "=" in line:
            name, value = line[4:].split("=", 1)
            result.append(("/".join(stack + [name.strip()]), value.strip()))
    return result


def instance_free(path):
    """@p path with the numbers of repeated subsections as <k>."""
    return re.sub(r"(Cable|Chamber|Pair|Tie|Region) \d+", r"\1 <k>", path)


def declared(pneuma):
    """Every entry of the template listing (--print-parameters-json):
    path -> (pattern description, default value)."""
    out = subprocess.run([pneuma, "--print-parameters-json"],
                         capture_output=True, text=True, check=True).stdout
    result = {}

    def walk(node, stack):
        for key, child in node.items():
            name = re.sub(r"_([0-9a-fA-F]{2})",
                          lambda m: chr(int(m.group(1), 16)), key)
            if isinstance(child, dict) and "value" in child:
                result["/".join(stack + [name])] = (
                    child.get("pattern_description", ""), child["value"])
            elif isinstance(child, dict):
                walk(child, stack + [name])
    walk(json.loads(out), [])
    return result


def mutate_value(rng, value):
    """A bad variant of the text @p value."""
    r = rng.random()
    numbers = list(NUMBER.finditer(value))
    if r < 0.3 or not value:
        return rng.choice(WRONG)
    if r < 0.8 and numbers:
        m = rng.choice(numbers)
        new = rng.choice(["1e300", "-1e300", "0", "-1", "nan", "inf",
                          "1e-300", "4294967297", "-" + m.group(0),
                          m.group(0) + "e300", m.group(0) + "x", "",
                          "1e6", "1e-9", m.group(0) + "0"])
        return value[:m.start()] + new + value[m.end():]
    if r < 0.9:
        items = re.split(r"([,;])", value)
        k = rng.randrange(len(items))
        items[k] = rng.choice(["", items[k] * 2, "1e300", "nan"])
        return "".join(items)
    return value[:rng.randrange(len(value) + 1)] + rng.choice(WRONG)


def extreme_value(rng, pattern, value):
    """A value that matches @p pattern but is extreme (bounds, zero,
    huge, tiny), or a mutation of @p value for free text and lists."""
    m = re.match(r"\[Double (\S+)\.\.\.(\S+) ", pattern)
    if m:
        lo, hi = (float(x.replace("MAX_DOUBLE", "1.7976e308"))
                  for x in m.groups())
        options = [x for x in (0., -0., 1e-300, 1e300, -1e300, 1e-12, 1e12,
                               -1., 1e6, 0.5, lo, hi, lo + 1e-9)
                   if lo <= x <= hi]
        return repr(rng.choice(options))
    m = re.match(r"\[Integer range (\S+)\.\.\.(\S+) ", pattern)
    if m:
        lo, hi = int(m.group(1)), int(m.group(2))
        options = [lo, min(lo + 1, hi), min(lo + 2, hi)]
        options.append(hi if hi - lo <= 64 else rng.choice([hi, 10**6]))
        return str(rng.choice(options))
    m = re.match(r"\[Selection (.*) \]", pattern)
    if m:
        return rng.choice(m.group(1).split("|"))
    if pattern.startswith("[Bool]"):
        return rng.choice(["true", "false"])
    return mutate_value(rng, value)


def mutate_text(rng, text):
    """The file's text with lines dropped, repeated, swapped or cut."""
    lines = text.splitlines()
    for _ in range(rng.randint(1, 3)):
        if not lines:
            break
        k = rng.randrange(len(lines))
        kind = rng.randrange(5)
        if kind == 0:
            del lines[k]
        elif kind == 1:
            lines.insert(k, lines[k])
        elif kind == 2:
            j = rng.randrange(len(lines))
            lines[k], lines[j] = lines[j], lines[k]
        elif kind == 3:
            lines[k] = lines[k][:rng.randrange(len(lines[k]) + 1)]
        else:
            lines = lines[:k]
    return "\n".join(lines) + "\n"


def make_case(rng, files, patterns):
    """One input: (base file, text or None, --set arguments)."""
    base = rng.choice(files)
    text = open(base).read()
    own = [e for e in entries(text) if e[0] not in FIXED]
    sets = []
    if rng.random() < 0.2:
        text = mutate_text(rng, text)
    else:
        text = None
    free = {instance_free(p): v for p, v in patterns.items()}
    count = rng.choice([1, 1, 1, 2, 2, 3]) - (text is not None)
    for _ in range(count):
        if own and rng.random() < 0.85:
            path, value = rng.choice(own)
        else:
            path = rng.choice([p for p in patterns if p not in FIXED])
            value = patterns[path][1]
        pattern = free.get(instance_free(path), ("", ""))[0]
        if rng.random() < 0.35:
            value = rng.choice(WRONG)
        else:
            value = extreme_value(rng, pattern, value)
        sets.append(f"{path}={value}")
    return base, text, sets


def outputs_clean(directory, code):
    """Problems of the outputs in @p directory after exit @p code."""
    if not os.path.isdir(directory):
        return []
    problems = []
    names = set(os.listdir(directory))
    if code == 1 and names - {"summary.json"}:
        problems.append("exit 1 left " + ", ".join(sorted(names)))
    for path in glob.glob(f"{directory}/**/*.vtu", recursive=True):
        problems += check_outputs_finite.check_vtu(path)
    for path in glob.glob(f"{directory}/**/summary.json", recursive=True):
        try:
            summary = json.load(open(path), parse_constant=float)
            if any(isinstance(v, float) and not math.isfinite(v)
                   for v in check_outputs_finite.walk(summary)):
                problems.append(f"{path}: non-finite number")
            if code == 1 and summary.get("exit_code") != 1:
                problems.append(f"{path}: exit_code is not 1")
        except ValueError as e:
            problems.append(f"{path}: {e}")
    for path in glob.glob(f"{directory}/**/history.csv", recursive=True):
        if re.search(r"(^|,)\s*[-+]?(nan|inf|infinity)\s*(?=,|$)",
                     open(path).read(), re.IGNORECASE | re.MULTILINE):
            problems.append(f"{path}: nan or inf")
    return problems


def run_case(args, k, files, patterns):
    """Run case @p k; returns (exit code, problems, command)."""
    rng = random.Random(f"{args.seed}-{k}")
    base, text, sets = make_case(rng, files, patterns)
    ranks = 2 if rng.random() < 0.125 else 1
    work = os.path.join(args.work, f"case-{k}")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    prm = base
    if text is not None:
        prm = os.path.join(work, os.path.basename(base))
        open(prm, "w").write(text)
    out = os.path.join(work, "out")
    fixed = [f"Output/Directory={out}", "Output/Quiet=true",
             "Output/Test output=false", "Checkpoint/Stop after step=2",
             "Newton/Maximum iterations=6"]
    # At most two global refinements (fewer leave the supports of the
    # cylinder scenes inside their rigid plates), unless mutated.
    refinements = dict(entries(open(base).read())).get(
        "Geometry/Global refinements", "0")
    if not any(s.startswith("Geometry/Global refinements=") for s in sets) \
            and refinements not in ("0", "1", "2"):
        fixed.append("Geometry/Global refinements=2")
    command = [args.pneuma, prm]
    for s in sets + fixed:
        command += ["--set", s]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    try:
        def cpu_limit():
            # Inherited by mpirun's ranks.
            resource.setrlimit(resource.RLIMIT_CPU,
                               (int(args.cpu_limit), int(args.cpu_limit) + 5))
        result = subprocess.run(command, cwd=args.source, capture_output=True,
                                text=True, errors="replace",
                                timeout=args.timeout, preexec_fn=cpu_limit)
        code, log = result.returncode, result.stdout + result.stderr
        if code == -signal.SIGXCPU or "CPU time limit" in log:
            code = "cpu-limit"
            log = (f"more than {args.cpu_limit:.0f} s of CPU (a hang, or far "
                   "too slow)\n" + log)
    except subprocess.TimeoutExpired:
        code = "timeout"
        log = (f"no answer within {args.timeout:.0f} s of wall time (a "
               "sleeping hang)")
    problems = []
    if code not in (0, 1, 2):
        problems.append(f"exit {code}: " + log.strip()[-2000:])
    else:
        problems += outputs_clean(out, code)
        if code == 1 and "pneuma: error in " not in log:
            problems.append("exit 1 without a message: " + log.strip()[-2000:])
    if not problems:
        shutil.rmtree(work, ignore_errors=True)
    if args.verbose:
        last = log.strip().splitlines()[-1:] or [""]
        print(f"case {k}: {os.path.basename(base)} "
              f"{'(text mutated) ' if text is not None else ''}{sets}: "
              f"exit {code}: {last[0][:160]}", flush=True)
    return code, problems, command, base, sets


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("pneuma")
    parser.add_argument("source")
    parser.add_argument("--seconds", type=float, default=120.)
    # A fixed seed by default: every run tries the same sequence of
    # inputs (as many of them as the time allows); FUZZ_SEED=N another.
    parser.add_argument("--seed", type=int,
                        default=int(os.environ.get("FUZZ_SEED", "46")))
    parser.add_argument("--case", type=int, default=None)
    parser.add_argument("--timeout", type=float, default=900.)
    parser.add_argument("--cpu-limit", type=float, default=120.)
    parser.add_argument("--work", default="fuzz")
    parser.add_argument("--verbose", action="store_true",
                        help="print every input and its outcome")
    args = parser.parse_args()
    args.pneuma = os.path.abspath(args.pneuma)
    args.source = os.path.abspath(args.source)
    args.work = os.path.abspath(args.work)
    print(f"fuzz_parameters: seed {args.seed} (repeat a case with --seed "
          f"{args.seed} --case K)", flush=True)
    files = sorted(glob.glob(f"{args.source}/parameter_files/*.prm")
                   + glob.glob(f"{args.source}/tests/*.prm"))
    patterns = declared(args.pneuma)
    # mpirun as root (containers) needs these, as in ctest.
    for key in ("OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM",
                "OMPI_MCA_rmaps_base_oversubscribe"):
        os.environ.setdefault(key, "1")
    os.makedirs(args.work, exist_ok=True)
    cases = [args.case] if args.case is not None else None
    start, k, failures, codes = time.time(), 0, 0, {}
    while True:
        if cases is not None:
            if not cases:
                break
            k = cases.pop()
        elif time.time() - start > args.seconds:
            break
        code, problems, command, base, sets = run_case(args, k, files,
                                                       patterns)
        codes[code] = codes.get(code, 0) + 1
        if problems:
            failures += 1
            print(f"FAIL case {k} ({os.path.relpath(base, args.source)}, "
                  f"{sets}):", flush=True)
            for p in problems:
                print("  " + p)
            print("  repeat: " + " ".join(
                f"'{c}'" if " " in c else c for c in sys.argv[:3])
                + f" --seed {args.seed} --case {k}")
            print("  command: " + " ".join(f"'{c}'" for c in command))
        k += 1
    tried = sum(codes.values())
    print(f"fuzz_parameters: {tried} inputs in {time.time() - start:.0f} s "
          f"(exit codes {dict(sorted(codes.items(), key=str))}), "
          f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
