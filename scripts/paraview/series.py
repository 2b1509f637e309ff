"""What the per-method ParaView scripts (spd.py, dpm.py, vsm.py) share: their command line, the run's time
series opened at the chosen frame, the colouring of the particles, and the interactive window or the
screenshot at the end. Each script imports it from its own folder (pvpython and pvbatch put that first on
the module path)."""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

from paraview import simple


def script_name():
    return os.path.basename(sys.argv[0])


def arguments(doc, array_help, array_default=None):
    """The command line every script takes: the .pvd, the array to colour by, the frame, the screenshot."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("pvd", help="the run's vtk/<scene>.pvd")
    parser.add_argument("--array", default=array_default, help=array_help)
    parser.add_argument("--time", default="last", help="frame index, 'first' or 'last'")
    parser.add_argument("--screenshot", help="write this PNG and exit")
    return parser.parse_args()


def open_series(args):
    """The reader of args.pvd, its frame times and the index of the frame args.time names (exit naming the
    allowed range when there is no such frame)."""
    reader = simple.PVDReader(FileName=args.pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    index = {"first": 0, "last": len(times) - 1}.get(args.time)
    index = int(args.time) if index is None else index
    if not 0 <= index < len(times):
        sys.exit(f"{script_name()}: --time {args.time}: allowed: 0 .. {len(times) - 1}, first or last")
    return reader, times, index


def part(reader, pvd, name):
    """The dataset `name` of every frame ("particles", "walls", ...), or None if the collection has none.
    With a single dataset the reader gives it as such, not as a block to extract."""
    names = {entry.get("name") for entry in ET.parse(pvd).getroot().iter("DataSet")}
    if name not in names:
        return None
    return reader if len(names) == 1 else simple.ExtractBlock(Input=reader, Selectors=[f"/Root/{name}"])


def require_array(array, available):
    if array not in available:
        sys.exit(f"{script_name()}: --array {array}: allowed: {', '.join(available)}")


def view_at(time, interaction_mode=None, orientation_axes=False):
    """The render view, showing the frame at `time`."""
    view = simple.GetActiveViewOrCreate("RenderView")
    if interaction_mode:
        view.InteractionMode = interaction_mode
    view.OrientationAxesVisibility = 1 if orientation_axes else 0
    scene = simple.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = time
    return view


def colour_by(display, view, association, array, preset, grey_without_array=False):
    """Colours `display` by `array` ("CELLS" or "POINTS") with a ParaView colour preset, over the data range,
    with a scalar bar; datasets without the array (walls, plates, the box) are grey if asked."""
    simple.ColorBy(display, (association, array))
    lut = simple.GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    if grey_without_array:
        lut.NanColor = [0.6, 0.6, 0.6]
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)


def colour_range(array):
    """The range the colour map of `array` spans: its first and last control point."""
    points = simple.GetColorTransferFunction(array).RGBPoints  # x, r, g, b per control point
    return points[0], points[-4]


def finish(view, args, array, times, index):
    """Saves the screenshot args.screenshot names, or opens the interactive window. The line it prints names
    what was drawn (array, frame, time and the colour range, to 17 digits) so that a test can check it."""
    view.ResetCamera()
    if args.screenshot:
        simple.SaveScreenshot(args.screenshot, view, ImageResolution=[1200, 900])
        low, high = colour_range(array)
        print(f"{script_name()}: wrote {args.screenshot} ({array} at time {times[index]:.17g}, frame {index}, "
              f"range {low:.17g} {high:.17g})")
    else:
        simple.Interact(view)
