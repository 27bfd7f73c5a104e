"""The fracture-pressure figures (Figs. 12, 14, 16, 17), the displacement figures (13, 15) and Fig. 7 describe
the run they draw (the verification figures the commit of their data): the setting comes from
its config.toml (a Q = 0.003 run is titled Q = 0.003, not the paper's 0.01), an in-situ field is named, a
run that stopped early is marked INCOMPLETE, a run without a snapshot is refused with one line, a
folder of the wrong kind is refused with one line instead of a traceback, and the script says where it
wrote.

Run: /usr/bin/python3 tests/figures/test_run_figures.py HMLATTICE (CTest runs it)."""
import os
import subprocess
import sys
import tempfile
import unittest

FIGURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "figures")
sys.path.insert(0, FIGURES)
import hmplot  # noqa: E402

HMLATTICE = sys.argv.pop(1) if len(sys.argv) > 1 else "build/hmlattice"

# A small fracturing annulus (N = 600) under an anisotropic in-situ field, to two output times: 34 steps
# (the first output time is step 30), ~1 s.
CASE = """model = "lattice2d"
[physics]
Q = 0.003
b = 0.2
iota = 1000
[lattice]
domain = "annulus"
n_particles = 600
seed = 4
[mechanics]
S_H = 3e-4
S_h = 1e-4
theta_H = 30
[numerics]
t_end = 0.002
[fracture]
enabled = true
[output]
times = [0.001, 0.002]
"""


def run(args, cwd):
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True)


class RunFigures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory(prefix="hmlattice-test-figures-")
        with open(os.path.join(cls.dir.name, "case.toml"), "w") as f:
            f.write(CASE)
        for args in (["run", "case.toml", "--out", "whole"],
                     # stopped before the first output time: no snapshot at all
                     ["run", "case.toml", "--out", "early", "--stop-after-steps", "2"]):
            r = run([HMLATTICE] + args, cls.dir.name)
            assert r.returncode == 0, r.stderr

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def script(self, name, data, out):
        return run([sys.executable, os.path.join(FIGURES, name), "--data", data, "--out", out], self.dir.name)

    def test_the_setting_is_the_runs(self):
        setting = hmplot.run_setting(os.path.join(self.dir.name, "whole"))
        for part in ("$Q = 0.003$", "$\\iota = 1000$", "$b = 0.2$", "$N = 600$", "seed 4",
                     "$S_H = 3 \\times 10^{-4}$", "$S_h = 10^{-4}$", "$\\theta_H = 30°$"):
            self.assertIn(part, setting)
        # The panel's count line has both arm counts; a summary without the fixed-gap column (an older
        # run's) only the one it has.
        summary = hmplot.fracture_summary_at(os.path.join(self.dir.name, "whole"), 0.002)
        self.assertRegex(hmplot.fracture_counts(summary), r"\d+ arms \(\d+ by the fixed gap\)")
        del summary["n_arms_fixed_gap"]
        self.assertNotIn("fixed gap", hmplot.fracture_counts(summary))
        r = self.script("fig12_fracture_pressure.py", "whole", "fig")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("fig12: b = 0.2: 2 snapshots\n", r.stdout)
        self.assertIn("wrote fig/fig12_fracture_pressure.png and .pdf\n", r.stdout)  # says where
        self.assertTrue(os.path.getsize(os.path.join(self.dir.name, "fig", "fig12_fracture_pressure.png")) > 10000)

    def test_an_incomplete_run_is_marked_and_one_without_snapshots_refused(self):
        r = run([HMLATTICE, "run", "case.toml", "--out", "part", "--stop-after-steps", "31"], self.dir.name)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertFalse(hmplot.run_is_complete(os.path.join(self.dir.name, "part")))
        self.assertTrue(hmplot.run_is_complete(os.path.join(self.dir.name, "whole")))
        r = self.script("fig14_fracture_pressure.py", "part", "fig_part")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("(INCOMPLETE run)", r.stdout)
        r = self.script("fig16_fracture_pressure.py", "early", "fig_early")
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
        self.assertIn("nothing to draw", r.stderr)

    def test_the_displacement_figures_title_each_run_with_its_setting(self):
        r = run([HMLATTICE, "run", "case.toml", "--out", "part15", "--stop-after-steps", "31"], self.dir.name)
        self.assertEqual(r.returncode, 0, r.stderr)
        whole, part = (os.path.join(self.dir.name, name) for name in ("whole", "part15"))
        self.assertEqual(hmplot.run_title(whole, "whole"), hmplot.run_setting(whole))
        self.assertIn("$Q = 0.003$", hmplot.run_title(whole, "whole"))
        self.assertTrue(hmplot.run_title(part, "part15").startswith("INCOMPLETE run: $Q = 0.003$"))
        for data in ("whole", "part15"):
            r = self.script("fig15_displacement_vs_1d.py", data, "fig15_" + data)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn(f"wrote fig15_{data}/fig15_displacement_vs_1d.png and .pdf\n", r.stdout)

    def test_fig7_is_titled_with_the_runs_setting(self):
        r = run([HMLATTICE, "run", "case.toml", "--out", "disk", "--set", 'lattice.domain="disk"', "--set", "physics.R_i=0",
                 "--set", "fracture.enabled=false", "--set", "mechanics.S_H=0", "--set", "mechanics.S_h=0",
                 "--set", "output.times=[0.001]", "--set", "numerics.t_end=0.001"], self.dir.name)
        self.assertEqual(r.returncode, 0, r.stderr)
        r = self.script("fig07_rudnicki.py", "disk", "fig07")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("fig07: 1 run(s), $Q = 0.003$, $b = 0.2$, t* = 1e-3\n", r.stdout)  # not the paper's 0.1, 0.5
        self.assertIn("wrote fig07/fig07_rudnicki.png and .pdf\n", r.stdout)
        # An annulus has no shell near a point source: one line, no traceback.
        r = self.script("fig07_rudnicki.py", "whole", "fig07_annulus")
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
        self.assertIn("no radial shell at r* <= 0.1", r.stderr)

    def test_a_verification_figure_names_the_commit_its_data_came_from(self):
        r = run([HMLATTICE, "verify", "--filter", "analytic.steady_borehole", "--out", "verify"], self.dir.name)
        self.assertEqual(r.returncode, 0, r.stderr)
        data = os.path.join(self.dir.name, "verify", "data")
        prov = hmplot.data_provenance(data)
        self.assertRegex(prov.get("git_commit", ""), r"^[0-9a-f]{12}")
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig = plt.figure()
        self.assertGreater(hmplot.provenance_footer(fig, [data]), 0.0)
        footer = fig.texts[-1].get_text()
        self.assertIn(f"verification data (hmlattice {prov['version']} {prov['git_commit']})", footer)
        # A folder with no provenance adds no footer (rather than one of question marks).
        self.assertEqual(hmplot.provenance_footer(plt.figure(), [self.dir.name]), 0.0)
        self.assertTrue(os.path.getsize(os.path.join(self.dir.name, "verify", "figures", "analytic.steady_borehole",
                                                     "verify_steady_borehole.png")) > 10000)

    def test_a_folder_of_another_kind_is_one_line(self):
        r = self.script("fig10_fdm1d_pressure_displacement.py", "whole", "fig10")
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
        self.assertIn("profiles.csv: no such file", r.stderr)
        self.assertNotIn("Traceback", r.stderr)


if __name__ == "__main__":
    unittest.main()
