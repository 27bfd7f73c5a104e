"""The Python package: results as DataFrames with the resolved config, the program driven with --set,
sweeps, the figure functions, and the example study. Run by the test command (pytest, via CTest) with
HMLATTICE set to the built program and PYTHONPATH to python/."""
import os
import subprocess
import sys

import pytest

import hmlattice
from hmlattice.driver import toml_value

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CASE = os.path.join(ROOT, "cases", "fig12_b0.2_quick.toml")
# The Fig. 12 quick case made small (N = 1000, to t* = 3e-5: three steps, no VTK): ~0.5 s a run.
SMALL = {"lattice.n_particles": 1000, "numerics.t_end": 3e-5, "output.times": [3e-5], "output.vtk": False}


def test_a_run_is_read_as_dataframes_with_its_config(tmp_path):
    r = hmlattice.run(CASE, tmp_path / "q3", set=SMALL, physics__Q=3e-3)
    assert r.complete
    assert r.config["physics"]["Q"] == 3e-3 and r.config["lattice"]["n_particles"] == 1000
    assert {"series", "radial", "breaks", "breakdown", "fracture_summary"} <= set(r.tables)
    assert list(r.series["t"]) == pytest.approx([0.0, 1e-5, 2.2e-5, 3e-5])  # dt growing by 1.2, snapped to t_end
    # The same numbers as the program's own CSV, read independently of pandas.
    with open(tmp_path / "q3" / "series.csv") as f:
        last = f.read().splitlines()[-1].split(",")
    assert r.series["p_h"].iloc[-1] == float(last[2])
    again = hmlattice.load_run(tmp_path / "q3")
    assert again.series.equals(r.series)
    with pytest.raises(KeyError):
        r.table("teeth")  # only under the saw-tooth law


def test_a_bad_key_is_the_programs_one_line_message(tmp_path):
    with pytest.raises(hmlattice.HmlatticeError) as e:
        hmlattice.run(CASE, tmp_path / "bad", set=SMALL, physics__bogus=1)
    assert e.value.exit_code == 2
    assert "unknown key 'bogus'" in str(e.value) and "\n" not in str(e.value)
    assert not os.path.exists(tmp_path / "bad")


def test_an_incomplete_run_says_so(tmp_path):
    exe = hmlattice.executable()
    args = [exe, "run", CASE, "--out", str(tmp_path / "part"), "--stop-after-steps", "2"]
    for key, value in SMALL.items():
        args += ["--set", f"{key}={toml_value(value)}"]
    assert subprocess.run(args, capture_output=True).returncode == 0
    r = hmlattice.load_run(tmp_path / "part")
    assert not r.complete
    assert len(r.series) == 3  # t = 0 and two steps


def test_a_sweep_is_one_row_per_combination(tmp_path):
    table = hmlattice.sweep(CASE, tmp_path / "sweep", {"physics.Q": [3e-3, 1e-2], "lattice.seed": [1, 2]}, set=SMALL)
    assert len(table) == 4
    assert list(table["status"]) == ["complete"] * 4
    assert list(table["physics.Q"]) == [3e-3, 3e-3, 1e-2, 1e-2]
    first = hmlattice.load_run(table["folder"][0])
    assert first.config["physics"]["Q"] == 3e-3 and first.config["lattice"]["seed"] == 1
    assert table["p_h_peak"][0] == first.breakdown["p_h_peak"][0]


def test_toml_values():
    assert toml_value(3e-3) == "0.003" and toml_value(1e-5) == "1e-05" and toml_value(7) == "7"
    assert toml_value(True) == "true" and toml_value("sawtooth") == '"sawtooth"'
    assert toml_value([0.1, 2]) == "[0.1, 2]"
    with pytest.raises(TypeError):
        toml_value({"a": 1})


def test_the_figure_functions_are_public(tmp_path):
    from hmlattice import plot
    r = hmlattice.run(CASE, tmp_path / "fig", set={**SMALL, "output.vtk": True}, physics__Q=3e-3)
    assert "$Q = 0.003$" in plot.run_setting(r.folder)
    fig = plot.fracture_pressure_figure("test", [("Q = 0.003", r.folder)], "test")
    plot.save(fig, str(tmp_path / "figs"), "fig")
    assert os.path.getsize(tmp_path / "figs" / "fig.png") > 10000


def test_the_example_study_runs(tmp_path):
    done = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "q_sweep.py"), str(tmp_path / "q")],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert os.path.getsize(tmp_path / "q" / "breakdown_vs_Q.png") > 10000
    assert done.stdout.count("complete") == 4
