"""Open a lattice run's VTK series in ParaView with a view that shows the fracture.

    pvbatch3.11 figures/paraview_view.py out/fig12_b0.2_quick --screenshot view.png  # Debian's ParaView
    pvpython figures/paraview_view.py out/fig12_b0.2_quick                          # a window (upstream)

(prefix xvfb-run -a without a display). The run folder may also be given as HM_RUN.

The view: the triangles coloured by the fluid pressure p/E on a colour range symmetric about 0 (so
suction and pressure read alike), or by a particle stress component (--field sxx|syy|sxy: the stress
the failure check sees, rest state included); the broken beams drawn black on top; the deformed
lattice (warp by displacement, scaled so that the largest displacement shows as 2% of R unless
--warp is given; 0 draws the reference positions). The title names the case, N, seed, the snapshot's
time and the commit; a run that stopped early is titled INCOMPLETE.

Needs ParaView's Python (Debian: apt-get install paraview python3-paraview). A folder without vtk/lattice.pvd is refused
with one line and exit code 2.
"""
import argparse
import os
import sys
import tomllib

FIELDS = {
    "pressure": ("CELLS", "pressure", -1, "p/E"),
    "sxx": ("POINTS", "stress", 0, "sigma_xx/E"),
    "syy": ("POINTS", "stress", 4, "sigma_yy/E"),
    "sxy": ("POINTS", "stress", 1, "sigma_xy/E"),
}


def arguments():
    parser = argparse.ArgumentParser(description="Open a lattice run's VTK series with a fracture view.")
    parser.add_argument("run", nargs="?", default=os.environ.get("HM_RUN"),
                        help="a run folder written by `hmlattice run` with [output] vtk = true (or HM_RUN)")
    parser.add_argument("--field", choices=sorted(FIELDS), default="pressure",
                        help="what colours the rock (default: pressure)")
    parser.add_argument("--time", type=float, default=None,
                        help="snapshot time t* (default: the last snapshot)")
    parser.add_argument("--warp", type=float, default=None,
                        help="displacement scale factor (default: largest displacement shown as 0.02 R)")
    parser.add_argument("--screenshot", default=None, help="write this PNG and exit instead of opening a window")
    args = parser.parse_args()
    if not args.run:
        parser.error("give a run folder (or set HM_RUN)")
    pvd = os.path.join(args.run, "vtk", "lattice.pvd")
    if not os.path.isfile(pvd):
        parser.error(f"{pvd} does not exist: not a lattice run folder written with [output] vtk = true")
    if args.warp is not None and not (args.warp >= 0 and args.warp < float("inf")):
        parser.error(f"--warp {args.warp}: a finite value >= 0 is allowed")
    if args.screenshot and os.path.exists(args.screenshot):
        parser.error(f"--screenshot {args.screenshot} exists; give a new file name")
    return args, pvd


def run_title(folder, time):
    config = {}
    path = os.path.join(folder, "config.toml")
    if os.path.exists(path):
        with open(path, "rb") as f:
            config = tomllib.load(f)
    lattice = config.get("lattice", {})
    provenance = config.get("provenance", {})
    marker = os.path.join(folder, ".hmlattice")
    incomplete = os.path.exists(marker) and "complete = false" in open(marker).read()
    words = provenance.get("command_line", "").split()
    case = next((os.path.basename(w) for w in words if w.endswith(".toml")), os.path.basename(os.path.normpath(folder)))
    return ("INCOMPLETE run: " if incomplete else "") + \
        f"{case}, N = {lattice.get('n_particles', '?')}, seed {lattice.get('seed', '?')}, t* = {time:.4g}" \
        f"\nhmlattice {provenance.get('version', '?')} {provenance.get('git_commit', '?')}"


def main():
    args, pvd = arguments()
    from paraview import simple as pv  # imported after the arguments: --help works without ParaView

    reader = pv.PVDReader(registrationName="lattice", FileName=os.path.abspath(pvd))
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    time = times[-1] if args.time is None else min(times, key=lambda t: abs(t - args.time))
    reader.UpdatePipeline(time)

    warp = pv.WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    largest = reader.PointData["displacement"].GetRange(-1)[1]
    warp.ScaleFactor = args.warp if args.warp is not None else (0.02 / largest if largest > 0 else 0.0)

    def cells_where(array, value):
        threshold = pv.Threshold(Input=warp)
        threshold.Scalars = ["CELLS", array]
        threshold.LowerThreshold = value
        threshold.UpperThreshold = value
        return threshold

    rock = cells_where("cell_kind", 0)  # the triangles, one per flow node
    cracks = cells_where("broken", 1)   # the broken beams (contact or open)

    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewTime = time
    view.ViewSize = [1200, 1000]
    view.InteractionMode = "2D"
    view.OrientationAxesVisibility = 0

    association, array, component, label = FIELDS[args.field]
    shown = pv.Show(rock, view)
    pv.ColorBy(shown, (association, array) if component < 0 else (association, array, str(component)))
    lut = pv.GetColorTransferFunction(array)
    lut.ApplyPreset("Cool to Warm", True)
    if component >= 0:
        lut.VectorMode = "Component"
        lut.VectorComponent = component
    data = (reader.CellData if association == "CELLS" else reader.PointData)[array]
    low, high = data.GetRange(max(component, 0))
    half = max(abs(low), abs(high)) or 1.0
    lut.RescaleTransferFunction(-half, half)  # symmetric about 0: the sign reads from the colour
    lut.AutomaticRescaleRangeMode = "Never"
    bar = pv.GetScalarBar(lut, view)
    bar.Title = label
    bar.ComponentTitle = ""
    shown.SetScalarBarVisibility(view, True)

    broken = pv.Show(cracks, view)
    pv.ColorBy(broken, None)
    broken.AmbientColor = broken.DiffuseColor = [0.0, 0.0, 0.0]
    broken.LineWidth = 2.0

    title = pv.Text(Text=run_title(args.run, time))
    title_display = pv.Show(title, view)
    title_display.WindowLocation = "Upper Center"
    title_display.FontSize = 14

    view.ResetCamera()
    if args.screenshot:
        pv.SaveScreenshot(args.screenshot, view, ImageResolution=[1200, 1000])
        print(f"wrote {args.screenshot}")
        pv.Delete(view)  # release the GL context before Python's exit tears the X connection down
    else:
        pv.Render(view)
        pv.Interact(view)


if __name__ == "__main__":
    sys.exit(main())
