"""Opens the ParaView time series of a VSM run (`softgrain run vsm.punch --vtk`, or vsm.swinging_cube,
vsm.lblock) and colours the particles by a point array: the Voronoi pressure p = -tr(sigma)/3 by default, as
in Frenning's Fig. 10 (the punch test), or any other (--array von_mises, volume_ratio, ...). The particles are
drawn as spheres; the walls (the symmetric faces and the punch) as translucent grey surfaces.

  pvpython scripts/paraview/vsm.py out/vsm.punch/vtk/vsm.punch.pvd
  pvpython scripts/paraview/vsm.py RUN.pvd --array von_mises --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last".
"""

import argparse
import sys
import xml.etree.ElementTree as ET

from paraview import simple


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd", help="the run's vtk/<scene>.pvd")
    parser.add_argument("--array", default="pressure",
                        help="point array of the particles to colour by (pressure, von_mises, volume_ratio, "
                             "voronoi_volume)")
    parser.add_argument("--time", default="last", help="frame index, 'first' or 'last'")
    parser.add_argument("--screenshot", help="write this PNG and exit")
    args = parser.parse_args()

    reader = simple.PVDReader(FileName=args.pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    index = {"first": 0, "last": len(times) - 1}.get(args.time)
    index = int(args.time) if index is None else index
    if not 0 <= index < len(times):
        sys.exit(f"vsm.py: --time {args.time}: allowed: 0 .. {len(times) - 1}, first or last")

    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 1
    scene = simple.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = times[index]

    # With one dataset (the free L-block: no walls) the reader gives it as such, not as blocks to extract.
    parts = {e.get("name") for e in ET.parse(args.pvd).getroot().iter("DataSet")}
    walls = "walls" in parts
    particles = simple.ExtractBlock(Input=reader, Selectors=["/Root/particles"]) if walls else reader
    if args.array not in reader.PointData.keys():
        sys.exit(f"vsm.py: --array {args.array}: allowed: {', '.join(reader.PointData.keys())}")
    display = simple.Show(particles, view)
    display.Representation = "Points"
    display.RenderPointsAsSpheres = 1
    display.PointSize = 14
    simple.ColorBy(display, ("POINTS", args.array))
    lut = simple.GetColorTransferFunction(args.array)
    lut.ApplyPreset("Jet", True)
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)

    if walls:
        walls_display = simple.Show(simple.ExtractBlock(Input=reader, Selectors=["/Root/walls"]), view)
        simple.ColorBy(walls_display, None)
        walls_display.AmbientColor = walls_display.DiffuseColor = [0.6, 0.6, 0.6]
        walls_display.Opacity = 0.25

    view.ResetCamera()
    if args.screenshot:
        simple.SaveScreenshot(args.screenshot, view, ImageResolution=[1200, 900])
        print(f"vsm.py: wrote {args.screenshot} ({args.array} at time {times[index]:g}, frame {index})")
    else:
        simple.Interact(view)


if __name__ == "__main__":
    main()
