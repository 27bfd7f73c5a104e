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
import textwrap
import tomllib
import xml.etree.ElementTree as ET
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # no display on CI machines
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

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
            f'command_line = {command}\nversion = "figures"\nutc_time = "{stamp}"\nfiles = [\n]\n')))
    except OSError as e:
        _fail_writing(e.filename or out, e)


def _list_in_marker(out, names):
    """Add `names` (files just written into `out`) to the `files` list of out's marker, so that
    hmlattice's --overwrite knows them as the toolkit's. A marker without a list (an older version's)
    is left as it is: --overwrite refuses its folder anyway."""
    marker = os.path.join(out, MARKER)
    with open(marker, errors="replace") as f:
        text = f.read()
    try:
        listed = tomllib.loads(text).get("files")
    except tomllib.TOMLDecodeError:
        return
    if listed is None:
        return
    files = sorted(set(listed) | set(names))
    head = text.split("\nfiles = [")[0].rstrip("\n") + "\n"
    body = "files = [\n" + "".join(f"  {json.dumps(name)},\n" for name in files) + "]\n"
    _write_atomically(marker, lambda path: _write_text(path, head + body))


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
    """Columns of a CSV with a header row, as a dict of numpy arrays. A missing file ends the script
    with one line (the --data folder is of another kind: a lattice run for a 1D figure, or the reverse)."""
    if not os.path.isfile(path):
        raise SystemExit(f"{path}: no such file: --data must be the folder of hmlattice's output this figure "
                         f"reads ({os.path.basename(path)})")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    if not body:
        raise SystemExit(f"{path}: no data rows")
    data = np.array(body, dtype=float)
    return {name: data[:, i] for i, name in enumerate(header)}


def run_config(folder):
    """A run folder's resolved config.toml as a dict ({} without one)."""
    path = os.path.join(folder, "config.toml")
    if not os.path.exists(path):
        return {}
    with open(path, "rb") as f:
        return tomllib.load(f)


def run_physics(folder, key):
    """[physics] <key> of a run folder's config.toml (as `hmlattice run` writes it), or None (also for
    a [physics_si] case, whose config.toml keeps [physics_si] and has the dimensionless values as comments)."""
    return run_config(folder).get("physics", {}).get(key)


def run_is_complete(folder):
    """False for a run that stopped early (its marker says complete = false: interrupted, failed, or
    stopped with --stop-after-steps), whose figures would describe only part of the case."""
    marker = os.path.join(folder, MARKER)
    if not os.path.exists(marker):
        return True
    with open(marker) as f:
        return "complete = false" not in f.read()


def _tex_number(v):
    """v in mathtext: 0.01, 1000 as 10^3, 3e-4 as 3 x 10^-4."""
    if v == 0 or 1e-3 <= abs(v) < 1e4:
        return f"{v:g}"
    mantissa, exponent = f"{v:.2e}".split("e")
    mantissa, exponent = f"{float(mantissa):g}", int(exponent)
    return f"10^{{{exponent}}}" if mantissa == "1" else f"{mantissa} \\times 10^{{{exponent}}}"


def run_setting(folder):
    """The run's setting in one mathtext line, from its config.toml: Q, iota, b, N, seed, the in-situ
    field if any, the fracture law if not the paper's; "" for a folder without a config."""
    c = run_config(folder)
    if not c:
        return ""
    physics, lattice, mech = c.get("physics", {}), c.get("lattice", {}), c.get("mechanics", {})
    fracture = c.get("fracture", {})
    parts = [f"$Q = {_tex_number(physics['Q'])}$" if "Q" in physics else None,
             f"$\\iota = {_tex_number(physics['iota'])}$" if "iota" in physics else None,
             f"$b = {physics['b']:g}$" if "b" in physics else None,
             f"$N = {lattice['n_particles']}$" if "n_particles" in lattice else None,
             f"seed {lattice['seed']}" if "seed" in lattice else None]
    if mech.get("S_H", 0) or mech.get("S_h", 0):
        parts.append(f"$S_H = {_tex_number(mech.get('S_H', 0))}$, $S_h = {_tex_number(mech.get('S_h', 0))}$, "
                     f"$\\theta_H = {mech.get('theta_H', 0):g}°$")
    if fracture.get("law", "brittle") != "brittle":
        parts.append(f"{fracture['law']} law, $G_f/(ER) = {_tex_number(fracture.get('fracture_energy', 0))}$")
    return ", ".join(p for p in parts if p)


def run_title(folder, label):
    """A run's panel title: its setting (run_setting), or its label without a config.toml; marked
    INCOMPLETE when it stopped early."""
    return ("INCOMPLETE run: " if not run_is_complete(folder) else "") + (run_setting(folder) or label)


def data_provenance(folder):
    """The [provenance] of what wrote a folder: a run's config.toml, or the provenance.toml of a
    verification report's data folder ({} without either)."""
    prov = run_config(folder).get("provenance")
    if prov is not None:
        return prov
    path = os.path.join(folder, "provenance.toml")
    if not os.path.exists(path):
        return {}
    with open(path, "rb") as f:
        return tomllib.load(f).get("provenance", {})


def provenance_footer(fig, folders):
    """A small footer naming what the figure was drawn from: each run's case file (from the command
    that wrote it; "verification data" for a report's data folder), grouped by the hmlattice version
    and commit that wrote it, wrapped to the width. Returns the footer's height as a fraction of the
    figure's (0 without provenance), for the layout to keep free."""
    builds = {}
    for folder in folders:
        prov = data_provenance(folder)
        if not prov:
            continue
        words = prov.get("command_line", "").split()
        fallback = "verification data" if words[1:2] == ["verify"] else os.path.basename(os.path.normpath(folder))
        case = next((os.path.basename(w) for w in words if w.endswith(".toml")), fallback)
        cases = builds.setdefault(f"hmlattice {prov.get('version', '?')} {prov.get('git_commit', '?')}", [])
        if case not in cases:
            cases.append(case)
    if not builds:
        return 0.0
    text = "drawn from: " + "; ".join(f"{', '.join(cases)} ({build})" for build, cases in builds.items())
    width = int(fig.get_figwidth() * 22)  # characters of 6 pt text per inch, about
    lines = textwrap.wrap(text, width)
    fig.text(0.01, 0.003, "\n".join(lines), fontsize=6, color="0.35", ha="left", va="bottom")
    return len(lines) * 6 * 1.25 / 72 / fig.get_figheight()


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


def is_run_folder(folder):
    """True if `folder` is what `hmlattice run` writes (its resolved config.toml and its break log)."""
    return all(os.path.isfile(os.path.join(folder, name)) for name in ("config.toml", "breaks.csv"))


def runs_to_draw(data):
    """[(label, folder)] of the fracturing runs a figure draws, one row or curve each, in order of b:

    - a folder with runs.csv (the lattice2d benchmarks' data folder): its rows with `figure` = 1;
    - a run folder: that run alone;
    - a folder of run folders (e.g. out/fig14 holding fig14_b0.2 and fig14_b0.8): each of them."""
    index = os.path.join(data, "runs.csv")
    if os.path.exists(index):
        with open(index, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["figure"] == "1"]
        return [(r["run"], os.path.join(data, r["run"])) for r in sorted(rows, key=lambda r: float(r["b"]))]
    if is_run_folder(data):
        return [(os.path.basename(os.path.normpath(data)), data)]
    # Hidden folders are left out: a run still under way writes into .hmlattice-staging-* beside its --out.
    runs = [(name, os.path.join(data, name)) for name in sorted(os.listdir(data))
            if not name.startswith(".") and is_run_folder(os.path.join(data, name))]
    return sorted(runs, key=lambda run: run_physics(run[1], "b") or 0.0)


def indexed_folders(data, column):
    """{run label: folder} from the `column` of a benchmark data folder's runs.csv (runs with a value
    there); {} without runs.csv."""
    index = os.path.join(data, "runs.csv")
    if not os.path.exists(index):
        return {}
    with open(index, newline="") as f:
        return {r["run"]: os.path.join(data, r[column]) for r in csv.DictReader(f) if r.get(column)}


def runs_problem(data):
    """None if `data` holds runs to draw (see runs_to_draw), else the one-line reason (for arguments' check)."""
    if not os.path.isdir(data):
        return f"--data = '{data}' is not a folder"
    if not runs_to_draw(data):
        return (f"--data = '{data}' holds no run: allowed: a folder `hmlattice run` wrote (config.toml, breaks.csv), "
                "a folder of such folders, or a benchmark data folder with runs.csv")
    return None


def vtk_snapshots(folder):
    """[(t, .vtu path)] listed in a run's vtk/lattice.pvd, t > 0 only (the output times)."""
    pvd = os.path.join(folder, "vtk", "lattice.pvd")
    root = ET.parse(pvd).getroot()
    out = []
    for ds in root.iter("DataSet"):
        t = float(ds.get("timestep"))
        if t > 0.0:
            out.append((t, os.path.join(folder, "vtk", ds.get("file"))))
    return out


def read_snapshot(path):
    """Points, triangles with their pressure, broken-beam segments, borehole-wall points (in order)."""
    import meshio  # only the lattice snapshot figures need it

    mesh = meshio.read(path)
    tri, p, seg = None, None, []
    for k, block in enumerate(mesh.cells):
        if block.type == "triangle":
            tri, p = block.data, np.asarray(mesh.cell_data["pressure"][k])
        elif block.type == "line":
            broken = np.asarray(mesh.cell_data["broken"][k]) == 1
            seg = block.data[broken]
    xy = mesh.points[:, :2]
    wall = xy[np.asarray(mesh.point_data["boundary"]) == 2]
    if len(wall):
        wall = wall[np.argsort(np.arctan2(wall[:, 1], wall[:, 0]))]
        wall = np.vstack([wall, wall[:1]])
    return xy, tri, p, xy[seg] if len(seg) else np.zeros((0, 2, 2)), wall


def fracture_summary_at(folder, t):
    """The run's fracture_summary.csv row at time t, as a dict (or None)."""
    path = os.path.join(folder, "fracture_summary.csv")
    if not os.path.exists(path):
        return None
    s = read_csv(path)
    k = np.argmin(np.abs(s["t"] - t))
    return {name: col[k] for name, col in s.items()} if abs(s["t"][k] - t) <= 1e-6 * t else None


def fracture_counts(summary):
    """The second title line of a snapshot panel: fracture_summary.csv's counts at that time (the
    arms by the 3-beam gap, and by the fixed gap in R where the run wrote that count)."""
    if summary is None:
        return ""
    fixed = f" ({int(summary['n_arms_fixed_gap'])} by the fixed gap)" if "n_arms_fixed_gap" in summary else ""
    return (f"\n{int(summary['n_radial'])} radial clusters, {int(summary['n_arms'])} arms{fixed}, "
            f"{int(summary['n_broken'])} broken")


def draw_pressure_snapshot(fig, ax, path, title, theta_H=None):
    """One panel of the paper's Figs. 12, 14, 16, 17, 19: the pressure p/E per triangle of a VTK
    snapshot (undeformed lattice; diverging colours on a range symmetric about 0, +-max|p| of that
    snapshot, so that equal colours are equal magnitudes of either sign; the colour bar's ticks give
    the snapshot's min and max), broken beams as black segments (the beam from particle i to j, so a
    crack shows as a chain of short segments across it), the borehole wall in grey, and with an in-situ
    field (theta_H in degrees) the direction of S_H as a double arrow."""
    xy, tri, p, seg, wall = read_snapshot(path)
    p_min, p_max = float(p.min()), float(p.max())
    scale = max(abs(p_min), abs(p_max), 1e-30)
    norm = mcolors.Normalize(vmin=-scale, vmax=scale)
    im = ax.tripcolor(xy[:, 0], xy[:, 1], tri, facecolors=p, cmap="RdBu_r", norm=norm, rasterized=True)
    if len(seg):
        ax.add_collection(LineCollection(seg, colors="k", linewidths=0.7))
    if len(wall):
        ax.plot(wall[:, 0], wall[:, 1], color="0.3", lw=0.6)
    ax.set_aspect("equal")
    ax.set_xlim(-1.02, 1.02)
    ax.set_ylim(-1.02, 1.02)
    ax.set_xticks([-1, 0, 1])
    ax.set_yticks([-1, 0, 1])
    ax.grid(False)
    if theta_H is not None:
        d = 0.22 * np.array([np.cos(np.radians(theta_H)), np.sin(np.radians(theta_H))])
        centre = np.array([-0.78, 0.78])
        ax.annotate("", xy=centre + d, xytext=centre - d,
                    arrowprops=dict(arrowstyle="<->", color="0.15", lw=1.0, shrinkA=0, shrinkB=0, mutation_scale=7))
        ax.text(*(centre + 1.25 * d), "$S_H$", fontsize=7, ha="center", va="center")
    ax.set_title(title, fontsize=8)
    cb = fig.colorbar(im, ax=ax, fraction=0.046, pad=0.03)
    cb.set_ticks(sorted({p_min, 0.0, p_max}))
    cb.set_label("$p/E$", fontsize=7, labelpad=1)
    cb.ax.tick_params(labelsize=7)
    cb.formatter = plt.FuncFormatter(lambda v, _: f"{v:.2e}")
    cb.update_ticks()


def fracture_pressure_figure(name, runs, suptitle):
    """Figs. 12, 14, 16, 17: one row per run (label, folder), one panel per output time, panels lettered
    A, B, ... row by row as in the paper; each row titled with its run's own setting (run_setting), a run
    that stopped early marked INCOMPLETE, the footer naming the cases and the build. Prints one line per
    row (`name: b = ...: n snapshots`). Exits with a message when no run has a snapshot (a run
    interrupted before its first output time). Returns the figure."""
    rows = []
    for label, folder in runs:
        snaps = vtk_snapshots(folder)
        b = run_physics(folder, "b")
        print(f"{name}: {f'b = {b:g}' if b is not None else label}: {len(snaps)} snapshots"
              + ("" if run_is_complete(folder) else " (INCOMPLETE run)"))
        rows.append((label, folder, snaps))
    if not any(snaps for _, _, snaps in rows):
        raise SystemExit(f"{name}: no run has a VTK snapshot at an output time (vtk = false, or stopped before the "
                         "first output time): nothing to draw")
    n_cols = max(1, max(len(s) for _, _, s in rows))
    # One subfigure per run, titled with that run's setting (constrained layout keeps titles clear).
    fig = plt.figure(figsize=(3.0 * n_cols, 3.3 * len(rows) + 0.5), layout="constrained")
    panel = iter("ABCDEFGHIJKLMNOPQRSTUVWXYZ")
    fig.get_layout_engine().set(rect=(0.0, 0.03, 1.0, 0.97))  # room for the footer
    # Transparent subfigures, so that the footer (a text of the whole figure) is not painted over.
    row_figs = fig.subfigures(len(rows), 1, squeeze=False, facecolor="none")[:, 0]
    for (label, folder, snaps), row_fig in zip(rows, row_figs):
        mech = run_config(folder).get("mechanics", {})
        theta_H = mech.get("theta_H", 0.0) if mech.get("S_H", 0) != mech.get("S_h", 0) else None
        incomplete = "" if run_is_complete(folder) else "INCOMPLETE run: "
        axes = row_fig.subplots(1, n_cols, squeeze=False)[0]
        for col, ax in enumerate(axes):
            if col >= len(snaps):
                ax.axis("off")
                continue
            t, path = snaps[col]
            draw_pressure_snapshot(row_fig, ax, path, f"{next(panel)}: {incomplete}$t^* = {t:.3g}$"
                                   + fracture_counts(fracture_summary_at(folder, t)), theta_H)
            ax.set_xlabel("$x/R$")
            if col == 0:
                ax.set_ylabel(f"{label}\n$y/R$")
        row_fig.suptitle(run_setting(folder), fontsize=8)
    fig.suptitle(suptitle + "\npressure $p/E$ per triangle (colours symmetric about 0, per panel) and broken beams "
                 "(black)", fontsize=10)
    provenance_footer(fig, [folder for _, folder, _ in rows])
    return fig


def fdm1d_folders(folder):
    """{b: folder} of the `hmlattice fdm1d` results in `folder` (itself one, or a folder of them)."""
    if folder is None:
        return {}
    candidates = [folder] if os.path.isfile(os.path.join(folder, "profiles.csv")) else [
        os.path.join(folder, name) for name in sorted(os.listdir(folder))
        if os.path.isfile(os.path.join(folder, name, "profiles.csv"))]
    return {run_physics(c, "b"): c for c in candidates}


def draw_displacement_vs_1d(ax, folder, folder_1d, t_first):
    """u_r(r) of a lattice run at its output times (radial.csv: solid, markers, shells binned by undeformed
    centroid radius) and, where the 1D folder has a profile at the same time, fdm1d's nodal u_r (dashed,
    same colour) - Figs. 13 and 15. Each curve says whether the run had broken a beam by then (t_first:
    breakdown.csv's first break, NaN if none). Returns (number of output times, number with a 1D profile)."""
    radial = group_by(read_csv(os.path.join(folder, "radial.csv")), "t")
    times = [t for t in radial if t > 0.0]
    profiles_1d = None
    if folder_1d and os.path.exists(os.path.join(folder_1d, "profiles.csv")):
        profiles_1d = group_by(read_csv(os.path.join(folder_1d, "profiles.csv")), "t")
    colors = plt.cm.viridis(np.linspace(0.0, 0.85, len(times)))
    markers = "osD^v<>"
    n_compared = 0
    for k, t in enumerate(times):
        d = radial[t]
        state = "unbroken" if not (t >= t_first) else "fractured"
        ax.plot(d["r_mean"], d["u_r"], "-", marker=markers[k % len(markers)], ms=3.5, markevery=2,
                color=colors[k], label=f"2D, $t^* = {t:.3g}$ ({state})")
        if profiles_1d is not None:
            match = [t1 for t1 in profiles_1d if abs(t1 - t) <= 1e-6 * t]
            if match:
                n_compared += 1
                d1 = profiles_1d[match[0]]
                ax.plot(d1["r"], d1["u_r"], "--", color=colors[k], lw=1.2)
    if profiles_1d is not None:
        ax.plot([], [], "k--", lw=1.2, label="1D (fdm1d), no fracture")
    ax.set_xlabel("$r/R$")
    ax.set_ylabel("radially averaged $u_r/R$")
    ax.set_xlim(0.0, 1.0)
    return len(times), n_compared


def sweep_problem(data, key):
    """None if `data` is a sweep folder over `key` (results.csv from `hmlattice sweep collect`, run folders
    in runs/) or a benchmark data folder (runs.csv naming run folders with their n_particles), else the
    one-line reason (for arguments' check)."""
    if os.path.isfile(os.path.join(data, "runs.csv")):
        return None
    path = os.path.join(data, "results.csv")
    if not os.path.isfile(path):
        return f"--data = '{data}' has no results.csv (hmlattice sweep collect) and no runs.csv (a benchmark's)"
    with open(path, newline="") as f:
        header = next(csv.reader(f), [])
    if key not in header:
        return f"--data = '{data}': results.csv has no column {key} (a sweep over {key})"
    return None


def sweep_runs(data, key):
    """[(value of key, run folder)] of a sweep folder's complete runs in order of the value, and the number
    of combinations left out (incomplete or missing runs). For a benchmark data folder (runs.csv): its
    runs with `figure` = 1, by the runs.csv column named as the key after its dot (n_particles)."""
    index = os.path.join(data, "runs.csv")
    if os.path.isfile(index):
        with open(index, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["figure"] == "1"]
        column = key.split(".")[-1]
        return sorted((float(r[column]), os.path.join(data, r["run"])) for r in rows), 0
    with open(os.path.join(data, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    done = [r for r in rows if r["status"] == "complete"]
    runs = sorted((float(r[key]), os.path.join(data, "runs", r["name"])) for r in done)
    return runs, len(rows) - len(done)


def save(fig, out, name, sources=()):
    """Write <out>/<name>.png and .pdf (each completely or not at all), close the figure, say where.
    sources: the folders the figure was drawn from, named in a provenance footer."""
    footer = provenance_footer(fig, sources) if sources else 0.0
    if fig.get_layout_engine() is None:  # a figure may bring its own (constrained) layout
        fig.tight_layout(rect=(0, footer + 0.01 if footer else 0, 1, 1))
    _prepare_out(out)
    for ext in ("png", "pdf"):
        path = os.path.join(out, f"{name}.{ext}")
        try:
            _write_atomically(path, lambda partial: fig.savefig(partial, format=ext))
        except OSError as e:
            _fail_writing(path, e)
    try:
        _list_in_marker(out, [f"{name}.png", f"{name}.pdf"])
    except OSError as e:
        _fail_writing(os.path.join(out, MARKER), e)
    plt.close(fig)
    print(f"wrote {os.path.join(out, name)}.png and .pdf")
