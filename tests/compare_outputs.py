#!/usr/bin/env python3
"""Compare the output directories of two runs of the same input byte for
byte: every file (VTU, PVTU, PVD, parameters.prm, ...) must be identical,
history.csv without its wall-clock column (wall_seconds) and summary.json
without its wall-clock entries (every "..._seconds" entry and the
"timings" block). Everything else, numbers included, must agree to the
last digit. Prints the first difference; exit 1 if any.

Usage: compare_outputs.py DIRECTORY_A DIRECTORY_B
"""
import os
import re
import sys

# summary.json: one entry per line; the timings block spans several.
SECONDS_ENTRY = re.compile(rb'^\s*"[^"]*_seconds": [^\n]*\n', re.M)
TIMINGS_BLOCK = re.compile(rb'\n\s*"timings": \{.*?\n\s*\}', re.S)


def summary_text(data):
    """summary.json without its wall-clock entries, and their names."""
    names = sorted(re.findall(rb'"([^"]*_seconds)": ', data))
    return TIMINGS_BLOCK.sub(b"", SECONDS_ENTRY.sub(b"", data)), names


def history_text(data):
    """history.csv without the wall_seconds column."""
    lines = data.split(b"\n")
    header = lines[0].split(b",")
    drop = [k for k, h in enumerate(header) if h.startswith(b"wall_seconds")]
    if len(drop) != 1:
        raise ValueError("history.csv has %d wall_seconds columns" % len(drop))
    out = []
    for line in lines:
        cells = line.split(b",")
        if len(cells) == len(header):
            del cells[drop[0]]
        out.append(b",".join(cells))
    return b"\n".join(out), None


def files(root):
    found = []
    for folder, _, names in os.walk(root):
        for name in names:
            found.append(os.path.relpath(os.path.join(folder, name), root))
    return sorted(found)


def first_difference(a, b):
    for k, (x, y) in enumerate(zip(a, b)):
        if x != y:
            start = max(0, k - 40)
            return k, a[start:k + 40], b[start:k + 40]
    return min(len(a), len(b)), a[-40:], b[-40:]


def main():
    a, b = sys.argv[1], sys.argv[2]
    names_a, names_b = files(a), files(b)
    if names_a != names_b:
        print("FAIL: different files: %s" %
              sorted(set(names_a) ^ set(names_b)))
        return 1
    if "summary.json" not in names_a or "history.csv" not in names_a:
        print("FAIL: %s has no summary.json or history.csv" % a)
        return 1
    failed, compared, size = 0, 0, 0
    for name in names_a:
        data_a = open(os.path.join(a, name), "rb").read()
        data_b = open(os.path.join(b, name), "rb").read()
        extra = None
        if os.path.basename(name) == "summary.json":
            data_a, extra = summary_text(data_a)
            data_b, extra_b = summary_text(data_b)
            if extra != extra_b:
                print("FAIL %s: other wall-clock entries" % name)
                failed += 1
        elif os.path.basename(name) == "history.csv":
            data_a, _ = history_text(data_a)
            data_b, _ = history_text(data_b)
        compared += 1
        size += len(data_a)
        if data_a != data_b:
            k, x, y = first_difference(data_a, data_b)
            print("FAIL %s differs at byte %d:\n  %r\n  %r" % (name, k, x, y))
            failed += 1
    print("%d files, %d bytes compared (less the wall-clock entries): %s" %
          (compared, size, "identical" if failed == 0 else
           "%d differ" % failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
