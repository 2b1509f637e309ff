"""Opens the ParaView time series of an SPD run (`softgrain run spd.compaction --vtk`, or any scene written
with --vtk) and colours the particles by a cell array: the area ratio A/A0 by default, or the elastic
energy W as in the paper's Figs. 29 and 32 (--array elastic_energy). Walls and plates are drawn in grey.

  pvpython scripts/paraview/spd.py out/spd.compaction/vtk/spd.compaction.pvd
  pvpython scripts/paraview/spd.py RUN.pvd --array elastic_energy --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last" (scripts/paraview/series.py).
"""

from paraview import simple

import series


def main():
    args = series.arguments(__doc__, "cell array of the particles to colour by (area_ratio, elastic_energy, "
                                     "core_pressure, particle_id)", array_default="area_ratio")
    reader, times, index = series.open_series(args)
    view = series.view_at(times[index], interaction_mode="2D")
    display = simple.Show(reader, view)
    series.require_array(args.array, reader.CellData.keys())
    series.colour_by(display, view, "CELLS", args.array, "Viridis (matplotlib)", grey_without_array=True)
    series.finish(view, args, args.array, times, index)


if __name__ == "__main__":
    main()
