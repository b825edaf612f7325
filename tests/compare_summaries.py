#!/usr/bin/env python3
"""Compare two summary.json files of the same scene: every number (counts
and physics; not wall times, timings or the message) must agree to a
relative tolerance. The scale of a vector's component is the vector's
largest component (a round-off zero of a reaction is compared with the
reaction, not with itself). Prints reference, value, error and tolerance of the
worst entry; exit 1 if any entry differs by more.

Usage: compare_summaries.py REFERENCE.json VALUE.json [TOLERANCE]
"""
import json
import math
import re
import sys

# The last factorization's kind, size and work, and the analyses and
# seconds of the LDL^T, describe this process (a run restarted at its end
# factorizes nothing; a restarted one analyses its pattern again), not the
# result.
SKIP = {"wall_seconds", "timings", "message", "units", "mpi_ranks",
        "factorization_symmetric", "factor_entries", "factorization_gflop",
        "ldlt_analyses", "ldlt_orderings", "ldlt_analysis_seconds",
        "ldlt_factorization_seconds", "ldlt_solve_seconds"}


def flatten(value, prefix, out):
    if isinstance(value, dict):
        for k, v in value.items():
            if k not in SKIP:
                flatten(v, prefix + "/" + k if prefix else k, out)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            flatten(v, "%s[%d]" % (prefix, i), out)
    else:
        out[prefix] = value


def main():
    reference, value = ({}, {})
    flatten(json.load(open(sys.argv[1])), "", reference)
    flatten(json.load(open(sys.argv[2])), "", value)
    tolerance = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-10
    if set(reference) != set(value):
        print("FAIL entries differ:", sorted(set(reference) ^ set(value)))
        return 1
    scales = {}
    for key, ref in reference.items():
        if isinstance(ref, (int, float)) and not isinstance(ref, bool):
            base = re.sub(r"\[[0-9]+\]$", "", key)
            scales[base] = max(scales.get(base, 0.0), abs(ref))
    worst, worst_key = -1.0, None
    for key, ref in reference.items():
        val = value[key]
        if ref is None or val is None or isinstance(ref, str):
            if ref != val:
                print("FAIL %s: reference %s, value %s" % (key, ref, val))
                return 1
            continue
        scale = scales[re.sub(r"\[[0-9]+\]$", "", key)]
        error = abs(val - ref) / scale if scale > 0 else abs(val)
        if not math.isfinite(error) or error > worst:
            worst, worst_key = error, key
    if worst_key is None:
        print("FAIL no numbers to compare")
        return 1
    ok = worst <= tolerance
    print("%s %d entries; worst %s: reference %.12g, value %.12g, "
          "relative error %.3g, tolerance %.1g"
          % ("ok  " if ok else "FAIL", len(reference), worst_key,
             reference[worst_key], value[worst_key], worst, tolerance))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
