"""Running the hmlattice program from Python: one case with keys changed (--set), or a sweep of them."""
import itertools
import json
import math
import os
import shutil
import subprocess
import tomllib

import pandas as pd

from .results import load_run


class HmlatticeError(RuntimeError):
    """The program refused the input (exit 2) or failed (exit 1); the message is its stderr line."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.exit_code = exit_code


def executable():
    """The program: $HMLATTICE, else the checkout's build/hmlattice (python/hmlattice/..), else an
    installed copy's PREFIX/bin/hmlattice (PREFIX/lib/python3/dist-packages/hmlattice/..), else
    `hmlattice` on PATH."""
    if os.environ.get("HMLATTICE"):
        return os.environ["HMLATTICE"]
    here = os.path.dirname(os.path.abspath(__file__))
    for candidate in (os.path.join(here, "..", "..", "build", "hmlattice"),
                      os.path.join(here, "..", "..", "..", "..", "bin", "hmlattice")):
        if os.path.isfile(candidate):
            return os.path.abspath(candidate)
    found = shutil.which("hmlattice")
    if not found:
        raise HmlatticeError("hmlattice not found: set HMLATTICE, build the checkout (scripts/build.sh) or "
                             "put hmlattice on PATH", 2)
    return found


def toml_value(v):
    """A Python value as a TOML value for --set: numbers, booleans, strings, lists of them."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string for what JSON escapes
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    raise TypeError(f"{v!r}: not a TOML value (a number, bool, string or list)")


def _set_arguments(changes):
    args = []
    for key, value in changes.items():
        args += ["--set", f"{key.replace('__', '.')}={toml_value(value)}"]
    return args


def run(case, out, overwrite=False, set=None, **keys):
    """Runs `case` (a TOML file of either model) into the result folder `out` and returns its Run.
    Keys are changed as by --set: set={"physics.Q": 3e-3} or physics__Q=3e-3. Raises HmlatticeError
    with the program's one-line message when it refuses the input or fails (the folder of a failed run
    is kept, marked incomplete)."""
    with open(case, "rb") as f:
        model = tomllib.load(f).get("model", "lattice2d")
    command = {"lattice2d": "run", "fdm1d": "fdm1d"}.get(model)
    if command is None:
        raise HmlatticeError(f"{case}: model = {model!r}, allowed: lattice2d, fdm1d", 2)
    args = [executable(), command, os.fspath(case), "--out", os.fspath(out)] + _set_arguments({**(set or {}), **keys})
    if overwrite:
        args.append("--overwrite")
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise HmlatticeError(done.stderr.strip() or f"hmlattice exited with {done.returncode}", done.returncode)
    return load_run(out)


def sweep(case, out, values, overwrite=False, set=None, **keys):
    """Runs `case` once per combination of `values` ({"physics.Q": [...], "lattice.seed": [...]}),
    each into out/<key=value,...> (with the other changes of set/keys), one after the other, and
    returns one row per combination: the swept values, `folder`, `status` (complete, or the program's
    message) and, where the run wrote it, breakdown.csv's row."""
    names = list(values)
    rows = []
    os.makedirs(out, exist_ok=True)
    for combination in itertools.product(*(values[k] for k in names)):
        changes = dict(zip(names, combination))
        folder = os.path.join(out, ",".join(f"{k}={v}" for k, v in changes.items()))
        row = dict(changes, folder=folder)
        try:
            r = run(case, folder, overwrite=overwrite, set={**(set or {}), **changes}, **keys)
            row["status"] = "complete" if r.complete else "incomplete"
            if "breakdown" in r.tables:
                row.update(r.breakdown.iloc[0].to_dict())
        except HmlatticeError as e:
            row["status"] = str(e)
        rows.append(row)
    return pd.DataFrame(rows)
