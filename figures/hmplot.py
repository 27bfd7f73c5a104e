"""Shared conventions for every figure script in figures/.

A figure script reads only CSV files that hmlattice wrote, and is run with the Python that has
matplotlib and numpy (Debian's /usr/bin/python3):

    /usr/bin/python3 figures/<script>.py --data <folder with the CSV> --out <folder for the figure>

It writes <out>/<name>.png and <out>/<name>.pdf via save(). Nothing is computed here that the
toolkit did not compute: scripts select, label and draw.

--out follows the rule of every hmlattice result folder (core/include/hm/core/result_folder.hpp): it
may be a new or empty folder (created, and given the marker file .hmlattice) or a folder that holds
the marker (a run folder, an earlier figure folder), into which the figures are added. Anything else
is refused before anything is drawn. Each figure file is written completely or not at all.
"""
import argparse
import csv
import datetime
import json
import os
import sys
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
    reason = out_folder_problem(args.out) or (check(args) if check else None)
    if reason:
        parser.error(reason)
    plt.rcParams.update(STYLE)
    return args


MARKER = ".hmlattice"
MARKER_FIRST_LINE = "# hmlattice result folder"


def is_result_folder(folder):
    """True if `folder` holds the toolkit's marker file (a regular file starting with its first line)."""
    marker = os.path.join(folder, MARKER)
    if os.path.islink(marker) or not os.path.isfile(marker):
        return False
    with open(marker, errors="replace") as f:
        return f.readline().startswith(MARKER_FIRST_LINE)


def out_folder_problem(out):
    """None if figures may be written into `out`, else the one-line reason (the rule of hmlattice's --out)."""
    shown = out.rstrip("/") or out
    allowed = "allowed: a new or empty folder, or a folder that hmlattice wrote"
    if not shown:
        return f"--out = '' is empty; {allowed}"
    absolute = os.path.normpath(os.path.abspath(shown))
    if absolute == os.path.dirname(absolute):
        return f"--out = '{shown}' is the root folder; {allowed}"
    where = os.path.join(os.path.realpath(os.path.dirname(absolute)), os.path.basename(absolute))
    cwd = os.path.realpath(os.getcwd())
    if cwd == where or cwd.startswith(where.rstrip("/") + "/"):
        return f"--out = '{shown}' is the working directory or a folder above it; {allowed}"
    home = os.environ.get("HOME")
    if home and os.path.realpath(home) == where:
        return f"--out = '{shown}' is the home directory; {allowed}"
    if os.path.islink(where):
        return f"--out = '{shown}' is a symbolic link; {allowed}"
    if not os.path.lexists(where):
        up = os.path.dirname(where)
        while not os.path.lexists(up) and up != os.path.dirname(up):
            up = os.path.dirname(up)
        return None if os.path.isdir(up) else f"--out = '{shown}' lies under '{up}', which is not a folder; {allowed}"
    if os.path.isdir(where):
        if not os.listdir(where) or is_result_folder(where):
            return None
        return f"--out = '{shown}' is a folder with files that hmlattice did not write; {allowed}"
    if os.path.isfile(where):
        return f"--out = '{shown}' is a file; {allowed}"
    return f"--out = '{shown}' is a device, pipe or socket; {allowed}"


def _fail_writing(path, error):
    print(f"{os.path.basename(sys.argv[0])}: cannot write '{path}': {error.strerror or error}", file=sys.stderr)
    sys.exit(1)


def _prepare_out(out):
    """Create `out` if needed and give it the marker unless it has one (checked by arguments() already)."""
    try:
        os.makedirs(out, exist_ok=True)
        if is_result_folder(out):
            return
        command = json.dumps(" ".join([os.path.basename(sys.executable)] + sys.argv))  # a valid TOML string
        stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
        _write_atomically(os.path.join(out, MARKER), lambda path: _write_text(path, (
            f"{MARKER_FIRST_LINE}: written by the command below; `--overwrite` may replace this folder.\n"
            f'command_line = {command}\nversion = "figures"\nutc_time = "{stamp}"\n')))
    except OSError as e:
        _fail_writing(e.filename or out, e)


def _write_text(path, text):
    with open(path, "w") as f:
        f.write(text)


def _write_atomically(path, write):
    """write(partial_path), then rename onto `path`: a failed write leaves no half-written file."""
    partial = os.path.join(os.path.dirname(path) or ".", "." + os.path.basename(path) + ".partial")
    try:
        write(partial)
        os.replace(partial, path)
    except BaseException:
        if os.path.exists(partial):
            os.remove(partial)
        raise


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
    """[physics] <key> of a run folder's config.toml (as `hmlattice run` writes it), or None (also for
    a [physics_si] case, whose config.toml keeps [physics_si] and has the dimensionless values as comments)."""
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
    """Write <out>/<name>.png and .pdf (each completely or not at all) and close the figure."""
    fig.tight_layout()
    _prepare_out(out)
    for ext in ("png", "pdf"):
        path = os.path.join(out, f"{name}.{ext}")
        try:
            _write_atomically(path, lambda partial: fig.savefig(partial, format=ext))
        except OSError as e:
            _fail_writing(path, e)
    plt.close(fig)
