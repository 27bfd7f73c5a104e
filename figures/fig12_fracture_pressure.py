"""Fig. 12 of Ulven & Sun (2017): pressure and fracture development around a pressurised borehole,
Q = 0.01, iota = 1, b = 0.2 (top row) and b = 0.8 (bottom row), at the case's output times.

Reads what `hmlattice run` writes for a fracturing case (the VTK snapshots vtk/lattice.pvd +
lattice_NNNN.vtu and fracture_summary.csv): one run folder, a folder of run folders (one row each, in
order of b), or a folder with runs.csv (written by the lattice2d.fig12 benchmarks: one row per run
folder, `figure` = 1 for the runs to draw):

    /usr/bin/python3 figures/fig12_fracture_pressure.py --data out/fig12_b0.2_quick --out fig
    /usr/bin/python3 figures/fig12_fracture_pressure.py --data verify/data/fig12_quick --out fig

Each panel (hmplot.draw_pressure_snapshot): the pressure p/E per triangle (undeformed lattice; diverging
colours on a range symmetric about 0, the colour bar's ticks at that snapshot's min and max), broken
beams as black segments, the borehole wall, S_H's direction under an anisotropic in-situ field. Each
row is titled with its run's setting from its config.toml; a run that stopped early is marked INCOMPLETE.
"""
import hmplot


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=lambda a: hmplot.runs_problem(a.data))
    fig = hmplot.fracture_pressure_figure("fig12", hmplot.runs_to_draw(args.data),
                                          "Fig. 12 of Ulven & Sun (2017); each row's setting from its config.toml")
    hmplot.save(fig, args.out, "fig12_fracture_pressure")


if __name__ == "__main__":
    main()
