"""hmlattice from Python: read a run's results into pandas, drive the program, draw the paper's figures.

    import hmlattice
    r = hmlattice.run("cases/fig12_b0.2_quick.toml", "out/q3", physics__Q=3e-3)   # physics.Q = 3e-3
    r.series.plot(x="t", y="p_h")                                                  # a pandas DataFrame
    table = hmlattice.sweep("cases/fig12_b0.2_quick.toml", "out/q", {"physics.Q": [3e-3, 1e-2]})

Nothing is computed here: results are the program's own files (results.py), runs are the program's
own command line (driver.py), figures are figures/hmplot.py's functions (plot.py).
"""
from .driver import HmlatticeError, executable, run, sweep
from .results import Run, load_run

__all__ = ["HmlatticeError", "Run", "executable", "load_run", "run", "sweep"]
