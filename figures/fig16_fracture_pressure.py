"""Fig. 16 of Ulven & Sun (2017): pressure and fractures at a high injection rate, Q = 1, iota = 1e3,
b = 0.2 (top row, A-D) and b = 0.8 (bottom row, E-H), at the case's four output times.

Reads what `hmlattice run` writes for a fracturing case (vtk/lattice.pvd + lattice_NNNN.vtu and
fracture_summary.csv): one run folder (one row), a folder of run folders (one row each, in order of b),
or a folder with runs.csv (a lattice2d benchmark's data folder, `figure` = 1 for the runs to draw):

    build/hmlattice run cases/fig16_b0.2_quick.toml --out out/fig16/b0.2
    build/hmlattice run cases/fig16_b0.8_quick.toml --out out/fig16/b0.8
    /usr/bin/python3 figures/fig16_fracture_pressure.py --data out/fig16 --out out/fig16/figures

The output times (initiation, growth, fractures near and at the boundary) were chosen from a quick run's
fracture_summary.csv; the case files say what was measured.
Each panel as Fig. 12's (hmplot.draw_pressure_snapshot): the pressure per triangle on the undeformed
lattice, colours on a range symmetric about 0 (ticks at that snapshot's min and max), broken beams in
black, the borehole wall in grey; the title gives fracture_summary.csv's counts.
"""
import hmplot


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=lambda a: hmplot.runs_problem(a.data))
    fig = hmplot.fracture_pressure_figure("fig16", hmplot.runs_to_draw(args.data),
                                          "Fig. 16 of Ulven & Sun (2017); each row's setting from its config.toml")
    hmplot.save(fig, args.out, "fig16_fracture_pressure")


if __name__ == "__main__":
    main()
