// Registration of the dpm.* scenes; each scene lives in its own file.
#include "dpm/dpm_scenes.hpp"

#include "dpm/bench_scene.hpp"
#include "dpm/boundary_jam_scene.hpp"
#include "dpm/box_compress_scene.hpp"
#include "dpm/compress3d_scene.hpp"
#include "dpm/compress_scene.hpp"
#include "dpm/crystal_scene.hpp"
#include "dpm/jam_scene.hpp"
#include "dpm/mesh3d.hpp"
#include "dpm/modes_scene.hpp"
#include "dpm/packing_scene.hpp"
#include "dpm/rearrangement_scene.hpp"
#include "dpm/scenes3d.hpp"
#include "dpm/shear_modulus3d_scene.hpp"
#include "dpm/shear_modulus_scene.hpp"
#include "dpm/shear_scene.hpp"
#include "dpm/slide3d_scene.hpp"
#include "dpm/slump_scene.hpp"
#include "dpm/system.hpp"

#include <algorithm>

namespace softgrain {

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

// A spectrum (eq. 9.28) takes the dense dynamical matrix and its eigenvectors: two n x n matrices.
MemoryEstimate modes_memory(const Parameters& p)
{
    // A packing has particles of nodes and nodes + 4 vertices, a single particle nodes.
    const double particles = integer(p, "particles"), nodes = integer(p, "nodes");
    if (disks(p)) return dense_matrix_memory(2 * particles, 2, "2 x particles");
    const double vertices = particles > 1 ? particles * (nodes + 2) : nodes;
    return dense_matrix_memory(2 * vertices, 2, particles > 1 ? "2 x particles x (nodes + 2)" : "2 x nodes");
}

// A 3D packing of `particles` particles of the chosen mesh, with `matrices` dense 3N x 3N matrices (the
// Hessian of the Newton polish at P_t, and for a spectrum its eigenvectors).
MemoryEstimate packing3d_memory(const Parameters& p, int matrices)
{
    const double vertices = integer(p, "particles") * dpm::mesh_from_name(p.choice("mesh")).vertex_count();
    return dense_matrix_memory(3 * vertices, matrices, "3 x particles x mesh vertices");
}

} // namespace

void register_dpm_scenes(SceneRegistry& registry)
{
    registry.add(
        Scene{"dpm.modes",
              "DPM eq. (9.28): eigenvalues of the dynamical matrix of a floppy / shell / surface-tension "
              "particle, zero modes, Delta U along each mode (Figs. 9.14a, c)",
              dpm::modes_parameters(), dpm::run_modes}
            .needing(modes_memory)
            .with_vtk());
    registry.add(Scene{"dpm.shear_friction",
                       "DPM sec. 9.3.3: simple shear of two rough or smooth particles, mu_eff against x/D "
                       "(Figs. 9.8, 9.9), maximum against eq. (9.13)",
                       dpm::shear_friction_parameters(), dpm::run_shear_friction}
                     .needing([](const Parameters& p) {
                         return dpm::dpm_vertex_memory(2 * integer(p, "nodes"), "vertices (2 x nodes)");
                     })
                     .with_vtk());
    registry.add(
        Scene{"dpm.packing_fraction",
              "DPM eqs. (9.18)-(9.22): packing fraction of a jammed packing of rough particles, analytic "
              "against Monte-Carlo, term by term (Table 9.2)",
              dpm::packing_fraction_parameters(), dpm::run_packing_fraction}
            .needing([](const Parameters& p) {
                return dpm::dpm_vertex_memory(integer(p, "particles") * integer(p, "nodes"),
                                              "vertices (particles x nodes)");
            })
            .with_vtk());
    registry.add(
        Scene{"dpm.crystal_modes",
              "DPM eq. (9.28), Fig. 9.5(a): modes of a compressed triangular soft-disk crystal against "
              "its exact phonon spectrum; the displacement field of one mode",
              dpm::crystal_modes_parameters(), dpm::run_crystal_modes}
            .needing([](const Parameters& p) {
                // rows x rows disks: the dynamical matrix of 2 rows^2 rows and its eigenvectors.
                return dense_matrix_memory(2 * integer(p, "rows") * integer(p, "rows"), 2, "2 x rows^2");
            })
            .with_vtk());
    registry.add(
        Scene{"dpm.jam",
              "DPM sec. 9.4: jamming onset of bidisperse disks or deformable particles by compression + "
              "FIRE with bisection on the pressure; P against phi - phi_c (Fig. 9.13)",
              dpm::jam_scene_parameters(), dpm::run_jam}
            .needing(bidisperse_memory)
            .with_vtk());
    registry.add(Scene{"dpm.bench",
                       "Issue 19: the cost of jamming one packing with the dpm.jam protocol (2D) or the 3D "
                       "protocol, and of its dense spectrum: time, FIRE iterations, force evaluations per "
                       "second (make bench)",
                       dpm::bench_parameters(), dpm::run_bench}
                     .needing(dpm::bench_memory)
                     .without_vtk("a timed scene: writing frames would change the time it measures; "
                                  "dpm.jam and dpm.modes3d draw the packings it times"));
    registry.add(Scene{"dpm.rearrangement",
                       "DPM Fig. 9.13(e, f): the first irreversible change of the contact network of a "
                       "smooth-disk packing compressed from onset in steps Delta phi; both networks",
                       dpm::rearrangement_parameters(), dpm::run_rearrangement}
                     .needing([](const Parameters& p) {
                         return dpm::dpm_vertex_memory(integer(p, "particles"), "disks (particles)");
                     })
                     .with_vtk());
    registry.add(
        Scene{"dpm.compress2d",
              "DPM sec. 9.3.4: an elastic shell or a spring-network disk compressed between two plates, "
              "F_a against delta/D, its small-strain exponent and eq. (9.14) (Fig. 9.10)",
              dpm::compress2d_parameters(), dpm::run_compress2d}
            .needing([](const Parameters& p) {
                return p.choice("model") == "shell"
                           ? dpm::dpm_vertex_memory(integer(p, "nodes"), "vertices (nodes)")
                           : dpm::dpm_vertex_memory(integer(p, "network_nodes"), "nodes (network_nodes)");
            })
            .with_vtk());
    registry.add(
        Scene{
            "dpm.compress3d",
            "DPM sec. 9.3.4: elastic tetrahedra (eqs. 9.15-9.17), an elastic shell or a spring-network ball "
            "compressed between two plates, F~ against delta/D and its exponents (Fig. 9.11)",
            dpm::compress3d_parameters(), dpm::run_compress3d}
            .advised_by({"compare",
                         "compare-solid-work-precision",
                         "method_index",
                         {"tetrahedra", "spring_network"},
                         "",
                         "",
                         "vertices",
                         "surface vertices + 1 (tetrahedra) or nodes (network)",
                         "fe_error_max",
                         "largest |F~/F~_FE - 1| over 0.01 <= delta/D <= 0.2 against the finite-element "
                         "ball of the same law and nu (data/compare/solid_fe.toml)"})
            .needing([](const Parameters& p) {
                // The spring network's Newton steps use its dense Hessian; the meshes are bounded.
                if (p.choice("model") != "spring_network") return MemoryEstimate{};
                return dense_matrix_memory(3 * integer(p, "network_nodes"), 1, "3 x network_nodes");
            })
            .with_vtk());
    registry.add(Scene{"dpm.compress_box",
                       "DPM Fig. 9.4: soft disks or deformable particles compressed uniaxially by 20 % in a "
                       "box with repulsive walls: snapshots, overlaps, facets",
                       dpm::compress_box_parameters(), dpm::run_compress_box}
                     .needing(bidisperse_memory)
                     .with_vtk());
    registry.add(Scene{"dpm.boundary_jam",
                       "DPM Fig. 9.18(a-e): jammed packings of 4 disks inside a floppy deformable boundary, "
                       "distinct packings by contacts and parallelogram angle",
                       dpm::boundary_jam_parameters(), dpm::run_boundary_jam}
                     .needing([](const Parameters& p) {
                         // The boundary's dense Hessian (4 disks beside it).
                         return dense_matrix_memory(2 * integer(p, "boundary_nodes") + 12, 1,
                                                    "2 x boundary_nodes + 12");
                     })
                     .with_vtk());
    registry.add(Scene{"dpm.shape3d",
                       "DPM sec. 9.3.1: closed triangulated meshes (Platonic solids, geodesic icosahedra), "
                       "Euler counts and the 3D shape parameter A^3D",
                       dpm::shape3d_parameters(), dpm::run_shape3d}
                     .with_vtk());
    registry.add(Scene{"dpm.modes3d",
                       "DPM eq. (9.2), (9.28): eigenvalues of the dynamical matrix of a single 3D floppy / "
                       "shell / surface-tension particle and its zero modes (Fig. 9.15a), or of a jammed "
                       "bidisperse packing of them (particles > 1, Fig. 9.15b)",
                       dpm::modes3d_parameters(), dpm::run_modes3d}
                     .needing([](const Parameters& p) { return packing3d_memory(p, 2); })
                     .with_vtk());
    registry.add(Scene{"dpm.shear_modulus",
                       "DPM sec. 9.4.3: shear modulus G of jammed packings from Lees-Edwards strain steps "
                       "against pressure, fitted exponent of G ~ P^eta (Fig. 9.16a)",
                       dpm::shear_modulus_parameters(), dpm::run_shear_modulus}
                     .needing([](const Parameters& p) {
                         // The Newton polish at each pressure uses the dense Hessian of the packing.
                         return dense_matrix_memory(2 * bidisperse_vertices(p), 1,
                                                    std::string("2 x ") + bidisperse_basis(p));
                     })
                     .with_vtk());
    registry.add(Scene{"dpm.shear_modulus3d",
                       "DPM sec. 9.4.3: shear modulus G of jammed 3D packings of floppy, shell and "
                       "surface-tension particles from Lees-Edwards strain steps against pressure, fitted "
                       "exponents of G ~ P^eta (Fig. 9.16b)",
                       dpm::shear_modulus3d_parameters(), dpm::run_shear_modulus3d}
                     .needing([](const Parameters& p) { return packing3d_memory(p, 1); })
                     .with_vtk());
    registry.add(Scene{"dpm.slump",
                       "DPM Fig. 9.3: slump test of rough or smooth deformable particles under gravity, "
                       "right wall removed; run-out, angle of repose, layers at the front",
                       dpm::slump_parameters(), dpm::run_slump_scene}
                     .needing(bidisperse_memory)
                     .with_vtk());
    registry.add(
        Scene{"dpm.slide3d",
              "DPM sec. 9.3.2 in 3D: a rigid 3D particle slid over a flat slab at fixed height, "
              "energy and F_x/F_z along the path for rough (vertex spheres) and smooth (vertex-face) "
              "contacts",
              dpm::slide3d_parameters(), dpm::run_slide3d}
            .with_vtk());
}

} // namespace softgrain
