#!/usr/bin/python3
"""Parameter tables of doc/user-guide.md, generated from the JSON listing.

Usage: scripts/parameter_tables.py PNEUMA (--write | --check) DOC.md

Runs `PNEUMA --print-parameters-json` (one template of each repeated
subsection, every variant) and replaces, in DOC.md, each block

    <!-- parameters: Section -->
    ...
    <!-- end parameters -->

by a table of every entry of the top-level subsection "Section": entry path
(below the section), default, allowed values, documentation. Template
instances are shown as "Region <id>", "Cable <k>", "Chamber <k>",
"Pair <k>", "Tie <k>", "Obstacle <k>". --check exits 1 (naming the sections) if DOC.md is not up to
date, so a test keeps the manual in step with the code.
"""
import json
import re
import subprocess
import sys

TEMPLATES = {r"^Region 0$": "Region <id>", r"^Cable 1$": "Cable <k>",
             r"^Chamber 1$": "Chamber <k>", r"^Pair 1$": "Pair <k>",
             r"^Tie 1$": "Tie <k>", r"^Obstacle 1$": "Obstacle <k>"}


def template_name(name):
    for pattern, shown in TEMPLATES.items():
        if re.match(pattern, name):
            return shown
    return name


def cell(text):
    return text.replace("|", "\\|").replace("\n", " ").strip()


def allowed(description):
    """The pattern in words: "number >= 0", "integer 1..25", "a, b"."""
    d = re.sub(r"\s+\(inclusive\)", "", description.strip("[]").strip())
    big = r"(?:MAX_DOUBLE|1\.79769e\+308|2147483647|4294967295)"
    m = re.fullmatch(r"Double (-?)" + big + r"\.\.\." + big, d)
    if m:
        return "number"
    m = re.fullmatch(r"(Double|Integer range) (-?[0-9.e+-]+)\.\.\.(\S+)", d)
    if m:
        kind = "number" if m.group(1) == "Double" else "integer"
        lo, hi = m.group(2), m.group(3)
        if re.fullmatch(big, hi):
            return f"{kind} >= {lo}"
        return f"{kind} in [{lo}, {hi}]"
    if d.startswith("Selection "):
        return ", ".join(f"`{v.strip()}`" for v in d[10:].split("|"))
    if d == "Bool":
        return "`true`, `false`"
    if d == "Anything":
        return "text"
    m = re.fullmatch(r"List of <\[(.*)\]> of length (\d+)\.\.\.(\S+)", d)
    if m:
        inner = allowed("[" + m.group(1) + "]")
        n = (f"{m.group(2)}" if m.group(2) == m.group(3) else
             f"at least {m.group(2)}" if re.fullmatch(big, m.group(3)) else
             f"{m.group(2)} to {m.group(3)}")
        return f"list of {n} ({inner})"
    return d


# deal.II's ParsedFunction entries carry a long generic text; the tables
# say it once, short.
PARSED_FUNCTION = {
    "Function constants": "constants of the expression, `a=1, b=2`",
    "Function expression": "muparser expression of the variables; vector "
                           "components separated by `;`",
    "Variable names": "the variables: reference position and pseudo time",
}


def rows(tree, path=()):
    for key in sorted(tree):
        value = tree[key]
        if isinstance(value, dict) and "default_value" in value:
            entry = " / ".join(path + (key,))
            doc = value.get("documentation", "")
            if key in PARSED_FUNCTION and doc.startswith(
                    ("Sometimes it is convenient", "The formula that",
                     "The names of the variables")):
                doc = PARSED_FUNCTION[key]
            # The value set at declaration (a function's own default
            # expression), not deal.II's generic default.
            yield (entry, value.get("value", value["default_value"]),
                   allowed(value.get("pattern_description", "")), doc)
        elif isinstance(value, dict):
            yield from rows(value, path + (template_name(key),))


def table(tree):
    lines = ["| entry | default | allowed | meaning |", "|---|---|---|---|"]
    for entry, default, pattern, doc in rows(tree):
        lines.append(f"| {cell(entry)} | `{cell(default)}` | {cell(pattern)} "
                     f"| {cell(doc)} |" if default else
                     f"| {cell(entry)} | | {cell(pattern)} | {cell(doc)} |")
    return "\n".join(lines)


def main(argv):
    if len(argv) != 4 or argv[2] not in ("--write", "--check"):
        sys.exit(__doc__)
    pneuma, mode, doc = argv[1], argv[2], argv[3]
    listing = json.loads(subprocess.run([pneuma, "--print-parameters-json"],
                                        check=True, capture_output=True,
                                        text=True).stdout)
    text = open(doc).read()
    block = re.compile(r"(<!-- parameters: (.+?) -->\n)(.*?)(<!-- end parameters -->)",
                       re.S)
    stale, seen = [], set()

    def replace(m):
        section = m.group(2).strip()
        seen.add(section)
        if section not in listing:
            sys.exit(f"parameter_tables: {doc}: no section '{section}' in the listing")
        new = table(listing[section]) + "\n"
        if new != m.group(3):
            stale.append(section)
        return m.group(1) + new + m.group(4)

    updated = block.sub(replace, text)
    missing = [s for s in listing if s not in seen]
    if mode == "--check":
        if stale or missing:
            print("parameter_tables: doc out of date; sections changed:",
                  ", ".join(stale) or "-", "; sections without a table:",
                  ", ".join(missing) or "-")
            print("run: scripts/parameter_tables.py build/pneuma --write", doc)
            return 1
        print(f"parameter_tables: {doc} matches the code ({len(seen)} sections)")
        return 0
    open(doc, "w").write(updated)
    print(f"parameter_tables: wrote {len(seen)} tables; without a table:",
          ", ".join(missing) or "-")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
