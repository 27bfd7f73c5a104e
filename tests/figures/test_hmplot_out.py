"""The figure scripts' --out follows hmlattice's result-folder rule (figures/hmplot.py): nothing of the
user's is overwritten or removed, and a figure is written completely or not at all.

Run: /usr/bin/python3 tests/figures/test_hmplot_out.py (CTest runs it)."""
import os
import resource
import signal
import subprocess
import sys
import tempfile
import tomllib
import unittest

FIGURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "figures")
# The smallest figure script: hmplot's arguments and save, like every script in figures/.
SCRIPT = """
import hmplot
import matplotlib.pyplot as plt
args = hmplot.arguments("test figure")
fig, ax = plt.subplots()
ax.plot(range(2000), range(2000))
hmplot.save(fig, args.out, "figure")
"""


def snapshot(root):
    out = {}
    for folder, dirs, files in os.walk(root):
        for name in dirs + files:
            path = os.path.join(folder, name)
            key = os.path.relpath(path, root)
            if os.path.islink(path):
                out[key] = "link -> " + os.readlink(path)
            elif os.path.isdir(path):
                out[key] = "dir"
            else:
                with open(path, "rb") as f:
                    out[key] = f.read()
    return out


class FigureOut(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.script = os.path.join(self.dir, "draw.py")
        with open(self.script, "w") as f:
            f.write(SCRIPT)

    def tearDown(self):
        self.tmp.cleanup()

    def draw(self, out, cwd=None, file_size_limit=None):
        def limit():
            if file_size_limit:
                signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails (EFBIG)
                resource.setrlimit(resource.RLIMIT_FSIZE, (file_size_limit, resource.RLIM_INFINITY))
        env = dict(os.environ, PYTHONPATH=FIGURES)
        return subprocess.run([sys.executable, self.script, "--data", self.dir, "--out", out], cwd=cwd or self.dir,
                              env=env, capture_output=True, text=True, preexec_fn=limit)

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)

    def test_a_new_folder_gets_the_figures_and_the_marker_and_can_be_drawn_into_again(self):
        for _ in range(2):
            r = self.draw("figs/")
            self.assertEqual(r.returncode, 0, r.stderr)
        names = sorted(os.listdir(os.path.join(self.dir, "figs")))
        self.assertEqual(names, [".hmlattice", "figure.pdf", "figure.png"])

    def test_a_folder_that_hmlattice_wrote_takes_figures_beside_its_files(self):
        self.write("run/.hmlattice", "# hmlattice result folder: written by the command below\n")
        self.write("run/series.csv", "t\n0\n")
        self.assertEqual(self.draw("run").returncode, 0)
        self.assertEqual(sorted(os.listdir(os.path.join(self.dir, "run"))),
                         [".hmlattice", "figure.pdf", "figure.png", "series.csv"])

    def test_the_figures_join_the_markers_file_list_so_that_overwrite_knows_them(self):
        self.write("run/.hmlattice", '# hmlattice result folder: written by the command below\n'
                                     'command_line = "hmlattice run"\nfiles = [\n  "series.csv",\n]\n')
        self.write("run/series.csv", "t\n0\n")
        for _ in range(2):  # drawn twice: listed once
            self.assertEqual(self.draw("run").returncode, 0)
        with open(os.path.join(self.dir, "run", ".hmlattice"), "rb") as f:
            marker = tomllib.load(f)
        self.assertEqual(marker["command_line"], "hmlattice run")
        self.assertEqual(marker["files"], ["figure.pdf", "figure.png", "series.csv"])
        self.assertEqual(self.draw("figs").returncode, 0)
        with open(os.path.join(self.dir, "figs", ".hmlattice"), "rb") as f:
            self.assertEqual(tomllib.load(f)["files"], ["figure.pdf", "figure.png"])

    def test_the_users_folders_files_and_links_are_refused_and_left_as_they_were(self):
        self.write("mine/figure.png", "the user's own figure")
        self.write("work/sub/keep.txt", "keep")
        self.write("file.png", "keep")
        os.symlink(os.path.join(self.dir, "mine"), os.path.join(self.dir, "link"))
        before = snapshot(self.dir)
        for out, cwd, why in [("mine", None, "is a folder with files that hmlattice did not write"),
                              ("file.png", None, "is a file"), ("link", None, "is a symbolic link"),
                              (".", os.path.join(self.dir, "work", "sub"), "is the working directory or a folder above it"),
                              ("..", os.path.join(self.dir, "work", "sub"), "is the working directory or a folder above it"),
                              ("/dev/null", None, "is a device, pipe or socket")]:
            r = self.draw(out, cwd)
            self.assertEqual(r.returncode, 2, (out, r.stderr))
            self.assertIn(f"--out = '{out}' {why}", r.stderr)
        self.assertEqual(snapshot(self.dir), before)

    def test_a_failed_write_is_one_line_exit_1_and_keeps_the_earlier_figure(self):
        self.assertEqual(self.draw("figs").returncode, 0)
        before = snapshot(os.path.join(self.dir, "figs"))
        r = self.draw("figs", file_size_limit=4096)  # the PNG needs more
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        self.assertIn("cannot write '", r.stderr)
        self.assertIn("File too large", r.stderr)
        self.assertEqual(snapshot(os.path.join(self.dir, "figs")), before)  # no partial file, old figure intact


if __name__ == "__main__":
    unittest.main()
