"""Opens the ParaView time series of an SD run (`softgrain run sd.many --vtk`, or sd.approach) and draws the
particles as translucent spheres of their radius R, and each bonded pair as a sphere at the middle of its
gap coloured by a point array of the pairs: the gap h by default, or the pair force F_ij (eq. 8, > 0
repulsive), the deflection delta (eq. 2) or the gap rate h-dot (eq. 7) (--array force, deflection,
gap_rate). A pair's sphere has a tenth of the particle radius, so that it sits in the gap.

  pvpython scripts/paraview/sd.py out/sd.many/vtk/sd.many.pvd
  pvpython scripts/paraview/sd.py RUN.pvd --array force --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last" (scripts/paraview/series.py).
"""

import sys

from paraview import simple

import series


def spheres(source, radius, radius_array=None):
    """A sphere at each point of `source`: of radius `radius`, times the point array `radius_array` if
    given."""
    glyphs = simple.Glyph(Input=source, GlyphType="Sphere")
    glyphs.ScaleArray = ["POINTS", radius_array or "No scale array"]
    glyphs.ScaleFactor = 2.0 * radius  # the sphere source has radius 1/2
    glyphs.OrientationArray = ["POINTS", "No orientation array"]
    glyphs.GlyphMode = "All Points"
    glyphs.GlyphType.ThetaResolution = 32
    glyphs.GlyphType.PhiResolution = 16
    return glyphs


def main():
    args = series.arguments(__doc__, "point array of the pairs to colour by (gap, force, deflection, gap_rate)",
                            array_default="gap")
    reader, times, index = series.open_series(args)
    view = series.view_at(times[index], orientation_axes=True)
    particles = series.part(reader, args.pvd, "particles")
    pairs = series.part(reader, args.pvd, "pairs")
    if pairs is None:
        sys.exit(f"{series.script_name()}: {args.pvd} has no pairs to colour (not an SD run?)")
    pairs.UpdatePipeline(times[index])
    series.require_array(args.array, pairs.PointData.keys())

    particle_display = simple.Show(spheres(particles, 1.0, "radius"), view)
    simple.ColorBy(particle_display, None)
    particle_display.AmbientColor = particle_display.DiffuseColor = [0.8, 0.8, 0.8]
    particle_display.Opacity = 0.3

    # A pair's sphere is a tenth of the particle radius R, which the pairs do not carry: R of the particles.
    particles.UpdatePipeline(times[index])
    pair_display = simple.Show(spheres(pairs, 0.1 * particles.PointData["radius"].GetRange()[0]), view)
    series.colour_by(pair_display, view, "POINTS", args.array, "Cool to Warm")
    series.finish(view, args, args.array, times, index)


if __name__ == "__main__":
    main()
