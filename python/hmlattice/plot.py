"""The figure functions of figures/hmplot.py (the scripts' shared drawing code), importable:

    from hmlattice import plot
    fig = plot.fracture_pressure_figure("fig12", [("b = 0.2", "out/fig12_b0.2_quick")], "my run")
    plot.save(fig, "out/figs", "fig12")
"""
import importlib.util
import os

_here = os.path.dirname(os.path.abspath(__file__))
# The checkout's figures/ (python/hmlattice/..), or an installed copy's (PREFIX/lib/python3/dist-packages/
# hmlattice/.. -> PREFIX/share/hmlattice/figures).
for _figures in (os.path.join(_here, "..", "..", "figures"),
                 os.path.join(_here, "..", "..", "..", "..", "share", "hmlattice", "figures")):
    if os.path.isfile(os.path.join(_figures, "hmplot.py")):
        break
else:
    raise ImportError("hmlattice.plot: figures/hmplot.py not found beside the package")
_spec = importlib.util.spec_from_file_location("hmplot", os.path.join(_figures, "hmplot.py"))
_hmplot = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_hmplot)

draw_pressure_snapshot = _hmplot.draw_pressure_snapshot
fracture_pressure_figure = _hmplot.fracture_pressure_figure
provenance_footer = _hmplot.provenance_footer
run_setting = _hmplot.run_setting
runs_to_draw = _hmplot.runs_to_draw
save = _hmplot.save
vtk_snapshots = _hmplot.vtk_snapshots

__all__ = ["draw_pressure_snapshot", "fracture_pressure_figure", "provenance_footer", "run_setting", "runs_to_draw",
           "save", "vtk_snapshots"]
