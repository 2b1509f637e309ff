"""Opens the ParaView time series of a DPM run (`softgrain run dpm.jam --vtk`, or dpm.compress2d,
dpm.slump, dpm.compress3d, dpm.modes3d) and colours the particles by a cell array: the area ratio a/a0 (2D)
or the volume ratio v/v0 (3D) by default, or the particle id (--array particle_id). Plates, walls and the
periodic box are drawn in grey. 3D meshes are shown with their edges.

  pvpython scripts/paraview/dpm.py out/dpm.jam/vtk/dpm.jam.pvd
  pvpython scripts/paraview/dpm.py RUN.pvd --array particle_id --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last".
"""

import argparse
import sys

from paraview import simple


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd", help="the run's vtk/<scene>.pvd")
    parser.add_argument("--array", help="cell array of the particles to colour by (default: area_ratio in 2D, "
                                        "volume_ratio in 3D; particle_id, vertices, spring_strain)")
    parser.add_argument("--time", default="last", help="frame index, 'first' or 'last'")
    parser.add_argument("--screenshot", help="write this PNG and exit")
    args = parser.parse_args()

    reader = simple.PVDReader(FileName=args.pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    index = {"first": 0, "last": len(times) - 1}.get(args.time)
    index = int(args.time) if index is None else index
    if not 0 <= index < len(times):
        sys.exit(f"dpm.py: --time {args.time}: allowed: 0 .. {len(times) - 1}, first or last")

    cells = reader.CellData.keys()
    three_d = "volume_ratio" in cells
    array = args.array or ("volume_ratio" if three_d else "area_ratio")
    if array not in cells:
        sys.exit(f"dpm.py: --array {array}: allowed: {', '.join(cells)}")

    view = simple.GetActiveViewOrCreate("RenderView")
    view.InteractionMode = "3D" if three_d else "2D"
    view.OrientationAxesVisibility = 1 if three_d else 0
    scene = simple.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = times[index]

    display = simple.Show(reader, view)
    if three_d:
        display.Representation = "Surface With Edges"
    simple.ColorBy(display, ("CELLS", array))
    lut = simple.GetColorTransferFunction(array)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.NanColor = [0.6, 0.6, 0.6]  # plates, walls and the box carry no particle array
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    if three_d:  # an oblique view from the side: the plates (normal to z) would hide the body from above
        camera = view.GetActiveCamera()
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(1, -3, 1.2)
        camera.SetViewUp(0, 0, 1)
    view.ResetCamera()

    if args.screenshot:
        simple.SaveScreenshot(args.screenshot, view, ImageResolution=[1200, 900])
        print(f"dpm.py: wrote {args.screenshot} ({array} at time {times[index]:g}, frame {index})")
    else:
        simple.Interact(view)


if __name__ == "__main__":
    main()
