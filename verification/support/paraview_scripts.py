#!/usr/bin/python3
"""Runs the ParaView scripts a user is told to run (scripts/paraview/spd.py, dpm.py, vsm.py, sd.py,
scripts/paraview/README.md) the way that page says, with pvbatch and --screenshot, on small runs of
`softgrain run --vtk`, and checks what they drew:

  - each script exits 0 and prints the array, frame index, time value and colour range it used;
  - the frame is the one asked for (--time N, last): its time value equals the collection's N-th time value;
  - the colour range equals the range of that array in that frame, read independently from the frame's
    .vtp files with VTK's own reader (NaN excluded; see same_colour_range for ParaView's widening of a range
    of zero width);
  - the PNG is 1200 x 900 and the particles are drawn: at least 0.2 % of the pixels left of the colour bar
    have the saturated colours of the colour map (the background, the grey walls and the text do not: their
    channel spread is below 60 of 255);
  - a wrong --array or --time stops the script with a message naming what is allowed.

The scenes are spd.ring_compression (coloured by the elastic energy at frame 2, which differs from the
last frame's), dpm.jam of shells (area ratio, last frame) and of smooth disks (one-vertex particles, drawn
only as the vertex disks of dpm.py: by particle id), dpm.compress3d (volume ratio, 3D), vsm.punch (von
Mises stress at frame 1) and sd.many (4 particles on a line: the pair force at frame 3). pvbatch renders into an X server of its own: Xvfb with -displayfd, which picks a free
display number itself (xvfb-run -a races with other X servers started at the same moment), and -noreset
(see start_display).

  paraview_scripts.py SOFTGRAIN [WORKDIR]

Exit status: 0 all checks pass; 1 a check failed (each failure named on stderr); 77 pvbatch, Xvfb or VTK's
Python module is missing (`scripts/install-deps --paraview` installs paraview, xvfb and python3-vtk9), which
ctest reports as skipped.
"""

import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

from checks import check, failures

SKIP = 77
try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
except ImportError:
    vtkXMLPolyDataReader = None

SCRIPTS = Path(__file__).resolve().parents[2] / "scripts" / "paraview"


def start_display():
    """An Xvfb server on a display number it chooses itself; returns the process and DISPLAY."""
    ready, announce = os.pipe()
    # -noreset: by default the server resets when its last client leaves, and a pvbatch that connects during
    # the reset aborts with "bad X server connection" (measured: 1 of 12 back-to-back runs; 0 of 20 with it).
    server = subprocess.Popen(["Xvfb", "-displayfd", str(announce), "-screen", "0", "1280x1024x24",
                               "-nolisten", "tcp", "-noreset"], pass_fds=(announce,), stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    os.close(announce)
    with os.fdopen(ready) as pipe:
        number = pipe.readline().strip()  # written once the server accepts connections; "" if it died
    if not number:
        server.wait()
        sys.exit(f"paraview_scripts: Xvfb did not start (exit {server.returncode})")
    return server, f":{number}"


def frames(pvd):
    """The collection's frames in time order: a list of (time value, [.vtp paths])."""
    by_time = {}
    for entry in ET.parse(pvd).getroot().iter("DataSet"):
        by_time.setdefault(float(entry.get("timestep")), []).append(pvd.parent / entry.get("file"))
    return sorted(by_time.items())


def array_range(files, association, name):
    """Smallest and largest finite value of the array `name` over the files that carry it."""
    values = []
    for path in files:
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(str(path))
        reader.Update()
        data = reader.GetOutput()
        arrays = data.GetCellData() if association == "CELLS" else data.GetPointData()
        array = arrays.GetArray(name)
        if array is not None:
            values += [v for v in vtk_to_numpy(array).ravel() if math.isfinite(v)]
    return (min(values), max(values)) if values else None


def same_colour_range(drawn, data):
    """Whether ParaView's colour range `drawn` is the data range `data`: equal to 1e-12 relative (both are the
    same doubles; the margin only absorbs printing), except that ParaView widens a range of zero width (one
    particle) upwards by 2048 single-precision ulps (vtkSMCoreUtilities::AdjustRange; measured: a relative
    1.3e-4 and 1.6e-4), accepted up to 2.5e-4 relative. Neighbouring frames of these runs differ by 2 % or
    more, so either rule still tells the frame drawn from its neighbours."""
    scale = max(1.0, abs(data[0]), abs(data[1]))
    if data[0] != data[1]:
        return abs(drawn[0] - data[0]) <= 1e-12 * scale and abs(drawn[1] - data[1]) <= 1e-12 * scale
    return drawn[0] == data[0] and 0 < drawn[1] - data[1] <= 2.5e-4 * max(abs(data[1]), 1e-300)


def coloured_fraction(png):
    """The fraction of pixels left of the colour bar (the right fifth) whose channel spread is at least 60."""
    reader = vtkPNGReader()
    reader.SetFileName(str(png))
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, : width * 4 // 5, :3]
    spread = pixels.max(axis=2).astype(int) - pixels.min(axis=2).astype(int)
    return (width, height), float((spread >= 60).mean())


def run_script(script, pvd, display, *options):
    command = ["pvbatch", str(SCRIPTS / script), str(pvd), *options]
    return subprocess.run(command, capture_output=True, text=True, env={**os.environ, "DISPLAY": display},
                          timeout=300), " ".join(command)


def check_drawing(work, display, label, script, pvd, association, array, time, options):
    """Runs `script` with --screenshot and checks the frame, the colour range and the picture."""
    png = work / f"{label}.png"
    done, command = run_script(script, pvd, display, *options, "--time", time, "--screenshot", str(png))
    if not check(done.returncode == 0, f"{command}: exit {done.returncode}: {done.stderr.strip()[-2000:]}"):
        return
    said = re.search(r"\((\S+) at time (\S+), frame (\d+), range (\S+) (\S+)\)", done.stdout)
    if not check(said is not None, f"{label}: no drawing line in {done.stdout.strip()!r}"):
        return
    drawn, drawn_time, frame, low, high = said.group(1), float(said.group(2)), int(said.group(3)), \
        float(said.group(4)), float(said.group(5))
    series = frames(pvd)
    wanted = len(series) - 1 if time == "last" else int(time)
    check(drawn == array, f"{label}: coloured by {drawn}, expected {array}")
    check(frame == wanted and drawn_time == series[wanted][0],
          f"{label}: drew frame {frame} at time {drawn_time}, expected frame {wanted} at {series[wanted][0]}")
    expected = array_range(series[wanted][1], association, array)
    if check(expected is not None, f"{label}: no finite {array} in frame {wanted}"):
        check(same_colour_range((low, high), expected),
              f"{label}: colour range [{low:.17g}, {high:.17g}], the frame's {array} spans "
              f"[{expected[0]:.17g}, {expected[1]:.17g}]")
    size, fraction = coloured_fraction(png)
    check(size == (1200, 900), f"{label}: screenshot is {size[0]} x {size[1]}, expected 1200 x 900")
    check(fraction >= 0.002, f"{label}: {100 * fraction:.3f} % of the picture is coloured; the particles are "
          "missing (expected at least 0.2 %)")


def check_refusals(display, pvd):
    """A wrong array or frame names what is allowed and draws nothing."""
    for option, allowed in (("--array", "allowed: "), ("--time", "allowed: 0 .. ")):
        value = "no_such_array" if option == "--array" else "999"
        done, command = run_script("dpm.py", pvd, display, option, value, "--screenshot", os.devnull)
        check(done.returncode != 0 and f"{option} {value}: {allowed}" in done.stderr,
              f"{command}: exit {done.returncode}, expected a refusal naming what is allowed: "
              f"{done.stderr.strip()[-500:]}")


def make_run(softgrain, work, label, scene, *settings):
    out = work / label
    command = [softgrain, "run", scene, "--out", str(out), "--quiet", "--vtk", *settings]
    done = subprocess.run(command, capture_output=True, text=True)
    if not check(done.returncode == 0, f"{' '.join(command)}: exit {done.returncode}: {done.stderr.strip()}"):
        return None
    return out / scene / "vtk" / f"{scene}.pvd"


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    missing = [tool for tool in ("pvbatch", "Xvfb") if shutil.which(tool) is None]
    if vtkXMLPolyDataReader is None:
        missing.append("VTK's Python module")
    if missing:
        print(f"paraview_scripts: skipped: {', '.join(missing)} missing (scripts/install-deps --paraview)")
        sys.exit(SKIP)
    softgrain = str(Path(sys.argv[1]).resolve())
    work = Path(sys.argv[2]) if len(sys.argv) == 3 else Path(tempfile.mkdtemp(prefix="paraview-scripts-"))
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    runs = {
        "spd": make_run(softgrain, work, "spd", "spd.ring_compression", "--set", "nodes=32"),
        "dpm2d": make_run(softgrain, work, "dpm2d", "dpm.jam", "--set", "particles=8", "--set", "model=shell",
                          "--set", "pressures=2"),
        "disks": make_run(softgrain, work, "disks", "dpm.jam", "--set", "particles=8", "--set", "pressures=2"),
        "dpm3d": make_run(softgrain, work, "dpm3d", "dpm.compress3d"),
        "vsm": make_run(softgrain, work, "vsm", "vsm.punch", "--set", "per_side=5", "--set", "layers=2",
                        "--vtk-every", "50"),
        "sd": make_run(softgrain, work, "sd", "sd.many", "--set", "particles=4", "--set", "outputs=8"),
    }
    server, display = start_display()
    try:
        drawings = (
            ("spd", "spd.py", "CELLS", "elastic_energy", "2", ["--array", "elastic_energy"]),
            ("dpm2d", "dpm.py", "CELLS", "area_ratio", "last", []),
            ("disks", "dpm.py", "CELLS", "particle_id", "last", ["--array", "particle_id"]),
            ("dpm3d", "dpm.py", "CELLS", "volume_ratio", "last", []),
            ("vsm", "vsm.py", "POINTS", "von_mises", "1", ["--array", "von_mises"]),
            ("sd", "sd.py", "POINTS", "force", "3", ["--array", "force"]),
        )
        for label, script, association, array, time, options in drawings:
            if runs[label] is not None:
                check_drawing(work, display, label, script, runs[label], association, array, time, options)
        if runs["dpm2d"] is not None:
            check_refusals(display, runs["dpm2d"])
    finally:
        server.terminate()
        server.wait()
    print(f"paraview_scripts: {len(failures)} failure(s); screenshots in {work}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
