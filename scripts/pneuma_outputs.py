"""Read pneuma's outputs in scripts: history.csv with its "name [unit]"
columns keyed by name (units dropped), and summary.json.

    import sys; sys.path.insert(0, "scripts"); import pneuma_outputs as po
    rows = po.history("output/airbeam")        # list of {name: float}
    units = po.history_units("output/airbeam") # {name: unit}
    s = po.summary("output/airbeam")          # the parsed summary.json
"""
import csv
import json


def _name(header):
    return header.split(" [")[0].strip()


def history(directory):
    """Rows of DIRECTORY/history.csv as {column name: float}."""
    with open(f"{directory}/history.csv") as f:
        reader = csv.reader(f)
        names = [_name(h) for h in next(reader)]
        # An empty field is a value that was not finite or not computed
        # (e.g. the stability columns of the reference state): NaN.
        return [{n: float(v) if v else float("nan")
                 for n, v in zip(names, row)} for row in reader]


def history_units(directory):
    """{column name: unit} of DIRECTORY/history.csv ('' without a unit)."""
    with open(f"{directory}/history.csv") as f:
        headers = next(csv.reader(f))
    return {_name(h): h.split(" [")[1].rstrip("]") if " [" in h else ""
            for h in headers}


def summary(directory):
    """DIRECTORY/summary.json."""
    with open(f"{directory}/summary.json") as f:
        return json.load(f)
