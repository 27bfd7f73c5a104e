"""Shared conventions for every figure script in figures/.

A figure script reads only CSV files that hmlattice wrote, and is run with the Python that has
matplotlib and numpy (Debian's /usr/bin/python3):

    /usr/bin/python3 figures/<script>.py --data <folder with the CSV> --out <folder for the figure>

It writes <out>/<name>.png and <out>/<name>.pdf via save(). Nothing is computed here that the
toolkit did not compute: scripts select, label and draw.
"""
import argparse
import csv
import os
import tomllib
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {
    "figure.dpi": 110,
    "savefig.dpi": 150,
    "font.size": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "legend.fontsize": 8,
    "lines.linewidth": 1.4,
}


def arguments(description, add_options=None, check=None):
    """Parse --data and --out (and the script's own options, added by add_options(parser)); create --out.

    check(args) returns None or a one-line reason the arguments are wrong: then the script exits with
    code 2 (argparse's usage error) before anything is written."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--data", required=True, help="folder with the CSV files hmlattice wrote")
    parser.add_argument("--out", required=True, help="folder to write the PNG and PDF into")
    if add_options:
        add_options(parser)
    args = parser.parse_args()
    reason = check(args) if check else None
    if reason:
        parser.error(reason)
    os.makedirs(args.out, exist_ok=True)
    plt.rcParams.update(STYLE)
    return args


def read_csv(path):
    """Columns of a CSV with a header row, as a dict of numpy arrays."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    if not body:
        raise SystemExit(f"{path}: no data rows")
    data = np.array(body, dtype=float)
    return {name: data[:, i] for i, name in enumerate(header)}


def run_physics(folder, key):
    """[physics] <key> of a run folder's config.toml (as `hmlattice run` writes it), or None."""
    path = os.path.join(folder, "config.toml")
    if not os.path.exists(path):
        return None
    with open(path, "rb") as f:
        return tomllib.load(f).get("physics", {}).get(key)


def read_break_log(path):
    """The break log's columns as numpy arrays; the text column `mode` is kept as strings."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no breaks")
    return {k: (np.array([r[k] for r in rows]) if k == "mode" else np.array([float(r[k]) for r in rows]))
            for k in rows[0]}


def group_by(columns, key):
    """Split a column dict into {value of `key`: column dict}, in order of first appearance."""
    groups = defaultdict(list)
    for i, v in enumerate(columns[key]):
        groups[v].append(i)
    return {v: {name: col[idx] for name, col in columns.items()} for v, idx in groups.items()}


def save(fig, out, name):
    """Write <out>/<name>.png and .pdf and close the figure."""
    fig.tight_layout()
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(out, f"{name}.{ext}"))
    plt.close(fig)
