"""A result folder of `hmlattice run` or `hmlattice fdm1d` as pandas DataFrames and its resolved config."""
import os
import tomllib

import pandas as pd

# The tables each command writes (docs: README "Running one case"); a run writes only those that apply
# (no fracture tables without fracture, teeth.csv only under the saw-tooth law).
TABLES = {
    "lattice2d": ("series", "radial", "breaks", "teeth", "breakdown", "fractures", "fracture_summary",
                  "fracture_pressure"),
    "fdm1d": ("borehole", "profiles", "probes", "steady_state"),
}


class Run:
    """One result folder. `config` is its config.toml (every default filled in, with provenance);
    each table it holds is an attribute (run.series, run.breaks, ...), read on first use; `tables`
    names them; `complete` is False for a run that stopped early (interrupted, failed or stopped with
    --stop-after-steps), whose tables end where it stopped."""

    def __init__(self, folder):
        self.folder = os.fspath(folder)
        config = os.path.join(self.folder, "config.toml")
        if not os.path.isfile(config):
            raise FileNotFoundError(f"{self.folder}: not a result folder of hmlattice run or fdm1d (no config.toml)")
        with open(config, "rb") as f:
            self.config = tomllib.load(f)
        self.model = self.config.get("model", "lattice2d")
        self.tables = tuple(t for t in TABLES.get(self.model, ())
                            if os.path.isfile(os.path.join(self.folder, t + ".csv")))
        with open(os.path.join(self.folder, ".hmlattice")) as f:
            self.complete = "complete = false" not in f.read()
        self._cache = {}

    def table(self, name):
        """The DataFrame of <folder>/<name>.csv."""
        if name not in self.tables:
            raise KeyError(f"{self.folder} has no {name}.csv; it has: {', '.join(self.tables)}")
        if name not in self._cache:
            self._cache[name] = pd.read_csv(os.path.join(self.folder, name + ".csv"))
        return self._cache[name]

    def __getattr__(self, name):
        if name.startswith("_") or name not in TABLES.get(self.__dict__.get("model"), ()):
            raise AttributeError(name)
        return self.table(name)

    def __repr__(self):
        state = "complete" if self.complete else "INCOMPLETE"
        return f"Run({self.folder!r}, {self.model}, {state}, tables: {', '.join(self.tables)})"


def load_run(folder):
    """The result folder `folder` (what `hmlattice run` or `fdm1d` wrote) as a Run."""
    return Run(folder)
