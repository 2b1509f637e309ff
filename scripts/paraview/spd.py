"""Opens the ParaView time series of an SPD run (`softgrain run spd.compaction --vtk`, or any scene written
with --vtk) and colours the particles by a cell array: the area ratio A/A0 by default, or the elastic
energy W as in the paper's Figs. 29 and 32 (--array elastic_energy). Walls and plates are drawn in grey.

  pvpython scripts/paraview/spd.py out/spd.compaction/vtk/spd.compaction.pvd
  pvpython scripts/paraview/spd.py RUN.pvd --array elastic_energy --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last".
"""

import argparse
import sys

from paraview import simple


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd", help="the run's vtk/<scene>.pvd")
    parser.add_argument("--array", default="area_ratio",
                        help="cell array of the particles to colour by (area_ratio, elastic_energy, core_pressure, "
                             "particle_id)")
    parser.add_argument("--time", default="last", help="frame index, 'first' or 'last'")
    parser.add_argument("--screenshot", help="write this PNG and exit")
    args = parser.parse_args()

    reader = simple.PVDReader(FileName=args.pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    index = {"first": 0, "last": len(times) - 1}.get(args.time)
    index = int(args.time) if index is None else index
    if not 0 <= index < len(times):
        sys.exit(f"spd.py: --time {args.time}: allowed: 0 .. {len(times) - 1}, first or last")

    view = simple.GetActiveViewOrCreate("RenderView")
    view.InteractionMode = "2D"
    view.OrientationAxesVisibility = 0
    scene = simple.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = times[index]

    display = simple.Show(reader, view)
    if args.array not in reader.CellData.keys():
        sys.exit(f"spd.py: --array {args.array}: allowed: {', '.join(reader.CellData.keys())}")
    simple.ColorBy(display, ("CELLS", args.array))
    lut = simple.GetColorTransferFunction(args.array)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.NanColor = [0.6, 0.6, 0.6]  # walls and plates carry no particle array
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    view.ResetCamera()

    if args.screenshot:
        simple.SaveScreenshot(args.screenshot, view, ImageResolution=[1200, 900])
        print(f"spd.py: wrote {args.screenshot} ({args.array} at time {times[index]:g}, frame {index})")
    else:
        simple.Interact(view)


if __name__ == "__main__":
    main()
