"""Opens the ParaView time series of a VSM run (`softgrain run vsm.punch --vtk`, or vsm.swinging_cube,
vsm.lblock) and colours the particles by a point array: the Voronoi pressure p = -tr(sigma)/3 by default, as
in Frenning's Fig. 10 (the punch test), or any other (--array von_mises, volume_ratio, ...). The particles are
drawn as spheres; the walls (the symmetric faces and the punch) as translucent grey surfaces.

  pvpython scripts/paraview/vsm.py out/vsm.punch/vtk/vsm.punch.pvd
  pvpython scripts/paraview/vsm.py RUN.pvd --array von_mises --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last" (scripts/paraview/series.py).
"""

from paraview import simple

import series


def main():
    args = series.arguments(__doc__, "point array of the particles to colour by (pressure, von_mises, "
                                     "volume_ratio, voronoi_volume)", array_default="pressure")
    reader, times, index = series.open_series(args)
    view = series.view_at(times[index], orientation_axes=True)

    particles = series.part(reader, args.pvd, "particles")
    walls = series.part(reader, args.pvd, "walls")
    series.require_array(args.array, reader.PointData.keys())
    display = simple.Show(particles, view)
    display.Representation = "Points"
    display.RenderPointsAsSpheres = 1
    display.PointSize = 14
    series.colour_by(display, view, "POINTS", args.array, "Jet")

    if walls is not None:
        walls_display = simple.Show(walls, view)
        simple.ColorBy(walls_display, None)
        walls_display.AmbientColor = walls_display.DiffuseColor = [0.6, 0.6, 0.6]
        walls_display.Opacity = 0.25
    series.finish(view, args, args.array, times, index)


if __name__ == "__main__":
    main()
