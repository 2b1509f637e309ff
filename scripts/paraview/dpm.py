"""Opens the ParaView time series of a DPM run (`softgrain run dpm.jam --vtk`, or dpm.compress2d,
dpm.slump, dpm.compress3d, dpm.modes3d) and colours the particles by a cell array: the area ratio a/a0 (2D)
or the volume ratio v/v0 (3D) by default, or the particle id (--array particle_id). In 2D each vertex is
also drawn as its disk of radius sigma/2 in its particle's colour, so smooth-disk packings (one-vertex
particles, whose area ratio is NaN: grey; colour them with --array particle_id) show their disks. Plates,
walls and the periodic box are drawn in grey. 3D meshes are shown with their edges.

  pvpython scripts/paraview/dpm.py out/dpm.jam/vtk/dpm.jam.pvd
  pvpython scripts/paraview/dpm.py RUN.pvd --array particle_id --time last --screenshot frame.png

Without --screenshot it opens an interactive window at the chosen time; with it, it renders off screen and
writes the PNG. --time is a frame index (0, 1, ...), "first" or "last" (scripts/paraview/series.py).
"""

from paraview import simple

import series


def show_vertex_disks(particles, view, array):
    """Each vertex as its disk of radius sigma/2 (the `radius` point array), coloured as its particle: the
    smooth disks (one-vertex particles, vertex cells that a surface does not fill) and the vertex disks
    whose union is a DPM particle's outline (eq. 9.4). The particle's cell value is carried to its own
    vertices (no vertex is shared between particles), so the colour map is the particles' one."""
    per_vertex = simple.CellDatatoPointData(Input=particles)
    per_vertex.PassCellData = 1
    disks = simple.Glyph(Input=per_vertex, GlyphType="Sphere")
    disks.ScaleArray = ["POINTS", "radius"]
    disks.ScaleFactor = 2.0  # the sphere source has radius 1/2
    disks.OrientationArray = ["POINTS", "No orientation array"]
    disks.GlyphMode = "All Points"
    disks.GlyphType.ThetaResolution = 24
    display = simple.Show(disks, view)
    simple.ColorBy(display, ("POINTS", array))


def main():
    args = series.arguments(__doc__, "cell array of the particles to colour by (default: area_ratio in 2D, "
                                     "volume_ratio in 3D; particle_id, vertices, spring_strain)")
    reader, times, index = series.open_series(args)
    cells = reader.CellData.keys()
    three_d = "volume_ratio" in cells
    array = args.array or ("volume_ratio" if three_d else "area_ratio")
    series.require_array(array, cells)

    view = series.view_at(times[index], interaction_mode="3D" if three_d else "2D", orientation_axes=three_d)
    display = simple.Show(reader, view)
    if three_d:
        display.Representation = "Surface With Edges"
    series.colour_by(display, view, "CELLS", array, "Viridis (matplotlib)", grey_without_array=True)
    if not three_d:
        show_vertex_disks(series.part(reader, args.pvd, "particles"), view, array)
    if three_d:  # an oblique view from the side: the plates (normal to z) would hide the body from above
        camera = view.GetActiveCamera()
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(1, -3, 1.2)
        camera.SetViewUp(0, 0, 1)
    series.finish(view, args, array, times, index)


if __name__ == "__main__":
    main()
