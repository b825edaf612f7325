#!/usr/bin/env python3
"""List the longest functions and files of the C++ sources (the
architecture's "functions read on one screen", doc/architecture.md).

A function is a body whose opening brace stands alone on a line, at the
indentation of the signature before it (the committed .clang-format puts
it there), up to the closing brace at that indentation.

Usage: function_lengths.py [--over N] [--files] DIR...
"""
import os
import re
import sys


def functions(path):
    lines = open(path, encoding="utf-8", errors="replace").read().split("\n")
    found = []
    for i, line in enumerate(lines):
        m = re.match(r"^(\s*)\{\s*$", line)
        if not m or i == 0:
            continue
        indent = m.group(1)
        # The signature: the lines above up to a blank line or comment.
        j = i - 1
        while j >= 0 and lines[j].strip() and not lines[j].strip().startswith(("//", "*", "/*")) \
                and not lines[j].rstrip().endswith((";", "{", "}")):
            j -= 1
        signature = " ".join(l.strip() for l in lines[j + 1:i])
        if "(" not in signature or not lines[i - 1].startswith(indent) \
                or re.match(r"^(if|for|while|switch|else|do|try|catch|namespace|struct|class|enum)\b",
                            signature):
            continue
        if "=" in signature.split("(")[0]:
            continue  # a lambda or an initialisation
        for k in range(i + 1, len(lines)):
            if re.match("^" + indent + r"\}", lines[k]):
                name = re.search(r"([\w:~<>]+)\s*\(", signature)
                found.append((k - i + 1, name.group(1) if name else signature[:40], i + 1))
                break
    return found


def main():
    args = sys.argv[1:]
    over, files = 100, False
    if "--over" in args:
        k = args.index("--over")
        over = int(args[k + 1])
        del args[k:k + 2]
    if "--files" in args:
        files = True
        args.remove("--files")
    rows, sizes = [], []
    for top in args:
        for root, _, names in os.walk(top):
            for n in sorted(names):
                if n.endswith((".cc", ".h")):
                    p = os.path.join(root, n)
                    sizes.append((sum(1 for _ in open(p, errors="replace")), p))
                    for length, name, line in functions(p):
                        if length > over:
                            rows.append((length, "%s:%d %s" % (p, line, name)))
    for length, what in sorted(rows, reverse=True):
        print("%5d  %s" % (length, what))
    print("%d functions over %d lines" % (len(rows), over))
    if files:
        for n, p in sorted(sizes, reverse=True)[:15]:
            print("%5d  %s" % (n, p))


if __name__ == "__main__":
    main()
