// The dpm.* scenes not yet in a file of their own under lib/dpm/scenes/ (issue 18), registered from
// lib/dpm/scenes/registry.cpp.
#include "dpm/scenes/scenes.hpp"

#include "dpm/bench_scene.hpp"
#include "dpm/boundary_jam_scene.hpp"
#include "dpm/box_compress_scene.hpp"
#include "dpm/compress_scene.hpp"
#include "dpm/jam_scene.hpp"
#include "dpm/packing_scene.hpp"
#include "dpm/rearrangement_scene.hpp"
#include "dpm/shear_modulus_scene.hpp"
#include "dpm/slump_scene.hpp"
#include "dpm/system.hpp"

#include <algorithm>

namespace softgrain::dpm {

namespace {

double integer(const Parameters& p, const std::string& name)
{
    return static_cast<double>(p.integer(name));
}

// A scene with a `model` choice that is set to disks (dpm.slump has deformable particles only).
bool disks(const Parameters& p)
{
    const auto& specs = p.specs();
    if (std::none_of(specs.begin(), specs.end(), [](const ParameterSpec& s) { return s.name == "model"; }))
        return false;
    const std::string& model = p.choice("model");
    return model == "smooth_disk" || model == "disks";
}

// Vertices of a bidisperse packing, half small and half large particles (a disk is one vertex).
double bidisperse_vertices(const Parameters& p)
{
    if (disks(p)) return integer(p, "particles");
    return integer(p, "particles") * (integer(p, "nodes_small") + integer(p, "nodes_large")) / 2;
}

const char* bidisperse_basis(const Parameters& p)
{
    return disks(p) ? "disks (particles)" : "vertices (particles x (nodes_small + nodes_large) / 2)";
}

MemoryEstimate bidisperse_memory(const Parameters& p)
{
    return dpm::dpm_vertex_memory(bidisperse_vertices(p), bidisperse_basis(p));
}

} // namespace

Scene packing_fraction_scene()
{
    return Scene{"dpm.packing_fraction",
                 "DPM eqs. (9.18)-(9.22): packing fraction of a jammed packing of rough particles, analytic "
                 "against Monte-Carlo, term by term (Table 9.2)",
                 dpm::packing_fraction_parameters(), dpm::run_packing_fraction}
        .needing([](const Parameters& p) {
            return dpm::dpm_vertex_memory(integer(p, "particles") * integer(p, "nodes"),
                                          "vertices (particles x nodes)");
        })
        .with_vtk();
}

Scene jam_scene()
{
    return Scene{"dpm.jam",
                 "DPM sec. 9.4: jamming onset of bidisperse disks or deformable particles by compression + "
                 "FIRE with bisection on the pressure; P against phi - phi_c (Fig. 9.13)",
                 dpm::jam_scene_parameters(), dpm::run_jam}
        .needing(bidisperse_memory)
        .with_vtk();
}

Scene bench_scene()
{
    return Scene{"dpm.bench",
                 "Issue 19: the cost of jamming one packing with the dpm.jam protocol (2D) or the 3D "
                 "protocol, and of its dense spectrum: time, FIRE iterations, force evaluations per "
                 "second (make bench)",
                 dpm::bench_parameters(), dpm::run_bench}
        .needing(dpm::bench_memory)
        .without_vtk("a timed scene: writing frames would change the time it measures; "
                     "dpm.jam and dpm.modes3d draw the packings it times");
}

Scene rearrangement_scene()
{
    return Scene{"dpm.rearrangement",
                 "DPM Fig. 9.13(e, f): the first irreversible change of the contact network of a "
                 "smooth-disk packing compressed from onset in steps Delta phi; both networks",
                 dpm::rearrangement_parameters(), dpm::run_rearrangement}
        .needing([](const Parameters& p) {
            return dpm::dpm_vertex_memory(integer(p, "particles"), "disks (particles)");
        })
        .with_vtk();
}

Scene compress2d_scene()
{
    return Scene{"dpm.compress2d",
                 "DPM sec. 9.3.4: an elastic shell or a spring-network disk compressed between two plates, "
                 "F_a against delta/D, its small-strain exponent and eq. (9.14) (Fig. 9.10)",
                 dpm::compress2d_parameters(), dpm::run_compress2d}
        .needing([](const Parameters& p) {
            return p.choice("model") == "shell"
                       ? dpm::dpm_vertex_memory(integer(p, "nodes"), "vertices (nodes)")
                       : dpm::dpm_vertex_memory(integer(p, "network_nodes"), "nodes (network_nodes)");
        })
        .with_vtk();
}

Scene compress_box_scene()
{
    return Scene{"dpm.compress_box",
                 "DPM Fig. 9.4: soft disks or deformable particles compressed uniaxially by 20 % in a "
                 "box with repulsive walls: snapshots, overlaps, facets",
                 dpm::compress_box_parameters(), dpm::run_compress_box}
        .needing(bidisperse_memory)
        .with_vtk();
}

Scene boundary_jam_scene()
{
    return Scene{"dpm.boundary_jam",
                 "DPM Fig. 9.18(a-e): jammed packings of 4 disks inside a floppy deformable boundary, "
                 "distinct packings by contacts and parallelogram angle",
                 dpm::boundary_jam_parameters(), dpm::run_boundary_jam}
        .needing([](const Parameters& p) {
            // The boundary's dense Hessian (4 disks beside it).
            return dense_matrix_memory(2 * integer(p, "boundary_nodes") + 12, 1, "2 x boundary_nodes + 12");
        })
        .with_vtk();
}

Scene shear_modulus_scene()
{
    return Scene{"dpm.shear_modulus",
                 "DPM sec. 9.4.3: shear modulus G of jammed packings from Lees-Edwards strain steps "
                 "against pressure, fitted exponent of G ~ P^eta (Fig. 9.16a)",
                 dpm::shear_modulus_parameters(), dpm::run_shear_modulus}
        .needing([](const Parameters& p) {
            // The Newton polish at each pressure uses the dense Hessian of the packing.
            return dense_matrix_memory(2 * bidisperse_vertices(p), 1,
                                       std::string("2 x ") + bidisperse_basis(p));
        })
        .with_vtk();
}

Scene slump_scene()
{
    return Scene{"dpm.slump",
                 "DPM Fig. 9.3: slump test of rough or smooth deformable particles under gravity, "
                 "right wall removed; run-out, angle of repose, layers at the front",
                 dpm::slump_parameters(), dpm::run_slump_scene}
        .needing(bidisperse_memory)
        .with_vtk();
}

} // namespace softgrain::dpm
