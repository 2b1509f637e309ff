#!/usr/bin/python3
"""Reads the ParaView time series of `softgrain run --vtk` back with VTK's own reader and compares it with the
run's tables and summary:

  - small runs of spd.ring_compression (with unloading), spd.compaction (--vtk-every 5), spd.tissue,
    dpm.compress2d (shell and spring network), dpm.slump (--vtk-every 5000 time steps) and dpm.jam
    (deformable particles, with decompression), each with --vtk;
  - the .pvd collection lists frames 0 .. n-1, every part of every frame, each file present, time values
    non-decreasing, no temporary file left; the number of frames is the scene's (one per recorded or load
    step, thinned by --vtk-every) and the summary's vtk_frames;
  - each frame opens with vtkXMLPolyDataReader (VTK reports no error or warning), with the point and cell counts the
    scene implies (vertices per particle, particles, walls) and its arrays; per frame, values compared
    with the run's table at the same step: the ring's area ratio with V/V0, the top wall's force summed over
    the contact lines with F/F* (relative to its largest), the strain with eps, the
    compaction's strain and height with eps and H, the tissue's strain with eps_h and its broken links with
    the links' broken flags, the shell's delta/D with delta, jam's phi with phi;
  - VSM: vsm.punch (every time step), vsm.swinging_cube and vsm.lblock (every 20th step): volume_ratio =
    det F, pressure = -tr(sigma)/3, the Voronoi volumes sum to the domain's, the punch wall at y = 0.5 - v t,
    the frames at the punch's snapshot steps equal snapshots.dat (positions, pressure), the L-block's
    momentum sum rho V v equals momentum.dat;
  - SD: sd.many on a line and in a cluster: gaps and velocities equal many.dat, |X_ij| = 2R + h - 2 delta
    (eq. 2);
  - spd.beam: the relaxed nodes equal profile.dat, the deflection the discrete chain's; spd.ring_pressure:
    area ratios against K_shell and K_e (eqs. (21), (25)); sd.approach: the pair against approach.dat, eq. (2)
    and the force balance; vsm.patch A, B, C: displacements and walls against the linear field eq. (52);
    compare.ring (SPD, DPM): widths and areas against ring.dat, the plate force against F R^2/B;
    dpm.shape3d: face areas, Euler count, volume, A^3D; dpm.slide3d: the slider's path and F_x/F_z against
    path.dat; dpm.shear_modulus3d: the first packing's phi from its meshes against modulus_shell.dat; the
    refusals of the benches, core.harmonic and sd.phase_diagram name their reason;
  - 3D DPM: dpm.compress3d (tetrahedra, shell, spring network): delta/D and F equal force.dat, the mesh's
    vertex forces at the top plate sum to F, volume ratios; dpm.modes3d (4 shells): the particles whole in
    the box and phi;
  - 2D DPM scenes with a frame per state, mode or packing: dpm.modes (a floppy particle and a disk packing:
    each mode's unit norm, orthogonality to the rigid motions and to the other modes, lambda against
    eigenvalues.dat, the first against lowest_mode.dat), dpm.crystal_modes (the mode against mode.dat and
    H u = lambda u with the pair Hessian recomputed from the frame), dpm.shear_friction (the contact line's
    forces against shear.dat's F_n and |F_t|, x_bm/D_beta from the anchors, mu's path), dpm.packing_fraction
    (phi of eqs. (9.18)-(9.22) recomputed from the polygons against the summary, contacts against eq. (9.4)),
    dpm.rearrangement (phi from the disks, the contact networks from the overlaps against the summary's
    counts, the irreversible step marked), dpm.compress_box (the walls' strain and the wall pressures from the
    vertex forces at the walls against pressure.dat), dpm.boundary_jam (disk-disk contacts from the centres
    against packings.dat) and dpm.shear_modulus (the Lees-Edwards parallelogram's shear against the strain,
    centres inside it, phi and P of packing 0 and G from the frames' stresses against modulus.dat);
  - DPM 2D contacts (jam, slump, and the scenes above): per particle, the contact forces sum to its
    vertices' forces; the contact pairs and forces of jam and packing_fraction equal eq. (9.4) recomputed
    from the frame's vertices;
  - spd.compaction stopped by kill -9 after a checkpoint and resumed with --resume --vtk: the same frames,
    time values and frame files, byte for byte, as the uninterrupted run.

  vtk_readback.py SOFTGRAIN [WORKDIR]

Exit status: 0 all checks pass; 1 a check failed (each failure named on stderr); 77 VTK's Python module is
missing (`scripts/install-deps --vtk` installs ParaView's, python3-paraview), which ctest reports as
skipped. Run it with Debian's /usr/bin/python3, for which that package is installed.
"""

import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

from checks import check, failures

SKIP = 77
try:
    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
except ImportError:
    vtkXMLPolyDataReader = None



def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def run(softgrain, out, scene, *options, expect=0):
    command = [softgrain, "run", scene, "--out", str(out), "--quiet", *options]
    started = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True)
    check(done.returncode == expect, f"{' '.join(command)}: exit {done.returncode}, expected {expect}: "
          f"{done.stderr.strip()}")
    return done, time.monotonic() - started


def table(path):
    """Rows of a softgrain .dat table as dicts of floats."""
    lines = [l for l in Path(path).read_text().splitlines() if l and not l.startswith("#")]
    names = lines[0].split()
    return [dict(zip(names, map(float, l.split()))) for l in lines[1:]]


# VTK's errors and warnings (a reader, its XML parser or its executive) go to this window, not to stderr.
messages = None
seen = 0


def vtk_messages():
    """What VTK reported since the last call."""
    global seen
    text = messages.GetOutput() if messages is not None else ""
    new, seen = text[seen:], len(text)
    return new.strip()


def read_series(result_dir, name):
    """The collection's frames as a list (per frame) of {part name: (time, vtkPolyData, file)}; checks the
    collection and that each file reads without error."""
    vtk_dir = Path(result_dir) / "vtk"
    pvd = vtk_dir / f"{name}.pvd"
    if not check(pvd.is_file(), f"{pvd} missing"):
        return []
    root = ET.parse(pvd).getroot()
    check(root.get("type") == "Collection", f"{pvd}: VTKFile type {root.get('type')}")
    entries = root.find("Collection").findall("DataSet")
    frames = {}
    for e in entries:
        file = e.get("file")
        stem = Path(file).stem
        frame = int(stem.rsplit("_", 1)[1])
        frames.setdefault(frame, {})[e.get("name")] = (float(e.get("timestep")), file, int(e.get("part")))
    check(sorted(frames) == list(range(len(frames))), f"{pvd}: frames {sorted(frames)} not 0..n-1")
    left = [p.name for p in vtk_dir.iterdir() if p.suffix == ".writing"]
    check(not left, f"{vtk_dir}: temporary files left: {left}")
    listed = {f for parts in frames.values() for (_, f, _) in parts.values()} | {pvd.name}
    check({p.name for p in vtk_dir.iterdir()} == listed, f"{vtk_dir}: files not listed in the collection")
    series, last_time = [], -math.inf
    for k in sorted(frames):
        parts = {}
        times = {t for (t, _, _) in frames[k].values()}
        check(len(times) == 1, f"{pvd}: frame {k} has parts at different times {times}")
        t = times.pop()
        check(t >= last_time, f"{pvd}: time {t} of frame {k} before {last_time}")
        last_time = t
        for part, (_, file, _) in frames[k].items():
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(str(vtk_dir / file))
            vtk_messages()
            reader.Update()
            reported = vtk_messages()
            check(not reported and reader.GetOutput() is not None, f"{file}: VTK's reader reported: {reported}")
            parts[part] = (t, reader.GetOutput(), vtk_dir / file)
        series.append(parts)
    return series


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    return array.GetValue(0) if array is not None else math.nan


def cell_values(data, name):
    array = data.GetCellData().GetArray(name)
    if array is None:
        return None
    return [array.GetValue(i) for i in range(array.GetNumberOfTuples())]


def summary(result_dir):
    return json.loads((Path(result_dir) / "summary.json").read_text())


def check_ring(softgrain, work):
    """spd.ring_compression with unloading: a frame per recorded load step."""
    out = work / "ring"
    nodes = 24
    _, seconds = run(softgrain, out, "spd.ring_compression", "--vtk", "--set", f"nodes={nodes}",
                     "strain_max=0.1", "strain_step=0.025", "unload=true")
    _, plain = run(softgrain, work / "ring-plain", "spd.ring_compression", "--set", f"nodes={nodes}",
                   "strain_max=0.1", "strain_step=0.025", "unload=true")
    result = out / "spd.ring_compression"
    rows = table(result / "compression.dat")
    series = read_series(result, "spd.ring_compression")
    check(len(series) == len(rows) == 9, f"ring: {len(series)} frames for {len(rows)} table rows (9 expected)")
    check(summary(result).get("vtk_frames") == len(series), "ring: summary vtk_frames")
    top_forces = []
    for k, (frame, row) in enumerate(zip(series, rows)):
        t, particles, _ = frame["particles"]
        _, walls, _ = frame["walls"]
        _, contacts, _ = frame["contacts"]
        check(t == k, f"ring frame {k}: time {t}, expected the load step {k}")
        # The top wall's force from the contact lines: minus the vertex force where the wall is the element,
        # plus it where a wall vertex is the contacting one (contact_force_on in lib/spd/shell_model.hpp).
        top = cell_values(walls, "wall_id")[1]
        mine, other = cell_values(contacts, "particle") or [], cell_values(contacts, "other_particle") or []
        force = contacts.GetCellData().GetArray("force")
        top_forces.append(sum((-1 if other[c] == top else 1 if mine[c] == top else 0) * force.GetTuple3(c)[1]
                              for c in range(contacts.GetNumberOfLines())))
        check(contacts.GetNumberOfLines() == contacts.GetNumberOfCells() and (row["F_over_Fstar"] <= 0 or mine),
              f"ring frame {k}: {contacts.GetNumberOfLines()} contact lines at F/F* = {row['F_over_Fstar']}")
        check(particles.GetNumberOfPoints() == nodes and particles.GetNumberOfPolys() == 1,
              f"ring frame {k}: {particles.GetNumberOfPoints()} points, {particles.GetNumberOfPolys()} polygons")
        check(walls.GetNumberOfLines() == 2, f"ring frame {k}: {walls.GetNumberOfLines()} wall lines")
        for name in ("velocity", "force", "contact_force", "hinge_torque", "plastic_ratio"):
            check(particles.GetPointData().GetArray(name) is not None, f"ring: point array {name} missing")
        ratio = cell_values(particles, "area_ratio")
        check(ratio is not None and close(ratio[0], row["V_over_V0"], 1e-10),
              f"ring frame {k}: area_ratio {ratio} against V/V0 = {row['V_over_V0']}")
        check(close(field(particles, "strain"), row["eps"], 1e-10),
              f"ring frame {k}: strain {field(particles, 'strain')} against eps = {row['eps']}")
    # Wall force over its largest value, from the contacts and from the table's F/F*.
    table_forces = [row["F_over_Fstar"] for row in rows]
    biggest = max(range(len(rows)), key=lambda k: table_forces[k])
    for k in range(len(rows)):
        check(close(top_forces[k] / top_forces[biggest], table_forces[k] / table_forces[biggest], 1e-9),
              f"ring frame {k}: top-wall force from the contacts {top_forces[k]} against F/F* {table_forces[k]}")
    size = sum(p.stat().st_size for p in (result / "vtk").iterdir())
    print(f"ring: {len(series)} frames, {size} bytes, {seconds:.2f} s with --vtk, {plain:.2f} s without")


def check_compaction(softgrain, work):
    """spd.compaction, every 5th recorded state, and a kill -9 + --resume that continues the series."""
    options = ["--set", "particles=6", "nodes=12", "strain_max=0.05", "--vtk", "--vtk-every", "5"]
    out = work / "compaction"
    _, seconds = run(softgrain, out, "spd.compaction", *options, "--checkpoint-every", "0")
    result = out / "spd.compaction"
    rows = table(result / "compaction.dat")
    series = read_series(result, "spd.compaction")
    expected = (len(rows) + 4) // 5
    check(len(series) == expected, f"compaction: {len(series)} frames for {len(rows)} records every 5th")
    s = summary(result)
    check(s.get("vtk_frames") == len(series), "compaction: summary vtk_frames")
    for k, frame in enumerate(series):
        t, particles, _ = frame["particles"]
        _, walls, _ = frame["walls"]
        row = rows[5 * k]
        check(particles.GetNumberOfPolys() == 6 and particles.GetNumberOfPoints() == 6 * 12,
              f"compaction frame {k}: {particles.GetNumberOfPolys()} polygons, "
              f"{particles.GetNumberOfPoints()} points")
        check(walls.GetNumberOfLines() == 4, f"compaction frame {k}: {walls.GetNumberOfLines()} walls")
        check(close(field(particles, "strain"), row["eps"], 1e-10),
              f"compaction frame {k}: strain {field(particles, 'strain')} against eps {row['eps']}")
        # H_over_R is H over the mean radius R = 1 m of the scene (ring radius, lib/spd/assembly.hpp).
        check(close(field(particles, "height"), row["H_over_R"], 1e-10),
              f"compaction frame {k}: height {field(particles, 'height')} against H/R {row['H_over_R']}")
        check((k == 0) == (t == 0), f"compaction frame {k}: time {t} (0 only at the first contact)")
        ids = cell_values(particles, "particle_id")
        check(ids is not None and len(set(ids)) == 6, f"compaction frame {k}: particle ids {ids}")
    check_resume(softgrain, work, options, series)
    return seconds


def check_resume(softgrain, work, options, reference):
    """Stops a run with kill -9 once a checkpoint and some frames exist, resumes it, and compares."""
    out = work / "resumed"
    command = [softgrain, "run", "spd.compaction", "--out", str(out), "--quiet", *options,
               "--checkpoint-every", "0.2"]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    frames_dir = out / ".spd.compaction.vtk-frames"
    checkpoint = out / "spd.compaction.checkpoint"
    deadline = time.monotonic() + 60
    second = frames_dir / "particles_000001.vtp"
    while time.monotonic() < deadline and process.poll() is None:
        # A checkpoint written after the second frame: it lists frames that the resumed run must keep.
        try:
            if checkpoint.stat().st_mtime_ns > second.stat().st_mtime_ns:
                break
        except FileNotFoundError:
            pass
        time.sleep(0.01)
    if process.poll() is not None:
        check(False, "resume: the run ended before a checkpoint and two frames existed; make it longer")
        return
    process.send_signal(signal.SIGKILL)
    process.wait()
    stopped_frames = len(list(frames_dir.glob("particles_*.vtp")))
    before = {p.name: p.stat().st_ino for p in frames_dir.glob("*.vtp")}
    run(softgrain, out, "spd.compaction", *options, "--checkpoint-every", "0.2", "--resume")
    result = out / "spd.compaction"
    s = summary(result)
    check(s.get("resumed_from_checkpoint") is True, "resume: the run did not resume from the checkpoint")
    check(not frames_dir.exists(), f"resume: {frames_dir} left after the run completed")
    series = read_series(result, "spd.compaction")
    check(len(series) == len(reference), f"resume: {len(series)} frames, uninterrupted {len(reference)}")
    for k, (a, b) in enumerate(zip(series, reference)):
        for part in ("particles", "walls"):
            check(a[part][0] == b[part][0], f"resume frame {k}: time {a[part][0]} against {b[part][0]}")
            check(a[part][2].read_bytes() == b[part][2].read_bytes(),
                  f"resume frame {k}: {a[part][2].name} differs from the uninterrupted run's")
    # The frames the checkpoint lists are the files written before the stop (the same inodes, moved into the
    # result), not written again.
    kept = [name for name, inode in before.items() if (result / "vtk" / name).exists()
            and (result / "vtk" / name).stat().st_ino == inode]
    check("particles_000000.vtp" in kept and "particles_000001.vtp" in kept,
          f"resume: the frames before the checkpoint were written again (kept: {sorted(kept)})")
    kept_frames = sum(1 for name in kept if name.startswith("particles_"))
    print(f"compaction resume: killed with {stopped_frames} frames on disk, {kept_frames} kept from before "
          f"the stop, resumed to {len(series)} frames, identical to the uninterrupted run")


def check_compress2d(softgrain, work):
    for model, extra in (("shell", ["nodes=16"]), ("spring_network", ["network_nodes=40"])):
        out = work / f"compress2d-{model}"
        run(softgrain, out, "dpm.compress2d", "--vtk", "--set", f"model={model}", "steps=4", *extra)
        result = out / "dpm.compress2d"
        rows = table(result / "force.dat")
        series = read_series(result, "dpm.compress2d")
        check(len(series) == len(rows) == 4, f"compress2d {model}: {len(series)} frames for {len(rows)} rows")
        for k, (frame, row) in enumerate(zip(series, rows)):
            t, body, _ = frame["particles"]
            _, plates, _ = frame["plates"]
            check(close(t, row["delta"], 1e-10), f"compress2d {model} frame {k}: time {t}, delta {row['delta']}")
            check(close(field(body, "force"), row["F"], 1e-10), f"compress2d {model} frame {k}: force")
            check(plates.GetNumberOfLines() == 2, f"compress2d {model} frame {k}: plates")
            radius = body.GetPointData().GetArray("radius")
            check(radius is not None and radius.GetValue(0) == 0.5, f"compress2d {model}: radius sigma/2")
            if model == "shell":
                check(body.GetNumberOfPoints() == 16 and body.GetNumberOfPolys() == 1,
                      f"compress2d shell frame {k}: {body.GetNumberOfPoints()} points")
            else:
                check(body.GetNumberOfVerts() == body.GetNumberOfPoints() and body.GetNumberOfLines() > 0,
                      f"compress2d network frame {k}: {body.GetNumberOfVerts()} nodes, "
                      f"{body.GetNumberOfLines()} springs")
                s = summary(result)
                check(body.GetNumberOfLines() == s["network_springs"], "compress2d network: springs")


def check_contact_balance(particles, contacts, label):
    """The contacts of a DPM 2D frame account for all of the interaction: per particle, the sum of the
    contact forces (+F on `particle`, -F on `other_particle`) equals the sum of its vertices' forces (the
    shape forces of a particle sum to zero)."""
    if not check(contacts.GetCellData().GetArray("normal_force") is not None
                 and contacts.GetCellData().GetArray("tangential_force") is not None,
                 f"{label}: contacts without normal_force or tangential_force"):
        return 0
    ids = cell_values(particles, "particle_id")
    vertex_force = particles.GetPointData().GetArray("force")
    total = {}
    for c in range(particles.GetNumberOfCells()):
        cell = particles.GetCell(c)
        f = [sum(vertex_force.GetTuple3(cell.GetPointId(k))[i] for k in range(cell.GetNumberOfPoints()))
             for i in range(2)]
        total[int(ids[c])] = f
    from_contacts = {p: [0.0, 0.0] for p in total}
    force = contacts.GetCellData().GetArray("force")
    mine, other = cell_values(contacts, "particle") or [], cell_values(contacts, "other_particle") or []
    normal = cell_values(contacts, "normal_force") or []
    for c in range(contacts.GetNumberOfCells()):
        f = force.GetTuple3(c)
        for i in range(2):
            from_contacts[int(mine[c])][i] += f[i]
            from_contacts[int(other[c])][i] -= f[i]
    # A missed pair or a wrong sign errs by a whole contact force; the shape forces cancel only to round-off
    # of their own size (the internal tensions, order k ~ 1 in the scenes' units, hidden in a relaxed frame).
    scale = max([abs(n) for n in normal] + [0.0])
    worst = max(abs(total[p][i] - from_contacts[p][i]) for p in total for i in range(2))
    check(worst <= 1e-6 * scale + 1e-12, f"{label}: particle force against its contacts' sum differs by "
          f"{worst} (largest normal force {scale})")
    return contacts.GetNumberOfCells()


def check_rough_contacts(particles, contacts, box, label):
    """The contacts of a rough DPM 2D packing (k_c = 1) against eq. (9.4) recomputed from the frame: for each
    particle pair, F on the first = sum over its vertex pairs closer than sigma_mb of (sigma_mb - r) r^/r,
    with the other particle at its image nearest to the first; one line exactly for each touching pair."""
    L = [max(box.GetPoint(i)[c] for i in range(box.GetNumberOfPoints())) for c in range(2)]
    ids = cell_values(particles, "particle_id")
    radius = particles.GetPointData().GetArray("radius")
    shapes = {}
    for c in range(particles.GetNumberOfCells()):
        cell = particles.GetCell(c)
        points = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
        shapes[int(ids[c])] = [(particles.GetPoint(q)[:2], radius.GetValue(q)) for q in points]
    expected = {}
    for m in shapes:
        for b in shapes:
            if b <= m:
                continue
            cm = [sum(p[c] for p, _ in shapes[m]) / len(shapes[m]) for c in range(2)]
            cb = [sum(p[c] for p, _ in shapes[b]) / len(shapes[b]) for c in range(2)]
            shift = [-L[c] * round((cb[c] - cm[c]) / L[c]) for c in range(2)]
            f, touching = [0.0, 0.0], False
            for (pi, ri) in shapes[m]:
                for (pj, rj) in shapes[b]:
                    d = [pi[c] - pj[c] - shift[c] for c in range(2)]
                    r = math.hypot(*d)
                    if r < ri + rj:
                        touching = True
                        for c in range(2):
                            f[c] += (ri + rj - r) * d[c] / r
            if touching:
                expected[(m, b)] = f
    mine, other = cell_values(contacts, "particle") or [], cell_values(contacts, "other_particle") or []
    got = {(int(mine[c]), int(other[c])): contacts.GetCellData().GetArray("force").GetTuple3(c)[:2]
           for c in range(contacts.GetNumberOfCells())}
    check(sorted(got) == sorted(expected), f"{label}: contact pairs {sorted(got)}, eq. (9.4) {sorted(expected)}")
    # Round-off: the frame's points are the particles shifted by whole box sides (eps L ~ 1e-15 per
    # coordinate), and each vertex pair's force k_c (sigma - r) inherits that absolutely: 1e-13 for the sums.
    scale = max([math.hypot(*f) for f in expected.values()] + [0.0])
    for pair in set(got) & set(expected):
        check(math.dist(got[pair], expected[pair]) <= 1e-9 * scale + 1e-13,
              f"{label}: contact {pair} force {got[pair]} against eq. (9.4) {expected[pair]}")


def check_jam(softgrain, work):
    out = work / "jam"
    particles = 6
    run(softgrain, out, "dpm.jam", "--vtk", "--set", "model=shell", f"particles={particles}", "nodes_small=6",
        "nodes_large=8", "pressures=2", "decompress=true")
    result = out / "dpm.jam"
    rows = table(result / "pressure.dat")
    series = read_series(result, "dpm.jam")
    check(len(series) == len(rows) == summary(result)["states"], f"jam: {len(series)} frames, {len(rows)} rows")
    for k, (frame, row) in enumerate(zip(series, rows)):
        t, data, _ = frame["particles"]
        _, box, _ = frame["box"]
        check(t == k, f"jam frame {k}: time {t}")
        check(data.GetNumberOfPolys() == particles and data.GetNumberOfPoints() == 3 * 6 + 3 * 8,
              f"jam frame {k}: {data.GetNumberOfPolys()} polygons, {data.GetNumberOfPoints()} points")
        check(close(field(data, "phi"), row["phi"], 1e-10), f"jam frame {k}: phi")
        check(close(field(data, "pressure"), row["P"], 1e-10), f"jam frame {k}: P")
        ratio = cell_values(data, "area_ratio")
        check(ratio is not None and all(0.5 < r < 1.5 for r in ratio), f"jam frame {k}: area ratios {ratio}")
        check(box.GetNumberOfLines() == 1, f"jam frame {k}: box outline")
        lines = check_contact_balance(data, frame["contacts"][1], f"jam frame {k}")
        check_rough_contacts(data, frame["contacts"][1], box, f"jam frame {k}")
        check(lines > 0, f"jam frame {k}: no contacts in a jammed packing")


def check_tissue(softgrain, work):
    """spd.tissue: every 20th record, the cells with W/W0 and the cohesive links."""
    out = work / "tissue"
    run(softgrain, out, "spd.tissue", "--vtk", "--checkpoint-every", "0", "--set", "columns=5", "rows=5",
        "pull_rate=2e-5", "strain_max=0.1")
    result = out / "spd.tissue"
    rows = table(result / "tissue.dat")
    series = read_series(result, "spd.tissue")
    s = summary(result)
    check(len(series) == (len(rows) + 19) // 20, f"tissue: {len(series)} frames for {len(rows)} records")
    for k, frame in enumerate(series):
        _, cells, _ = frame["particles"]
        _, links, _ = frame["links"]
        row = rows[20 * k]
        check(cells.GetNumberOfPolys() == s["cells"] and cells.GetNumberOfPoints() == s["vertices"]
              and links.GetNumberOfLines() == s["links"],
              f"tissue frame {k}: {cells.GetNumberOfPolys()} cells, {cells.GetNumberOfPoints()} vertices, "
              f"{links.GetNumberOfLines()} links; summary {s['cells']}, {s['vertices']}, {s['links']}")
        check(close(field(cells, "strain"), row["eps_h"], 1e-10),
              f"tissue frame {k}: strain {field(cells, 'strain')} against eps_h {row['eps_h']}")
        broken = cell_values(links, "broken")
        check(broken is not None and len(broken) == links.GetNumberOfLines() > 0
              and sum(broken) == field(cells, "broken_links"), f"tissue frame {k}: links")
        check(cell_values(cells, "W_over_W0") is not None, f"tissue frame {k}: W_over_W0 missing")
        check(frame["contacts"][1].GetCellData().GetArray("normal_force") is not None,
              f"tissue frame {k}: contacts without normal_force")


def check_slump(softgrain, work):
    """dpm.slump, a dynamic scene: a frame every 5000 time steps of both stages."""
    out = work / "slump"
    run(softgrain, out, "dpm.slump", "--vtk", "--vtk-every", "5000", "--set", "particles=4", "box_width=2",
        "nodes_small=8", "nodes_large=10")
    result = out / "dpm.slump"
    s = summary(result)
    series = read_series(result, "dpm.slump")
    check(len(series) == s["steps"] // 5000 + 1, f"slump: {len(series)} frames for {s['steps']} steps")
    released = touching = 0
    for k, frame in enumerate(series):
        t, particles, _ = frame["particles"]
        _, walls, _ = frame["walls"]
        check(close(t, 5000 * k * s["dt"], 1e-12), f"slump frame {k}: time {t}, expected {5000 * k} dt")
        check(field(particles, "step") == 5000 * k, f"slump frame {k}: step {field(particles, 'step')}")
        check(particles.GetNumberOfPolys() == 4 and particles.GetNumberOfPoints() == 2 * 8 + 2 * 10,
              f"slump frame {k}: {particles.GetNumberOfPolys()} polygons, {particles.GetNumberOfPoints()} points")
        check(particles.GetPointData().GetArray("velocity") is not None, f"slump frame {k}: no velocity")
        gone = field(particles, "released") == 1
        released += gone
        check(walls.GetNumberOfLines() == (2 if gone else 3), f"slump frame {k}: {walls.GetNumberOfLines()} walls")
        touching += check_contact_balance(particles, frame["contacts"][1], f"slump frame {k}")
    check(0 < released < len(series), f"slump: {released} of {len(series)} frames after the release")
    check(touching > 0, "slump: no contact line in any frame")


def cell_points(data, c):
    """The point ids of cell c."""
    cell = data.GetCell(c)
    return [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]


def box_sides(box):
    """(L_x, L_y) of a box outline starting at the origin (its largest coordinates; unsheared)."""
    return [max(box.GetPoint(i)[c] for i in range(box.GetNumberOfPoints())) for c in range(2)]


def mode_checks(data, label, rigid_rotation=False):
    """A `mode` point vector of unit norm, orthogonal to the rigid translations (and, for a free particle, to
    the rotation about its centre): a non-zero mode of a translation-invariant energy (eq. 9.28) is orthogonal
    to every zero mode. Returns the vector as a list of (ux, uy)."""
    u = point_tuples(data, "mode")
    if not check(u is not None and len(u) == data.GetNumberOfPoints(), f"{label}: no point vector `mode`"):
        return []
    # Round-off of a unit eigenvector of LAPACK / Eigen: n eps; 1e-12 leaves room for a few hundred dof.
    check(abs(sum(a * a + b * b + c * c for a, b, c in u) - 1) <= 1e-12, f"{label}: |mode| != 1")
    for i in range(2):
        check(abs(sum(v[i] for v in u)) <= 1e-10, f"{label}: mode not orthogonal to the translation {i}: "
              f"{sum(v[i] for v in u)}")
    check(all(v[2] == 0 for v in u), f"{label}: mode with a z component")
    if rigid_rotation:
        n = data.GetNumberOfPoints()
        c = [sum(data.GetPoint(i)[k] for i in range(n)) / n for k in range(2)]
        torque = sum((data.GetPoint(i)[0] - c[0]) * u[i][1] - (data.GetPoint(i)[1] - c[1]) * u[i][0] for i in range(n))
        check(abs(torque) <= 1e-10, f"{label}: mode not orthogonal to the rotation: {torque}")
    return [v[:2] for v in u]


def check_modes(softgrain, work):
    """dpm.modes: a frame per lowest non-zero mode (at most 8) of a floppy particle and of a smooth-disk
    packing; each mode against eigenvalues.dat and lowest_mode.dat, unit norm, orthogonal to the rigid motions
    and to the other frames' modes."""
    for name, options, single in (("modes", ["nodes=10"], True),
                                  ("modes-packing", ["particles=6", "model=smooth_disk"], False)):
        out = work / name
        run(softgrain, out, "dpm.modes", "--vtk", "--set", *options)
        result = out / "dpm.modes"
        s = summary(result)
        eigen = table(result / "eigenvalues.dat")
        lowest = table(result / "lowest_mode.dat")
        series = read_series(result, "dpm.modes")
        first = s["zero_modes"] + s["negative_modes"]  # index (from 0) of the first non-zero mode
        check(len(series) == min(8, len(eigen) - first) > 0,
              f"{name}: {len(series)} frames for {len(eigen) - first} non-zero modes (at most 8)")
        modes = []
        for k, frame in enumerate(series):
            t, data, _ = frame["particles"]
            label = f"{name} frame {k}"
            row = eigen[first + k]
            check(t == row["k"] == field(data, "mode_index"), f"{label}: time {t}, mode index {row['k']}")
            check(close(field(data, "lambda"), row["lambda"], 1e-10),
                  f"{label}: lambda {field(data, 'lambda')} against eigenvalues.dat {row['lambda']}")
            check(("box" in frame) == (not single) and ("contacts" in frame) == (not single),
                  f"{label}: parts {sorted(frame)}")
            modes.append(mode_checks(data, label, rigid_rotation=single))
        # The first frame's mode is the lowest non-zero one of lowest_mode.dat (12 significant digits).
        if modes and modes[0]:
            check(len(lowest) == len(modes[0]) and all(
                abs(a[0] - r["ux"]) <= 1e-11 and abs(a[1] - r["uy"]) <= 1e-11 for a, r in zip(modes[0], lowest)),
                f"{name}: the first frame's mode differs from lowest_mode.dat")
        for a in range(len(modes)):
            for b in range(a):
                dot = sum(p[0] * q[0] + p[1] * q[1] for p, q in zip(modes[a], modes[b]))
                check(abs(dot) <= 1e-10, f"{name}: modes of frames {a} and {b} not orthogonal ({dot})")
    print("dpm.modes: mode frames of a floppy particle and of a disk packing read back")


def check_shear_friction(softgrain, work):
    """dpm.shear_friction: a frame per shear step; the contact line's forces against shear.dat's F_n, F_t
    (eqs. 9.11, 9.12, from another computation of the pair force), x_bm / D_beta from the anchors."""
    out = work / "shear-friction"
    run(softgrain, out, "dpm.shear_friction", "--vtk", "--set", "dx=0.1")
    result = out / "dpm.shear_friction"
    s = summary(result)
    rows = table(result / "shear.dat")
    series = read_series(result, "dpm.shear_friction")
    check(len(series) == 15, f"shear_friction: {len(series)} frames, expected (0.7 + 0.7) / 0.1 + 1 = 15")
    in_contact = 0
    for k, frame in enumerate(series):
        t, particles, _ = frame["particles"]
        contacts, anchors, path = frame["contacts"][1], frame["anchors"][1], frame["path"][1]
        label = f"shear_friction frame {k}"
        check(particles.GetNumberOfPolys() == 2 and particles.GetNumberOfPoints() == 16, f"{label}: particles")
        # x_bm / D_beta (shear_friction.hpp): mu's middle anchor (index 3) from the midpoint of beta's two.
        a = [anchors.GetPoint(i) for i in range(anchors.GetNumberOfPoints())]
        check(len(a) == 5 and close((a[3][0] - 0.5 * (a[0][0] + a[1][0])) / s["D_beta"], t, 1e-12),
              f"{label}: anchors give x/D {(a[3][0] - 0.5 * (a[0][0] + a[1][0])) / s['D_beta']}, time {t}")
        # The path: mu's centre at every step so far, the last one this frame's.
        mu = cell_points(particles, 1)
        centre = [sum(particles.GetPoint(i)[c] for i in mu) / len(mu) for c in range(2)]
        check(path.GetNumberOfPoints() == k + 1 and math.dist(path.GetPoint(k)[:2], centre) <= 1e-12,
              f"{label}: path of {path.GetNumberOfPoints()} points ending at {path.GetPoint(k)}, mu at {centre}")
        row = next((r for r in rows if close(r["x_over_D"], t, 1e-9)), None)
        normal = cell_values(contacts, "normal_force") or []
        tangential = cell_values(contacts, "tangential_force") or []
        if row is None:
            check(all(n <= 0 for n in normal), f"{label}: a repulsive contact {normal} where shear.dat has none")
            continue
        in_contact += 1
        # shear.dat prints 12 significant digits.
        check(len(normal) == 1 and close(normal[0], row["F_n"], 1e-10) and close(tangential[0], abs(row["F_t"]), 1e-10),
              f"{label}: contact forces {normal}, {tangential} against F_n {row['F_n']}, |F_t| {abs(row['F_t'])}")
        check(close(field(particles, "mu_eff"), row["mu_eff"], 1e-10), f"{label}: mu_eff")
    check(in_contact == len(rows) > 0, f"shear_friction: {in_contact} frames in contact, {len(rows)} rows")
    print(f"dpm.shear_friction: {len(series)} frames, {in_contact} in contact match shear.dat")


def segment(r, sigma_mu, sigma_beta):
    """Eq. (9.20): the circular segment of the vertex disk mu beyond the radical line with beta."""
    a, b = 0.5 * sigma_mu, 0.5 * sigma_beta
    if r >= a + b:
        return 0.0
    c = min(1.0, max(-1.0, (r * r - b * b + a * a) / (2 * r) / a))
    return a * a * (math.acos(c) - c * math.sqrt(1 - c * c))


def packing_fraction_of_frame(particles, L):
    """Eqs. (9.18)-(9.22) recomputed from a frame's polygons and vertex radii: (phi, A_polygon / L^2)."""
    radius = point_tuples(particles, "radius")
    shapes = []
    for c in range(particles.GetNumberOfCells()):
        ids = cell_points(particles, c)
        shapes.append(([particles.GetPoint(i)[:2] for i in ids], 2 * radius[ids[0]][0]))
    polygon = vertices = sector = pair = 0.0
    for points, sigma in shapes:
        n = len(points)
        polygon += 0.5 * sum(points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1]
                             for i in range(n))
        vertices += n * math.pi * sigma * sigma / 4
        for i in range(n):
            p, q, r = points[i - 1], points[i], points[(i + 1) % n]
            e, f = (q[0] - p[0], q[1] - p[1]), (r[0] - q[0], r[1] - q[1])
            turning = math.atan2(e[0] * f[1] - e[1] * f[0], e[0] * f[0] + e[1] * f[1])
            sector += sigma * sigma * (math.pi - turning) / 8
            pair += segment(math.hypot(*f), sigma, sigma)
    for m, (pm, sm) in enumerate(shapes):
        for b, (pb, sb) in enumerate(shapes):
            if b == m:
                continue
            for p in pm:
                for q in pb:
                    d = [p[c] - q[c] for c in range(2)]
                    d = [d[c] - L[c] * round(d[c] / L[c]) for c in range(2)]
                    pair += segment(math.hypot(*d), sm, sb)
    area = L[0] * L[1]
    return (polygon + vertices - sector - pair) / area, polygon / area


def check_packing_fraction(softgrain, work):
    """dpm.packing_fraction: one frame of the jammed packing; phi of eqs. (9.18)-(9.22) recomputed from the
    frame's polygons against the summary's, the contacts against eq. (9.4)."""
    out = work / "packing-fraction"
    run(softgrain, out, "dpm.packing_fraction", "--vtk", "--set", "samples=1000")
    result = out / "dpm.packing_fraction"
    s = summary(result)
    series = read_series(result, "dpm.packing_fraction")
    check(len(series) == 1, f"packing_fraction: {len(series)} frames")
    for frame in series:
        _, particles, _ = frame["particles"]
        box, contacts = frame["box"][1], frame["contacts"][1]
        L = box_sides(box)
        check(close(L[0], s["box"], 1e-15), f"packing_fraction: box {L} against {s['box']}")
        check(particles.GetNumberOfPolys() == 7 and particles.GetNumberOfPoints() == 35, "packing_fraction: cells")
        phi, polygon = packing_fraction_of_frame(particles, L)
        # The same sums from the same coordinates in another order: round-off, 1e-12.
        check(close(phi, s["phi_analytic"], 1e-12) and close(field(particles, "phi"), s["phi_analytic"], 1e-15),
              f"packing_fraction: phi {phi} from the polygons, summary {s['phi_analytic']}")
        check(close(polygon, s["A_polygon_analytic"], 1e-12), f"packing_fraction: A_polygon {polygon}")
        lines = check_contact_balance(particles, contacts, "packing_fraction")
        check_rough_contacts(particles, contacts, box, "packing_fraction")
        check(lines > 0, "packing_fraction: no contacts in a jammed packing")
        print(f"dpm.packing_fraction: phi = {phi:.12f} from the frame, {lines} contacts")


def check_crystal_modes(softgrain, work):
    """dpm.crystal_modes: the crystal and its mode; the mode against mode.dat and the eigenvalue equation
    H u = lambda u of eq. (9.28) with the pair Hessian of k/2 (sigma - r)^2 recomputed from the frame."""
    rows_n = 6
    out = work / "crystal"
    run(softgrain, out, "dpm.crystal_modes", "--vtk", "--set", f"rows={rows_n}")
    result = out / "dpm.crystal_modes"
    s = summary(result)
    rows = table(result / "mode.dat")
    series = read_series(result, "dpm.crystal_modes")
    check(len(series) == 1, f"crystal: {len(series)} frames")
    for frame in series:
        _, disks, _ = frame["particles"]
        L = box_sides(frame["box"][1])
        n = rows_n * rows_n
        check(disks.GetNumberOfVerts() == n == disks.GetNumberOfPoints(), "crystal: disks")
        check(frame["contacts"][1].GetNumberOfLines() == 3 * n, f"crystal: {frame['contacts'][1].GetNumberOfLines()} "
              f"contacts, 6 per disk in a compressed triangular crystal")
        u = mode_checks(disks, "crystal")
        check(all(abs(a[0] - r["ux"]) <= 1e-11 and abs(a[1] - r["uy"]) <= 1e-11 for a, r in zip(u, rows)),
              "crystal: mode differs from mode.dat")
        lam = field(disks, "lambda_mode")
        check(close(lam, s["lambda_mode"], 1e-15) and close(lam, s["lambda_mode_exact"], 1e-9),
              f"crystal: lambda {lam}, exact phonon {s['lambda_mode_exact']}")
        sigma = 2 * point_tuples(disks, "radius")[0][0]
        hu = [[0.0, 0.0] for _ in range(n)]
        for i in range(n):
            for j in range(i + 1, n):
                d = [disks.GetPoint(j)[c] - disks.GetPoint(i)[c] for c in range(2)]
                d = [d[c] - L[c] * round(d[c] / L[c]) for c in range(2)]
                r = math.hypot(*d)
                if r >= sigma:
                    continue
                e = [d[0] / r, d[1] / r]
                # U'' e e^T + (U'/r)(I - e e^T), U'' = k = 1, U' = -(sigma - r) (crystal.hpp).
                K = [[e[a] * e[b] - (sigma - r) / r * ((a == b) - e[a] * e[b]) for b in range(2)] for a in range(2)]
                du = [u[i][c] - u[j][c] for c in range(2)]
                for a in range(2):
                    f = K[a][0] * du[0] + K[a][1] * du[1]
                    hu[i][a] += f
                    hu[j][a] -= f
        # Eigensolver round-off: n eps lambda_max (lambda_max < 6 k in this crystal): 1e-12.
        residual = max(abs(hu[i][a] - lam * u[i][a]) for i in range(n) for a in range(2))
        check(residual <= 1e-12, f"crystal: |H u - lambda u| = {residual}")
        print(f"dpm.crystal_modes: H u = lambda u to {residual:.1e} from the frame")


def check_rearrangement(softgrain, work):
    """dpm.rearrangement: a frame per compression step; phi from the disks, the contact networks before and
    after against the summary, the irreversible step marked."""
    out = work / "rearrangement"
    run(softgrain, out, "dpm.rearrangement", "--vtk", "--set", "particles=12", "dphi=1e-3")
    result = out / "dpm.rearrangement"
    s = summary(result)
    series = read_series(result, "dpm.rearrangement")
    check(s["found"] and len(series) == s["step"] + 1, f"rearrangement: {len(series)} frames, step {s['step']}")
    threshold = s["contact_overlap_threshold"]
    networks, changed = [], 0
    for k, frame in enumerate(series):
        t, disks, _ = frame["particles"]
        contacts = frame["contacts"][1]
        label = f"rearrangement frame {k}"
        check(t == k == field(disks, "step"), f"{label}: time {t}")
        L = box_sides(frame["box"][1])
        radius = point_tuples(disks, "radius")
        n = disks.GetNumberOfPoints()
        phi = sum(math.pi * r[0] ** 2 for r in radius) / (L[0] * L[1])
        check(close(phi, field(disks, "phi"), 1e-12), f"{label}: phi {field(disks, 'phi')}, disks {phi}")
        touching, network = set(), set()
        for i in range(n):
            for j in range(i + 1, n):
                d = [disks.GetPoint(j)[c] - disks.GetPoint(i)[c] for c in range(2)]
                d = [d[c] - L[c] * round(d[c] / L[c]) for c in range(2)]
                overlap = radius[i][0] + radius[j][0] - math.hypot(*d)
                if overlap > 0:
                    touching.add((i, j))
                if overlap > threshold:
                    network.add((i, j))
        lines = set(zip(map(int, cell_values(contacts, "particle") or []),
                        map(int, cell_values(contacts, "other_particle") or [])))
        check(lines == touching, f"{label}: contact lines {sorted(lines ^ touching)} differ from the overlaps")
        check(len(network) == field(disks, "network_contacts"), f"{label}: network {len(network)}")
        check((k > 0 and network != networks[-1]) == (field(disks, "network_changed") == 1),
              f"{label}: network_changed {field(disks, 'network_changed')}")
        changed += field(disks, "network_changed") == 1
        check((field(disks, "irreversible") == 1) == (k == len(series) - 1), f"{label}: irreversible")
        networks.append(network)
    check(changed == s["elastic_network_changes"] + 1, f"rearrangement: {changed} network changes, summary "
          f"{s['elastic_network_changes']} elastic + 1")
    if len(series) >= 2:
        check(len(networks[-2]) == s["contacts_before"] and len(networks[-1]) == s["contacts_after"],
              f"rearrangement: networks {len(networks[-2])}, {len(networks[-1])} against the summary's "
              f"{s['contacts_before']}, {s['contacts_after']}")
        broken, formed = networks[-2] - networks[-1], networks[-1] - networks[-2]
        check(len(broken) == s["contacts_broken"] and len(formed) == s["contacts_formed"],
              f"rearrangement: {len(broken)} broken, {len(formed)} formed")
        last, before = series[-1]["particles"][1], series[-2]["particles"][1]
        check(close(field(last, "phi"), s["phi_after"], 1e-15) and close(field(before, "phi"), s["phi_before"], 1e-15)
              and close(field(last, "pressure"), s["pressure_after"], 1e-15), "rearrangement: phi and P")
    # Every 10th step, and always the rearrangement's.
    run(softgrain, work / "rearrangement-every", "dpm.rearrangement", "--vtk", "--vtk-every", "10", "--set",
        "particles=12", "dphi=1e-3")
    thinned = read_series(work / "rearrangement-every" / "dpm.rearrangement", "dpm.rearrangement")
    expected = [k for k in range(s["step"] + 1) if k % 10 == 0 or k == s["step"]]
    check([frame["particles"][0] for frame in thinned] == expected,
          f"rearrangement --vtk-every 10: steps {[frame['particles'][0] for frame in thinned]}, expected {expected}")
    print(f"dpm.rearrangement: {len(series)} frames, rearrangement at step {s['step']}")


def check_compress_box(softgrain, work):
    """dpm.compress_box (disks, deformable): a frame per state; the strain from the walls and the wall
    pressures from the particles' forces on the vertices touching them (static balance) against pressure.dat."""
    for model, extra, points in (("disks", ["particles=6"], 6),
                                 ("deformable", ["particles=4", "nodes_small=6", "nodes_large=8"], 2 * 6 + 2 * 8)):
        out = work / f"compress-box-{model}"
        run(softgrain, out, "dpm.compress_box", "--vtk", "--set", f"model={model}", "steps=3", *extra)
        result = out / "dpm.compress_box"
        s = summary(result)
        rows = table(result / "pressure.dat")
        series = read_series(result, "dpm.compress_box")
        check(len(series) == len(rows) == 4, f"compress_box {model}: {len(series)} frames, {len(rows)} rows")
        h0 = box_sides(series[0]["walls"][1])[1] if series else 1
        unit, p0 = s["pressure_unit_over_kc"], 1e-2  # pressure_start's default
        for k, (frame, row) in enumerate(zip(series, rows)):
            t, particles, _ = frame["particles"]
            label = f"compress_box {model} frame {k}"
            w, h = box_sides(frame["walls"][1])
            check(particles.GetNumberOfPoints() == points, f"{label}: {particles.GetNumberOfPoints()} points")
            check(close(t, row["strain"], 1e-10) and close(1 - h / h0, row["strain"], 1e-10),
                  f"{label}: time {t}, walls' strain {1 - h / h0}, table {row['strain']}")
            radius, force = point_tuples(particles, "radius"), point_tuples(particles, "force")
            # A vertex overlapping a wall is held by it: the particles' force on it balances the wall's, so
            # the wall pressure is the sum of those forces per length (both walls of a pair, as the table).
            fx = fy = 0.0
            touching = 0
            for i in range(particles.GetNumberOfPoints()):
                x, y, _ = particles.GetPoint(i)
                r = radius[i][0]
                for position, axis, sign in ((0, 0, -1), (w, 0, 1), (0, 1, -1), (h, 1, 1)):
                    if sign * ((x, y)[axis] - position) > -r:
                        touching += 1
                        if axis == 0:
                            fx += sign * force[i][0]
                        else:
                            fy += sign * force[i][1]
            # FIRE leaves each force component below 1e-3 P0 (in the system's units): per touching vertex.
            bound = touching * 1e-3 * p0
            check(abs(fx / (2 * h) / unit - row["P_x"]) <= bound / (2 * h) + 1e-10 * row["P_x"]
                  and abs(fy / (2 * w) / unit - row["P_y"]) <= bound / (2 * w) + 1e-10 * row["P_y"],
                  f"{label}: wall pressures from the vertex forces {fx / (2 * h) / unit}, {fy / (2 * w) / unit}, "
                  f"table {row['P_x']}, {row['P_y']}")
            check(close(field(particles, "pressure_y"), row["P_y"], 1e-10), f"{label}: field pressure_y")
            check_contact_balance(particles, frame["contacts"][1], label)
    print("dpm.compress_box: wall pressures from the frames match pressure.dat")


def check_boundary_jam(softgrain, work):
    """dpm.boundary_jam: a frame per packing; the disk-disk contacts from the frame's disks against
    packings.dat."""
    out = work / "boundary-jam"
    nodes = 50
    run(softgrain, out, "dpm.boundary_jam", "--vtk", "--set", "trials=2", f"boundary_nodes={nodes}",
        "boundary_sigma=0.4")
    result = out / "dpm.boundary_jam"
    rows = table(result / "packings.dat")
    series = read_series(result, "dpm.boundary_jam")
    check(len(series) == len(rows) == 2, f"boundary_jam: {len(series)} frames, {len(rows)} rows")
    for k, (frame, row) in enumerate(zip(series, rows)):
        t, data, _ = frame["particles"]
        label = f"boundary_jam frame {k}"
        check(t == row["trial"], f"{label}: time {t}")
        check(data.GetNumberOfVerts() == 4 and data.GetNumberOfPolys() == 1 and data.GetNumberOfPoints() == 4 + nodes,
              f"{label}: {data.GetNumberOfVerts()} disks, {data.GetNumberOfPolys()} rings")
        radius = point_tuples(data, "radius")
        disks = [(data.GetPoint(i)[:2], radius[i][0]) for i in range(4)]
        # Disk-disk contacts: centres closer than the disk diameter d = 1.
        geometric = sum(math.dist(disks[i][0], disks[j][0]) < disks[i][1] + disks[j][1]
                        for i in range(4) for j in range(i + 1, 4))
        contacts = frame["contacts"][1]
        mine, other = cell_values(contacts, "particle") or [], cell_values(contacts, "other_particle") or []
        lines = sum(1 for a, b in zip(mine, other) if a < 4 and b < 4)
        check(geometric == lines == row["contacts"] == field(data, "disk_contacts"),
              f"{label}: {geometric} disk contacts from the centres, {lines} lines, table {row['contacts']}")
        check_contact_balance(data, contacts, label)
    print("dpm.boundary_jam: disk contacts of the frames match packings.dat")


def check_shear_modulus(softgrain, work):
    """dpm.shear_modulus: frames of the first packing at each strain step of each pressure; the box a
    parallelogram of the strain, the particles' centres inside it, G from the frames' stresses against
    modulus.dat."""
    out = work / "shear-modulus"
    steps, dgamma = 2, 5e-9
    run(softgrain, out, "dpm.shear_modulus", "--vtk", "--set", "particles=6", "packings=2", "pressures=2",
        f"strain_steps={steps}", f"strain_step={dgamma}")
    result = out / "dpm.shear_modulus"
    rows = [r for r in table(result / "modulus.dat") if r["packing"] == 0]
    series = read_series(result, "dpm.shear_modulus")
    check(len(series) == len(rows) * (steps + 1) == 9, f"shear_modulus: {len(series)} frames, {len(rows)} states")
    for state, row in enumerate(rows):
        gammas, stresses = [], []
        for step in range(steps + 1):
            k = state * (steps + 1) + step
            if k >= len(series):
                break
            t, disks, _ = series[k]["particles"]
            box = series[k]["box"][1]
            label = f"shear_modulus frame {k}"
            check(t == k and field(disks, "state") == state and field(disks, "step") == step, f"{label}: time {t}")
            gamma = field(disks, "gamma")
            check(close(gamma, step * dgamma, 1e-12), f"{label}: gamma {gamma}, expected {step} x {dgamma}")
            corners = [box.GetPoint(i)[:2] for i in range(4)]
            Lx, Ly = corners[1][0], corners[3][1]
            # The parallelogram (0, 0), (L_x, 0), (L_x + gamma L_y, L_y), (gamma L_y, L_y): its shear is gamma.
            check(corners[0] == (0, 0) and corners[1][1] == 0 and close(corners[3][0] / Ly, gamma, 1e-12)
                  and close(corners[2][0] - corners[3][0], Lx, 1e-15), f"{label}: box {corners}")
            radius = point_tuples(disks, "radius")
            n = disks.GetNumberOfPoints()
            for i in range(n):
                x, y, _ = disks.GetPoint(i)
                s_, t_ = (x - gamma * y) / Lx, y / Ly
                check(0 <= s_ < 1 and 0 <= t_ < 1, f"{label}: disk {i} at ({x}, {y}) outside the sheared box")
            phi = sum(math.pi * r[0] ** 2 for r in radius) / (Lx * Ly)
            check(close(phi, row["phi"], 1e-10) and close(field(disks, "pressure"), row["P"], 1e-10),
                  f"{label}: phi {phi} from the disks, P {field(disks, 'pressure')}; table {row['phi']}, {row['P']}")
            gammas.append(gamma)
            stresses.append(field(disks, "shear_stress"))
        if len(gammas) == steps + 1:
            # G: the least-squares slope of Sigma~ against gamma (shear_modulus.hpp).
            mg, ms = sum(gammas) / len(gammas), sum(stresses) / len(stresses)
            G = sum((g - mg) * (s_ - ms) for g, s_ in zip(gammas, stresses)) / sum((g - mg) ** 2 for g in gammas)
            check(abs(G - row["G"]) <= 1e-9 * abs(row["G"]), f"shear_modulus state {state}: G {G} from the "
                  f"frames, modulus.dat {row['G']}")
    print(f"dpm.shear_modulus: {len(series)} frames of packing 0, G from the frames matches modulus.dat")


def point_tuples(data, name):
    """The point array `name` as a list of tuples (None if absent)."""
    array = data.GetPointData().GetArray(name)
    if array is None:
        return None
    return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]


def det3(F):
    return (F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6])
            + F[2] * (F[3] * F[7] - F[4] * F[6]))


def check_vsm_particles(data, label, particles, volume):
    """A VSM particles part: one vertex cell per particle, F with 9 components, volume_ratio = det F,
    pressure = -tr(sigma)/3, and the Voronoi cells tiling the domain."""
    check(data.GetNumberOfPoints() == particles and data.GetNumberOfVerts() == particles,
          f"{label}: {data.GetNumberOfPoints()} points, {data.GetNumberOfVerts()} vertex cells for {particles}")
    F = data.GetPointData().GetArray("deformation_gradient")
    sigma = data.GetPointData().GetArray("cauchy_stress")
    if not check(F is not None and F.GetNumberOfComponents() == 9 and sigma is not None
                 and sigma.GetNumberOfComponents() == 9, f"{label}: F or sigma missing or not 9 components"):
        return
    J, p, V = (point_tuples(data, n) for n in ("volume_ratio", "pressure", "voronoi_volume"))
    for name in ("displacement", "velocity", "von_mises"):
        check(data.GetPointData().GetArray(name) is not None, f"{label}: point array {name} missing")
    scale = max(abs(q[0]) for q in p) or 1.0
    for a in range(particles):
        f, s = F.GetTuple(a), sigma.GetTuple(a)
        check(close(J[a][0], det3(f), 1e-12), f"{label}: particle {a} volume_ratio {J[a][0]}, det F {det3(f)}")
        check(abs(p[a][0] + (s[0] + s[4] + s[8]) / 3) <= 1e-12 * scale,
              f"{label}: particle {a} pressure {p[a][0]} against -tr(sigma)/3")
    check(close(sum(v[0] for v in V), volume, 1e-9), f"{label}: Voronoi volumes sum to {sum(v[0] for v in V)}, "
          f"domain {volume}")
    ids = cell_values(data, "particle_id")
    check(ids == list(range(particles)), f"{label}: particle ids")


def check_vsm(softgrain, work):
    """vsm.punch every time step (the frames at the snapshot steps against snapshots.dat), vsm.swinging_cube
    and vsm.lblock with their cadence."""
    out = work / "punch"
    run(softgrain, out, "vsm.punch", "--vtk", "--vtk-every", "1", "--set", "per_side=2", "layers=2",
        "final_strain=0.02")
    result = out / "vsm.punch"
    s = summary(result)
    series = read_series(result, "vsm.punch")
    check(len(series) == s["steps"] + 1, f"punch: {len(series)} frames for {s['steps']} steps")
    rows = table(result / "snapshots.dat")
    n, dt, velocity, height = s["particles"], s["dt"], 0.1, 0.5
    check(n == 3 * 2 * 2 and len(rows) == 2 * n, f"punch: {n} particles, {len(rows)} snapshot rows")
    snapshot_strains = sorted({r["strain"] for r in rows})
    for k, frame in enumerate(series):
        t, particles, _ = frame["particles"]
        _, walls, _ = frame["walls"]
        check(close(t, k * dt, 1e-9), f"punch frame {k}: time {t}, expected {k} dt")
        check(field(particles, "step") == k, f"punch frame {k}: step {field(particles, 'step')}")
        check(close(field(particles, "strain"), velocity * t / height, 1e-12), f"punch frame {k}: strain")
        check_vsm_particles(particles, f"punch frame {k}", n, 1.0 * 0.5 * 0.1)
        # The walls: the five symmetric faces (kind 2) and the punch (label 6, kind 1) at y = 0.5 - v t.
        labels, kinds = cell_values(walls, "face_label"), cell_values(walls, "boundary_kind")
        check(walls.GetNumberOfPolys() == 6 and sorted(kinds) == [1, 2, 2, 2, 2, 2],
              f"punch frame {k}: walls {labels} of kinds {kinds}")
        punch = labels.index(6) if 6 in labels else None
        if punch is not None:
            ys = {round(walls.GetPoint(walls.GetCell(punch).GetPointId(c))[1], 14) for c in range(4)}
            check(len(ys) == 1 and close(ys.pop(), height - velocity * t, 1e-12),
                  f"punch frame {k}: the punch is not at y = 0.5 - v t")
    # The state at each snapshot: the first step with t + dt/2 >= strain height / v.
    for strain in snapshot_strains:
        k = next(k for k in range(len(series)) if series[k]["particles"][0] + 0.5 * dt >= strain * height / velocity)
        data = series[k]["particles"][1]
        expected = [r for r in rows if r["strain"] == strain]
        pressure = point_tuples(data, "pressure")
        scale = max(abs(r["pressure"]) for r in expected)
        for a, r in enumerate(expected):
            x = data.GetPoint(a)
            check(all(abs(x[i] - r[f"x{i + 1}"]) <= 1e-10 for i in range(3)),
                  f"punch strain {strain}: particle {a} at {x}, table {r}")
            check(abs(pressure[a][0] - r["pressure"]) <= 1e-10 * scale,
                  f"punch strain {strain}: particle {a} pressure {pressure[a][0]}, table {r['pressure']}")
    print(f"vsm.punch: {len(series)} frames, snapshots at frames of strain {snapshot_strains} match")

    out = work / "cube"
    run(softgrain, out, "vsm.swinging_cube", "--vtk", "--set", "per_side=3", "end_time=1e-3")
    result = out / "vsm.swinging_cube"
    s = summary(result)
    series = read_series(result, "vsm.swinging_cube")
    check(len(series) == s["steps"] + 1, f"cube: {len(series)} frames for {s['steps']} steps")
    for k, frame in enumerate(series):
        t, particles, _ = frame["particles"]
        check(close(t, k * s["dt"], 1e-9), f"cube frame {k}: time {t}")
        check_vsm_particles(particles, f"cube frame {k}", 27, 1.0)
        check(close(field(particles, "cos_omega_t"), math.cos(s["omega"] * t), 1e-12), f"cube frame {k}: cos")
        _, walls, _ = frame["walls"]
        kinds = cell_values(walls, "boundary_kind")
        check(sorted(kinds) == [2, 2, 2, 3, 3, 3], f"cube frame {k}: wall kinds {kinds}")
    # The last frame is the final state: its displacements against the summary's error need the exact field;
    # the first frame's displacement is the initial one of eq. (53), not zero.
    first = point_tuples(series[0]["particles"][1], "displacement")
    check(max(abs(c) for d in first for c in d) > 1e-5, "cube frame 0: no initial displacement")

    out = work / "lblock"
    run(softgrain, out, "vsm.lblock", "--vtk", "--vtk-every", "20", "--set", "spacing=1", "end_time=6")
    result = out / "vsm.lblock"
    s = summary(result)
    series = read_series(result, "vsm.lblock")
    check(len(series) == s["steps"] // 20 + 1, f"lblock: {len(series)} frames for {s['steps']} steps every 20")
    rows = table(result / "momentum.dat")
    for k, frame in enumerate(series):
        t, particles, _ = frame["particles"]
        check(set(frame) == {"particles"}, f"lblock frame {k}: parts {sorted(frame)} (a free block: no walls)")
        check(close(t, 20 * k * s["dt"], 1e-9), f"lblock frame {k}: time {t}")
        check_vsm_particles(particles, f"lblock frame {k}", s["particles"], 117.0)
        check(close(field(particles, "traction_pulse"), max(2.5 - abs(t - 2.5), 0.0), 1e-12),
              f"lblock frame {k}: traction_pulse")
    # Linear momentum sum m v from the frames' half-step velocities and the Voronoi volumes (m = rho V)
    # against momentum.dat at the same times (rho = 1000 kg/m^3).
    by_time = {round(r["t"], 9): r for r in rows}
    matched = 0
    for frame in series:
        t, data, _ = frame["particles"]
        r = by_time.get(round(t, 9))
        if r is None:
            continue
        v, V = point_tuples(data, "velocity"), point_tuples(data, "voronoi_volume")
        p = [sum(1000 * V[a][0] * v[a][i] for a in range(len(v))) for i in range(3)]
        scale = max(abs(r["p1"]), abs(r["p2"]), abs(r["p3"]), 1e-300)
        check(all(abs(p[i] - r[f"p{i + 1}"]) <= 1e-9 * scale for i in range(3)),
              f"lblock t = {t}: momentum {p} against {r}")
        matched += 1
    check(matched >= 2, f"lblock: only {matched} frames at the times of momentum.dat")
    print(f"vsm.swinging_cube and vsm.lblock: frames read back; lblock momentum matched at {matched} times")


def check_sd(softgrain, work):
    """sd.many on a line and in the triangle cluster: a frame per output sample, gaps and velocities against
    many.dat."""
    for geometry, n in (("line", 4), ("cluster", 3)):
        out = work / f"sd-{geometry}"
        run(softgrain, out, "sd.many", "--vtk", "--set", f"geometry={geometry}", f"particles={n}", "outputs=8")
        result = out / "sd.many"
        rows = table(result / "many.dat")
        series = read_series(result, "sd.many")
        s = summary(result)
        bonds = s["bonds"]
        dim = 1 if geometry == "line" else 2
        force = 1e-3
        check(len(series) == len(rows) and len(rows) > 2, f"sd {geometry}: {len(series)} frames, {len(rows)} rows")
        for k, (frame, row) in enumerate(zip(series, rows)):
            t, particles, _ = frame["particles"]
            _, pairs, _ = frame["pairs"]
            check(close(t, row["t"], 1e-10), f"sd {geometry} frame {k}: time {t} against t = {row['t']}")
            check(particles.GetNumberOfVerts() == n and pairs.GetNumberOfVerts() == bonds,
                  f"sd {geometry} frame {k}: {particles.GetNumberOfVerts()} particles, "
                  f"{pairs.GetNumberOfVerts()} pairs")
            gaps = point_tuples(pairs, "gap")
            check(all(close(gaps[b][0], row[f"h_{b}"], 1e-10) for b in range(bonds)), f"sd {geometry} frame {k}: gaps")
            check(close(field(particles, "gap_min"), min(g[0] for g in gaps), 1e-15),
                  f"sd {geometry} frame {k}: gap_min")
            v = point_tuples(particles, "velocity")
            scale = max(abs(row[f"v_{i}x"]) for i in range(n)) * force
            for i in range(n):
                for c, axis in enumerate("xy"[:dim]):
                    check(abs(v[i][c] - row[f"v_{i}{axis}"] * force) <= 1e-9 * max(scale, 1e-300),
                          f"sd {geometry} frame {k}: velocity of {i}")
            radius = point_tuples(particles, "radius")
            forces, deflection = point_tuples(pairs, "force"), point_tuples(pairs, "deflection")
            # Eq. (2): |X_ij| = 2R + h - 2 delta, from the centres in the frame.
            i_ids, j_ids = cell_values(pairs, "particle_i"), cell_values(pairs, "particle_j")
            for b in range(bonds):
                xi, xj = particles.GetPoint(int(i_ids[b])), particles.GetPoint(int(j_ids[b]))
                distance = math.dist(xi, xj)
                check(close(distance, 2 * radius[0][0] + gaps[b][0] - 2 * deflection[b][0], 1e-9),
                      f"sd {geometry} frame {k} bond {b}: |X| {distance} against 2R + h - 2 delta")
                check(forces[b][0] > 0, f"sd {geometry} frame {k} bond {b}: pair force {forces[b][0]}")
    print("sd.many: frames of the line and the cluster match many.dat")


def relatively_close(a, b, tol):
    """|a - b| <= tol max(|a|, |b|): for values far below 1, which close() compares absolutely."""
    return abs(a - b) <= tol * max(abs(a), abs(b))


def check_beam(softgrain, work):
    """spd.beam, cantilever and simply supported: frames along the damped relaxation (every 100th force check
    here, 1600 steps) and the relaxed state, whose nodes are profile.dat's and whose largest deflection is
    the discrete hinge chain's exact small-load result."""
    every = 100
    for support in ("cantilever", "simple"):
        out = work / f"beam-{support}"
        nodes, length = 11, 1.0
        run(softgrain, out, "spd.beam", "--vtk", "--vtk-every", str(every), "--set", f"nodes={nodes}",
            f"support={support}")
        result = out / "spd.beam"
        s = summary(result)
        rows = table(result / "profile.dat")
        series = read_series(result, "spd.beam")
        # Opportunities: step 0 and each unsuccessful check (every 16 steps) before the converged one.
        checks = s["steps"] // 16
        expected = (checks + every - 1) // every + 1
        check(len(series) == expected == s.get("vtk_frames"),
              f"beam {support}: {len(series)} frames, expected {expected} for {s['steps']} steps")
        ghost = 1 if support == "cantilever" else 0  # the clamp's frozen node at x = -l, drawn first
        for k, frame in enumerate(series):
            t, beam, _ = frame["beam"]
            last = k == len(series) - 1
            check(close(t, s["steps"] if last else 16 * every * k), f"beam {support} frame {k}: time {t}")
            check(field(beam, "relaxed") == (1 if last else 0) and field(beam, "step") == t,
                  f"beam {support} frame {k}: field data relaxed/step")
            check(beam.GetNumberOfPoints() == nodes + ghost and beam.GetNumberOfLines() == 1,
                  f"beam {support} frame {k}: {beam.GetNumberOfPoints()} points, {beam.GetNumberOfLines()} lines")
        # The load is applied to the straight beam at step 0.
        first = series[0]["beam"][1]
        check(all(first.GetPoint(i)[1] == 0 for i in range(first.GetNumberOfPoints())),
              f"beam {support}: frame 0 not straight")
        # The relaxed state: each node at (x, -delta) of profile.dat (12 significant digits there).
        relaxed = series[-1]["beam"][1]
        for i, row in enumerate(rows):
            x, y, _ = relaxed.GetPoint(ghost + i)
            check(abs(x - row["x_over_L"] * length) <= 1e-11 and abs(-y - row["delta"]) <= 1e-11 * abs(row["delta"]),
                  f"beam {support} node {i}: ({x}, {y}) against profile.dat ({row['x_over_L']}, {row['delta']})")
        # The largest deflection against the small-load discrete chain (cantilever (n+1)(2n+1)/(2n^2), simply
        # supported 1 + 2/n^2 times F L^3/(3 EI) or F L^3/(48 EI)); 1e-4: the relaxation residual 1e-6 F leaves
        # < 5e-5 (lib/spd/beam.hpp), the geometric nonlinearity (delta/L)^2 < 1e-8.
        deepest = max(-relaxed.GetPoint(i)[1] for i in range(relaxed.GetNumberOfPoints()))
        ratio = deepest / s["deflection_max_theory"]
        check(abs(ratio / s["ratio_discrete_theory"] - 1) <= 1e-4,
              f"beam {support}: deflection {deepest} is {ratio} x theory, discrete chain {s['ratio_discrete_theory']}")
    print("spd.beam: relaxation frames read back; the relaxed nodes equal profile.dat")


def check_ring_pressure(softgrain, work):
    """spd.ring_pressure with a compressible core: the relaxed ring without and with its core, area ratios
    against the summary's moduli and the theory's K_shell (eq. (21)) and K_e (eq. (25))."""
    out = work / "ring-pressure"
    pressure, eta = 0.05, 2e4
    run(softgrain, out, "spd.ring_pressure", "--vtk", "--set", "nodes=32", f"eta={eta}", f"pressure={pressure}")
    result = out / "spd.ring_pressure"
    s = summary(result)
    series = read_series(result, "spd.ring_pressure")
    check(len(series) == 2 == s.get("vtk_frames"), f"ring_pressure: {len(series)} frames, expected 2")
    for k, (frame, measured, theory) in enumerate(zip(series, ("K_shell", "K_effective"),
                                                       ("K_shell_theory", "K_effective_theory"))):
        t, particles, _ = frame["particles"]
        check(t == k and field(particles, "state") == k, f"ring_pressure frame {k}: time {t}")
        check(field(particles, "pressure") == pressure and field(particles, "eta") == (0 if k == 0 else eta),
              f"ring_pressure frame {k}: field data pressure, eta")
        check(particles.GetNumberOfPolys() == 1 and particles.GetNumberOfPoints() == 32,
              f"ring_pressure frame {k}: {particles.GetNumberOfPolys()} polygons")
        strain = cell_values(particles, "area_ratio")[0] - 1
        check(close(pressure / strain, s[measured], 1e-9),
              f"ring_pressure frame {k}: p/(A/A0 - 1) = {pressure / strain} against {measured} {s[measured]}")
        # Against the theory: 1e-5, the relaxation tolerance (1e-5 p s l0 on each vertex).
        check(abs(pressure / strain / s[theory] - 1) <= 1e-5,
              f"ring_pressure frame {k}: p/(A/A0 - 1) = {pressure / strain} against {theory} {s[theory]}")
        # The uniform pressure excites only the breathing mode: the vertices stay on a circle.
        points = [particles.GetPoint(i) for i in range(32)]
        cx, cy = sum(p[0] for p in points) / 32, sum(p[1] for p in points) / 32
        radii = [math.hypot(p[0] - cx, p[1] - cy) for p in points]
        check(max(radii) - min(radii) <= 1e-9 * max(radii), f"ring_pressure frame {k}: not a circle")
    core = cell_values(series[0]["particles"][1], "core_pressure")[0]
    check(core == 0, f"ring_pressure frame 0: core pressure {core} without a core")
    print("spd.ring_pressure: the two relaxed rings match K_shell and K_e")


def check_approach(softgrain, work):
    """sd.approach (every 4th row here): the two spheres and their pair against approach.dat, eq. (2) and
    the force balance eq. (1)."""
    out = work / "approach"
    kappa, every = 1e-4, 4
    run(softgrain, out, "sd.approach", "--vtk", "--vtk-every", str(every), "--set", f"kappa={kappa}")
    result = out / "sd.approach"
    rows = table(result / "approach.dat")
    series = read_series(result, "sd.approach")
    check(len(series) == (len(rows) + every - 1) // every == summary(result).get("vtk_frames"),
          f"approach: {len(series)} frames for {len(rows)} rows every {every}")
    # approach.dat has 12 significant digits: 1e-10 relative (h goes down to 1e-6 R).
    same = lambda a, b: relatively_close(a, b, 1e-10)  # noqa: E731
    for k, frame in enumerate(series):
        row = rows[every * k]
        t, particles, _ = frame["particles"]
        _, pairs, _ = frame["pairs"]
        label = f"approach frame {k}"
        check(same(t, row["t"]) and same(field(particles, "time") * kappa, row["t"]), f"{label}: time {t}")
        check(particles.GetNumberOfVerts() == 2 and pairs.GetNumberOfVerts() == 1, f"{label}: counts")
        x0, x1 = particles.GetPoint(0), particles.GetPoint(1)
        check(same(x1[0] - x0[0], row["X"]) and x0[0] == -x1[0] and x0[1] == x1[1] == 0,
              f"{label}: centres {x0}, {x1} against X = {row['X']}")
        h, delta = point_tuples(pairs, "gap")[0][0], point_tuples(pairs, "deflection")[0][0]
        check(same(h, row["h"]) and same(delta, row["delta"]) and same(field(particles, "gap_min"), h),
              f"{label}: gap {h}, deflection {delta} against {row['h']}, {row['delta']}")
        # Eq. (2), R = 1: X = 2R + h - 2 delta.
        check(close(x1[0] - x0[0], 2 + h - 2 * delta, 1e-12), f"{label}: eq. (2)")
        v = point_tuples(particles, "velocity")
        check(same((v[1][0] - v[0][0]) / kappa, row["X_dot"]) and same(point_tuples(pairs, "gap_rate")[0][0] / kappa,
                                                                        row["h_dot"]),
              f"{label}: velocities {v} against X-dot = {row['X_dot']} V")
        # Eq. (1): F_ela balances F_ext = kappa E R^2, to the table's residual (12 digits there; the frame's
        # F_ela/F_ext - 1 is known to a few ulp, 1e-15).
        force = point_tuples(pairs, "force")[0][0]
        residual = row["force_balance_residual"]
        check(abs(abs(force / kappa - 1) - residual) <= 1e-10 * residual + 1e-15,
              f"{label}: |F_ela/F_ext - 1| = {abs(force / kappa - 1)}, table {row['force_balance_residual']}")
        pushed = point_tuples(particles, "external_force")
        check(pushed[0][0] == kappa and pushed[1][0] == -kappa, f"{label}: external forces {pushed}")
    print(f"sd.approach: {len(series)} frames match approach.dat")


def check_refusal_reasons(softgrain, work):
    """Scenes without frames by design say why: the timed benches, core.harmonic, sd.phase_diagram."""
    for scene, words in (("spd.bench", ["timed scene"]), ("dpm.bench", ["timed scene"]),
                         ("core.harmonic", ["no particle"]), ("sd.phase_diagram", ["not a time series"])):
        done, _ = run(softgrain, work / "refused-reason", scene, "--vtk", expect=2)
        check(all(w in done.stderr for w in ["--vtk", scene, "allowed for", *words]),
              f"{scene} --vtk: message {done.stderr.strip()!r} lacks {words}")


def check_patch(softgrain, work):
    """vsm.patch: test A's one state and B, C along their ramp and hold (every 2000th step here) and their final
    state: the displacement against the linear field u = r alpha M X of eq. (52), the walls moved by it."""
    alpha = 1e-4
    G = [[alpha * (3 * i + j + 1) for j in range(3)] for i in range(3)]  # alpha M, M = [1 2 3; 4 5 6; 7 8 9]
    linear = lambda X, r: [r * sum(G[i][j] * X[j] for j in range(3)) for i in range(3)]  # noqa: E731
    every, ramp = 2000, 5.0
    for test in ("A", "B", "C"):
        out = work / f"patch-{test}"
        run(softgrain, out, "vsm.patch", "--vtk", "--vtk-every", str(every), "--set", f"test={test}",
            f"ramp_time={ramp}", "hold_time=5")
        result = out / "vsm.patch"
        s = summary(result)
        X = [(r["X1"], r["X2"], r["X3"]) for r in table(result / "particles.dat")]
        series = read_series(result, "vsm.patch")
        n = s["particles"]
        steps = s["steps"]
        # B, C: the steps 0, every, 2 every, ... and the final one.
        expected = 1 if test == "A" else steps // every + 1 + (steps % every != 0)
        check(len(series) == expected == s.get("vtk_frames"),
              f"patch {test}: {len(series)} frames, expected {expected}")
        u_max = math.sqrt(sum(sum(G[i]) ** 2 for i in range(3)))  # the largest exact displacement, X = (1, 1, 1)
        for k, frame in enumerate(series):
            t, particles, _ = frame["particles"]
            _, walls, _ = frame["walls"]
            label = f"patch {test} frame {k}"
            final = k == len(series) - 1
            step = steps if final and test != "A" else every * k
            load = 1.0 if test == "A" else min(t / ramp, 1.0)
            check(field(particles, "step") == step and close(t, step * (s["dt"] or 0), 1e-12),
                  f"{label}: time {t}, step {field(particles, 'step')}, expected {step}")
            check(field(particles, "test") == s["test_id"] and close(field(particles, "load"), load, 1e-12),
                  f"{label}: field data test {field(particles, 'test')}, load {field(particles, 'load')}")
            check_vsm_particles(particles, label, n, 1.0)
            # Reference positions: x - u equals particles.dat (12 digits there).
            u = point_tuples(particles, "displacement")
            check(all(abs(particles.GetPoint(a)[i] - u[a][i] - X[a][i]) <= 1e-11 for a in range(n) for i in range(3)),
                  f"{label}: x - displacement differs from particles.dat")
            # The walls: total displacement on every face (A, B) or on X3 = 0 only (C), each corner W at
            # W + r alpha M W.
            kinds, labels = cell_values(walls, "boundary_kind"), cell_values(walls, "face_label")
            check(kinds == [1] * (1 if test == "C" else 6) and (test != "C" or labels == [4]),
                  f"{label}: walls {labels} of kinds {kinds}")
            for c in range(walls.GetNumberOfPolys()):
                cell = walls.GetCell(c)
                for q in range(4):
                    w = walls.GetPoint(cell.GetPointId(q))
                    W = [round(coordinate) for coordinate in w]  # the unit cube's corners
                    moved = linear(W, load)
                    check(all(abs(w[i] - W[i] - moved[i]) <= 1e-15 for i in range(3)),
                          f"{label}: wall {labels[c]} corner {w} not at W + r alpha M W")
            if not final:
                continue
            # The final state against eq. (52): A exact (the positions it sets), B and C within their error.
            deviation = max(math.dist([u[a][i] for i in range(3)], linear(X[a], 1.0)) for a in range(n))
            allowed = 1e-12 * u_max + (0 if test == "A" else s["max_error"])
            check(deviation <= allowed, f"{label}: displacement {deviation} m from alpha M X, allowed {allowed}")
            # A's deformation gradient is the exact I + alpha M (eq. (6) reproduces linear fields).
            if test == "A":
                F = point_tuples(particles, "deformation_gradient")
                check(all(abs(F[a][3 * i + j] - (i == j) - G[i][j]) <= 1e-12 for a in range(n)
                          for i in range(3) for j in range(3)), f"{label}: F is not I + alpha M")
    print("vsm.patch: tests A, B, C frames follow the linear field of eq. (52)")


def check_compare_ring(softgrain, work):
    """compare.ring by SPD and by DPM: a frame per recorded strain (eps = 0 and each row of ring.dat), the
    ring's width and area ratio against the table, and its plate force from the frame against F R^2/B."""
    nodes, h, E, nu, R = 32, 0.02, 1e6, 0.3, 1.0
    l0 = 2 * R * math.sin(math.pi / nodes)
    B = E * h ** 3 / (12 * (1 - nu ** 2)) * l0  # k_b l0, SPD eqs. (10)-(11) (decision compare-ring-mapping)
    for model in ("spd", "dpm"):
        out = work / f"compare-ring-{model}"
        run(softgrain, out, "compare.ring", "--vtk", "--set", f"model={model}", f"nodes={nodes}", f"h_over_R={h}",
            "strain_max=0.2", "strain_step=0.05")
        result = out / "compare.ring"
        rows = table(result / "ring.dat")
        series = read_series(result, "compare.ring")
        check(len(series) == len(rows) + 1 == summary(result).get("vtk_frames"),
              f"compare.ring {model}: {len(series)} frames for {len(rows)} rows and eps = 0")
        check(set(series[0]) == ({"particles", "walls", "contacts"} if model == "spd" else {"particles", "plates"}),
              f"compare.ring {model}: parts {sorted(series[0])}")
        for k, frame in enumerate(series):
            t, particles, _ = frame["particles"]
            label = f"compare.ring {model} frame {k}"
            row = rows[k - 1] if k > 0 else {"eps": 0.0, "F_R2_over_B": None, "a_over_b0": 1.0, "V_over_V0": 1.0}
            check(close(t, row["eps"], 1e-10) and close(field(particles, "strain"), row["eps"], 1e-10),
                  f"{label}: time {t} against eps {row['eps']}")
            check(particles.GetNumberOfPolys() == 1 and particles.GetNumberOfPoints() == nodes, f"{label}: counts")
            xs = [particles.GetPoint(i)[0] for i in range(nodes)]
            # ring.dat has 12 significant digits: 1e-10 relative.
            check(close((max(xs) - min(xs)) / (2 * R), row["a_over_b0"], 1e-10),
                  f"{label}: width {(max(xs) - min(xs)) / (2 * R)} against a/b0 {row['a_over_b0']}")
            check(close(cell_values(particles, "area_ratio")[0], row["V_over_V0"], 1e-10),
                  f"{label}: area ratio {cell_values(particles, 'area_ratio')[0]} against V/V0 {row['V_over_V0']}")
            if k == 0:
                continue
            check(close(field(particles, "F_R2_over_B"), row["F_R2_over_B"], 1e-10), f"{label}: field F R^2/B")
            if model == "spd":
                # The top wall's force from the contact lines (as in check_ring).
                _, walls, _ = frame["walls"]
                _, contacts, _ = frame["contacts"]
                top = cell_values(walls, "wall_id")[1]
                mine, other = cell_values(contacts, "particle") or [], cell_values(contacts, "other_particle") or []
                f = contacts.GetCellData().GetArray("force")
                force = sum((-1 if other[c] == top else 1 if mine[c] == top else 0) * f.GetTuple3(c)[1]
                            for c in range(contacts.GetNumberOfLines()))
                check(close(force * R ** 2 / B, row["F_R2_over_B"], 1e-9),
                      f"{label}: top-wall force {force * R ** 2 / B} B/R^2 against {row['F_R2_over_B']}")
            else:
                # The top plate at D - delta = 2R + h - eps b0; the body's vertex forces where it touches
                # balance F, to FIRE's tolerance: its rms force below 1e-5 B/R^2 / sqrt(2N) bounds the sum over
                # k touching vertices by sqrt(k) 1e-5 B/R^2 (Cauchy-Schwarz).
                _, plates, _ = frame["plates"]
                top = max(plates.GetPoint(i)[1] for i in range(plates.GetNumberOfPoints()))
                check(close(top, 2 * R + h - row["eps"] * 2 * R, 1e-12), f"{label}: top plate at {top}")
                fy = point_tuples(particles, "force")
                touching = [i for i in range(nodes) if top - particles.GetPoint(i)[1] < h / 2]
                pushed = sum(fy[i][1] for i in touching)
                check(abs(pushed * R ** 2 / B - row["F_R2_over_B"]) <= math.sqrt(len(touching)) * 1e-5,
                      f"{label}: body force at the top plate {pushed * R ** 2 / B} B/R^2, F {row['F_R2_over_B']}")
    print("compare.ring: SPD and DPM frames match ring.dat")


def mesh_volumes(data):
    """The volume each particle's closed triangle mesh encloses (divergence theorem), by particle_id."""
    ids = cell_values(data, "particle_id")
    volumes = {}
    for c in range(data.GetNumberOfPolys()):
        cell = data.GetCell(c)
        a, b, d = (data.GetPoint(cell.GetPointId(q)) for q in range(3))
        triple = (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
                  + a[2] * (b[0] * d[1] - b[1] * d[0]))
        volumes[int(ids[c])] = volumes.get(int(ids[c]), 0.0) + triple / 6
    return volumes


def check_shape3d(softgrain, work):
    """dpm.shape3d: the mesh's one frame against faces.dat (face areas), the summary's counts (Euler), volume
    and A^3D, and the unit sphere."""
    out = work / "shape3d"
    run(softgrain, out, "dpm.shape3d", "--vtk", "--set", "mesh=geodesic42")
    result = out / "dpm.shape3d"
    s = summary(result)
    areas = [r["area"] for r in table(result / "faces.dat")]
    series = read_series(result, "dpm.shape3d")
    if not check(len(series) == 1 == s.get("vtk_frames"), f"shape3d: {len(series)} frames, expected 1"):
        return
    t, mesh, _ = series[0]["particles"]
    check(t == 0, f"shape3d: time {t}")
    check(mesh.GetNumberOfPoints() == s["vertices"] and mesh.GetNumberOfPolys() == s["faces"],
          f"shape3d: {mesh.GetNumberOfPoints()} points, {mesh.GetNumberOfPolys()} faces")
    edges = {tuple(sorted((mesh.GetCell(c).GetPointId(q), mesh.GetCell(c).GetPointId((q + 1) % 3))))
             for c in range(mesh.GetNumberOfPolys()) for q in range(3)}
    check(len(edges) == s["edges"] and mesh.GetNumberOfPoints() - len(edges) + mesh.GetNumberOfPolys() == 2,
          f"shape3d: {len(edges)} edges, Euler characteristic not 2")
    check(all(abs(math.dist(mesh.GetPoint(i), (0, 0, 0)) - 1) <= 1e-12 for i in range(mesh.GetNumberOfPoints())),
          "shape3d: vertices not on the unit sphere")
    written = cell_values(mesh, "face_area")
    for c in range(mesh.GetNumberOfPolys()):
        cell = mesh.GetCell(c)
        a, b, d = (mesh.GetPoint(cell.GetPointId(q)) for q in range(3))
        u, v = [b[i] - a[i] for i in range(3)], [d[i] - a[i] for i in range(3)]
        area = 0.5 * math.sqrt((u[1] * v[2] - u[2] * v[1]) ** 2 + (u[2] * v[0] - u[0] * v[2]) ** 2
                               + (u[0] * v[1] - u[1] * v[0]) ** 2)
        # faces.dat has 12 significant digits: 1e-10 relative.
        check(close(area, areas[c], 1e-10) and close(written[c], areas[c], 1e-10),
              f"shape3d face {c}: area {area} (face_area {written[c]}) against faces.dat {areas[c]}")
    volume = mesh_volumes(mesh)[0]
    check(close(volume, s["volume"], 1e-12) and close(field(mesh, "volume"), s["volume"], 1e-15),
          f"shape3d: enclosed volume {volume} against {s['volume']}")
    area_sum = sum(areas)
    A = area_sum ** 1.5 / (6 * math.sqrt(math.pi) * volume)  # A^3D = s^(3/2)/(6 sqrt(pi) v), sec. 9.3.1
    check(close(A, s["shape_parameter_min"], 1e-10) and close(field(mesh, "shape_parameter"), A, 1e-10),
          f"shape3d: A^3D {A} from the frame against {s['shape_parameter_min']}")
    print("dpm.shape3d: the mesh frame matches faces.dat and the summary")


def check_slide3d(softgrain, work):
    """dpm.slide3d (every 3rd of 21 positions here): the slider along the path of path.dat at its height, the
    slab fixed, and the smooth force on the slider from the frame's vertex forces against mu_smooth."""
    out = work / "slide3d"
    every, gap, sigma = 3, 0.5, 1.0  # every 3rd: positions off the symmetry points where F_x = 0
    run(softgrain, out, "dpm.slide3d", "--vtk", "--vtk-every", str(every), "--set", "steps=20", f"gap={gap}")
    result = out / "dpm.slide3d"
    s = summary(result)
    rows = table(result / "path.dat")
    series = read_series(result, "dpm.slide3d")
    check(len(series) == (len(rows) + every - 1) // every == s.get("vtk_frames"),
          f"slide3d: {len(series)} frames for {len(rows)} positions every {every}")
    slab, slider = s["slab_vertices"], s["slider_vertices"]
    slab_points = None
    for k, frame in enumerate(series):
        row = rows[every * k]
        t, data, _ = frame["particles"]
        label = f"slide3d frame {k}"
        check(close(t, row["x"], 1e-10) and close(field(data, "x"), row["x"], 1e-10), f"{label}: time {t}")
        check(data.GetNumberOfPoints() == slab + slider, f"{label}: {data.GetNumberOfPoints()} points")
        # path.dat has 12 significant digits: 1e-10 relative, and 1e-13 absolute for F_x/F_z (F_x is round-off,
        # 1e-17, at the symmetry points).
        for name in ("U_rough", "U_smooth", "mu_rough", "mu_smooth"):
            check(abs(field(data, name) - row[name]) <= 1e-10 * abs(row[name]) + 1e-13,
                  f"{label}: {name} {field(data, name)} against {row[name]}")
        points = [data.GetPoint(i) for i in range(slab + slider)]
        slab_points = slab_points or points[:slab]
        check(points[:slab] == slab_points, f"{label}: the slab moved")
        # The slider (vertex 0 down, a centrally symmetric mesh): centre at x, lowest vertex gap above the
        # slab's top face z = sigma.
        centre = [sum(p[c] for p in points[slab:]) / slider for c in range(3)]
        check(close(centre[0], row["x"], 1e-10), f"{label}: slider centre {centre} against x {row['x']}")
        check(close(min(p[2] for p in points[slab:]), sigma + gap, 1e-12), f"{label}: slider height")
        f = point_tuples(data, "force")
        fx, fz = sum(f[i][0] for i in range(slab, slab + slider)), sum(f[i][2] for i in range(slab, slab + slider))
        check(fz > 0 and abs(fx / fz - row["mu_smooth"]) <= 1e-10 * abs(row["mu_smooth"]) + 1e-13,
              f"{label}: F_x/F_z on the slider {fx / fz} against mu_smooth {row['mu_smooth']}")
    print(f"dpm.slide3d: {len(series)} frames match path.dat")


def check_shear_modulus3d(softgrain, work):
    """dpm.shear_modulus3d, two packings: frames of the first packing only, one per pressure state, with
    pressure, phi and G of modulus_shell.dat's packing 0 and phi recomputed from the meshes and the box."""
    out = work / "shear-modulus3d"
    run(softgrain, out, "dpm.shear_modulus3d", "--vtk", "--set", "model=shell", "mesh=icosahedron",
        "particles=2", "packings=2", "pressures=2")
    result = out / "dpm.shear_modulus3d"
    rows = [r for r in table(result / "modulus_shell.dat") if r["packing"] == 0]
    series = read_series(result, "dpm.shear_modulus3d")
    check(len(series) == len(rows) == 3 == summary(result).get("vtk_frames"),
          f"shear_modulus3d: {len(series)} frames for {len(rows)} states of packing 0")
    for k, (frame, row) in enumerate(zip(series, rows)):
        t, data, _ = frame["particles"]
        _, box, _ = frame["box"]
        label = f"shear_modulus3d frame {k}"
        check(t == k, f"{label}: time {t}")
        # modulus_shell.dat has 12 significant digits: 1e-10 relative (P_t = 1e-5).
        for name, column in (("pressure", "P"), ("phi", "phi"), ("G", "G")):
            check(relatively_close(field(data, name), row[column], 1e-10),
                  f"{label}: {name} {field(data, name)} against {row[column]}")
        check(data.GetNumberOfPoints() == 2 * 12 and data.GetNumberOfPolys() == 2 * 20 and box.GetNumberOfLines() == 12,
              f"{label}: counts")
        L = max(box.GetPoint(i)[0] for i in range(box.GetNumberOfPoints()))
        phi = sum(mesh_volumes(data).values()) / L ** 3
        check(close(phi, row["phi"], 1e-10), f"{label}: phi from the meshes {phi} against {row['phi']}")
        for p in range(2):
            centre = [sum(data.GetPoint(12 * p + v)[c] for v in range(12)) / 12 for c in range(3)]
            check(all(0 <= c < L for c in centre), f"{label}: particle {p} centre {centre} outside [0, {L})")
    print("dpm.shear_modulus3d: the first packing's frames match modulus_shell.dat")


def check_dpm3d(softgrain, work):
    """dpm.compress3d (tetrahedra, shell, spring network) and dpm.modes3d's jammed packing."""
    for model, extra, points, polys in (("tetrahedra", ["mesh=geodesic42"], 42, 80),
                                        ("shell", ["mesh=geodesic42"], 42, 80),
                                        ("spring_network", ["network_nodes=60"], None, 0)):
        out = work / f"compress3d-{model}"
        run(softgrain, out, "dpm.compress3d", "--vtk", "--set", f"model={model}", "steps=4", "delta_max=0.05",
            *extra)
        result = out / "dpm.compress3d"
        rows = table(result / "force.dat")
        series = read_series(result, "dpm.compress3d")
        s = summary(result)
        check(len(series) == len(rows) == 4, f"compress3d {model}: {len(series)} frames for {len(rows)} rows")
        for k, (frame, row) in enumerate(zip(series, rows)):
            t, body, _ = frame["particles"]
            _, plates, _ = frame["plates"]
            check(close(t, row["delta"], 1e-10), f"compress3d {model} frame {k}: time {t}")
            check(close(field(body, "force"), row["F"], 1e-10), f"compress3d {model} frame {k}: force")
            check(plates.GetNumberOfPolys() == 2 and cell_values(plates, "plate_id") == [0, 1],
                  f"compress3d {model} frame {k}: plates")
            top = max(plates.GetPoint(i)[2] for i in range(plates.GetNumberOfPoints()))
            zmax = max(body.GetPoint(i)[2] for i in range(body.GetNumberOfPoints()))
            # The top plate overlaps the highest vertex's disk (radius 1/2) exactly when the table counts contacts.
            check(zmax < top and (top < zmax + 0.5) == (row["contacts"] > 0),
                  f"compress3d {model} frame {k}: top plate at {top}, body up to {zmax}, {row['contacts']} contacts")
            if points is not None:
                check(body.GetNumberOfPoints() == points and body.GetNumberOfPolys() == polys,
                      f"compress3d {model} frame {k}: {body.GetNumberOfPoints()} points, "
                      f"{body.GetNumberOfPolys()} faces")
                ratio = cell_values(body, "volume_ratio")
                check(len(set(ratio)) == 1 and 0.5 < ratio[0] < 1 + 1e-6,
                      f"compress3d {model} frame {k}: volume ratios {set(ratio)}")
                check(set(cell_values(body, "particle_id")) == {0}, f"compress3d {model} frame {k}: ids")
                # The force on the vertices from the body's energy balances the plates': its z sum over the
                # vertices touching the top plate is -F (the relaxed state), within the FIRE tolerance.
                f = point_tuples(body, "force")
                pushed = sum(f[i][2] for i in range(body.GetNumberOfPoints()) if body.GetPoint(i)[2] > top - 0.5)
                check(abs(pushed - row["F"]) <= 1e-6 * max(1.0, row["F"]),
                      f"compress3d {model} frame {k}: body force at the top {pushed} against F = {row['F']}")
            else:
                check(body.GetNumberOfVerts() == s["vertices"] and body.GetNumberOfLines() == s["network_springs"],
                      f"compress3d network frame {k}: {body.GetNumberOfVerts()} nodes, "
                      f"{body.GetNumberOfLines()} springs")

    out = work / "modes3d"
    run(softgrain, out, "dpm.modes3d", "--vtk", "--set", "particles=4", "mesh=icosahedron", "model=shell")
    result = out / "dpm.modes3d"
    s = summary(result)
    series = read_series(result, "dpm.modes3d")
    check(len(series) == 1, f"modes3d packing: {len(series)} frames (one pressure state)")
    for k, frame in enumerate(series):
        _, data, _ = frame["particles"]
        _, box, _ = frame["box"]
        check(data.GetNumberOfPoints() == 4 * 12 and data.GetNumberOfPolys() == 4 * 20,
              f"modes3d frame {k}: {data.GetNumberOfPoints()} points, {data.GetNumberOfPolys()} faces")
        check(box.GetNumberOfLines() == 12, f"modes3d frame {k}: box edges {box.GetNumberOfLines()}")
        check(close(field(data, "phi"), s["phi"], 1e-6),
              f"modes3d frame {k}: phi {field(data, 'phi')} against {s['phi']}")
        # Each particle drawn whole, its centre in the box.
        L = max(box.GetPoint(i)[0] for i in range(box.GetNumberOfPoints()))
        for p in range(4):
            centre = [sum(data.GetPoint(12 * p + v)[c] for v in range(12)) / 12 for c in range(3)]
            check(all(0 <= c < L for c in centre), f"modes3d frame {k}: particle {p} centre {centre} outside [0, {L})")
        ratio = cell_values(data, "volume_ratio")
        check(all(0.5 < r < 1.5 for r in ratio), f"modes3d frame {k}: volume ratios")
    print("dpm.compress3d and dpm.modes3d: frames read back")


def check_refusals(softgrain, work):
    for options, words in ((["--vtk", "--vtk-every", "0"], ["--vtk-every 0", ">= 1"]),
                           (["--vtk-every", "3"], ["--vtk-every 3", "--vtk"]),
                           (["--vtk"], ["--vtk", "core.harmonic", "allowed for", "spd.compaction"])):
        done, _ = run(softgrain, work / "refused", "core.harmonic", *options, expect=2)
        check(all(w in done.stderr for w in words), f"{options}: message {done.stderr.strip()!r} lacks {words}")
    check(not (work / "refused").exists() or not any((work / "refused").iterdir()),
          "a refused run left files behind")


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    if vtkXMLPolyDataReader is None:
        print("vtk_readback: VTK's Python module is missing (scripts/install-deps --vtk; run with "
              "/usr/bin/python3): skipped", file=sys.stderr)
        return SKIP
    global messages
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)
    softgrain = sys.argv[1]
    work = Path(sys.argv[2]) if len(sys.argv) == 3 else Path(tempfile.mkdtemp(prefix="softgrain-vtk-"))
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    check_refusals(softgrain, work)
    check_ring(softgrain, work)
    check_compaction(softgrain, work)
    check_tissue(softgrain, work)
    check_compress2d(softgrain, work)
    check_slump(softgrain, work)
    check_modes(softgrain, work)
    check_shear_friction(softgrain, work)
    check_packing_fraction(softgrain, work)
    check_crystal_modes(softgrain, work)
    check_rearrangement(softgrain, work)
    check_compress_box(softgrain, work)
    check_boundary_jam(softgrain, work)
    check_shear_modulus(softgrain, work)
    check_jam(softgrain, work)
    check_vsm(softgrain, work)
    check_sd(softgrain, work)
    check_beam(softgrain, work)
    check_ring_pressure(softgrain, work)
    check_approach(softgrain, work)
    check_patch(softgrain, work)
    check_compare_ring(softgrain, work)
    check_refusal_reasons(softgrain, work)
    check_shape3d(softgrain, work)
    check_slide3d(softgrain, work)
    check_shear_modulus3d(softgrain, work)
    check_dpm3d(softgrain, work)
    if failures:
        print(f"vtk_readback: {len(failures)} failures", file=sys.stderr)
        return 1
    if len(sys.argv) == 2:
        shutil.rmtree(work, ignore_errors=True)
    print("vtk_readback: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
