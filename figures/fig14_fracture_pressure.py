"""Fig. 14 of Ulven & Sun (2017): pressure and fractures with fast flow in fractures, Q = 0.01,
iota = 1e3, b = 0.2 (top row, A-D) and b = 0.8 (bottom row, E-H), at the case's output times.

Reads what `hmlattice run` writes for a fracturing case (vtk/lattice.pvd + lattice_NNNN.vtu and
fracture_summary.csv): one run folder (one row), a folder of run folders (one row each, in order of b),
or a folder with runs.csv (a lattice2d benchmark's data folder, `figure` = 1 for the runs to draw):

    build/hmlattice run cases/fig14_b0.2_quick.toml --out out/fig14/b0.2
    build/hmlattice run cases/fig14_b0.8_quick.toml --out out/fig14/b0.8
    /usr/bin/python3 figures/fig14_fracture_pressure.py --data out/fig14 --out out/fig14/figures

The cases' output times are Fig. 15's snapshot times (b = 0.2: t* = 2.3e-3, 4.5e-3, 6.8e-3, 1.4e-2;
b = 0.8: 2.3e-3, 4.5e-3, 9e-3, 2.5e-2, 9.3e-2): the paper's Fig. 14 shows four of them per row.
Each panel as Fig. 12's (hmplot.draw_pressure_snapshot): the pressure per triangle on the undeformed
lattice, colours on a range symmetric about 0 (ticks at that snapshot's min and max), broken beams in
black, the borehole wall in grey; the title gives fracture_summary.csv's counts.
"""
import hmplot


def main():
    args = hmplot.arguments(__doc__.splitlines()[0], check=lambda a: hmplot.runs_problem(a.data))
    fig = hmplot.fracture_pressure_figure("fig14", hmplot.runs_to_draw(args.data),
                                          "Fig. 14 of Ulven & Sun (2017); each row's setting from its config.toml")
    hmplot.save(fig, args.out, "fig14_fracture_pressure")


if __name__ == "__main__":
    main()
