// The dpm.* scenes not yet in a file of their own under lib/dpm/scenes/ (registered by
// lib/dpm/scenes/registry.cpp).
#include "dpm/scenes/scenes.hpp"

#include "dpm/compress3d_scene.hpp"
#include "dpm/crystal_scene.hpp"
#include "dpm/mesh3d.hpp"
#include "dpm/modes_scene.hpp"
#include "dpm/scenes3d.hpp"
#include "dpm/shear_modulus3d_scene.hpp"
#include "dpm/shear_scene.hpp"
#include "dpm/slide3d_scene.hpp"
#include "dpm/system.hpp"

namespace softgrain::dpm {

namespace {

double integer(const Parameters& p, const std::string& name)
{
    return static_cast<double>(p.integer(name));
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
    const double vertices = integer(p, "particles") * mesh_from_name(p.choice("mesh")).vertex_count();
    return dense_matrix_memory(3 * vertices, matrices, "3 x particles x mesh vertices");
}

} // namespace

Scene modes_scene()
{
    return Scene{"dpm.modes",
                 "DPM eq. (9.28): eigenvalues of the dynamical matrix of a floppy / shell / surface-tension "
                 "particle, zero modes, Delta U along each mode (Figs. 9.14a, c)",
                 modes_parameters(), run_modes}
        .needing(modes_memory)
        .with_vtk();
}

Scene shear_friction_scene()
{
    return Scene{"dpm.shear_friction",
                 "DPM sec. 9.3.3: simple shear of two rough or smooth particles, mu_eff against x/D "
                 "(Figs. 9.8, 9.9), maximum against eq. (9.13)",
                 shear_friction_parameters(), run_shear_friction}
        .needing([](const Parameters& p) {
            return dpm_vertex_memory(2 * integer(p, "nodes"), "vertices (2 x nodes)");
        })
        .with_vtk();
}

Scene crystal_modes_scene()
{
    return Scene{"dpm.crystal_modes",
                 "DPM eq. (9.28), Fig. 9.5(a): modes of a compressed triangular soft-disk crystal against "
                 "its exact phonon spectrum; the displacement field of one mode",
                 crystal_modes_parameters(), run_crystal_modes}
        .needing([](const Parameters& p) {
            // rows x rows disks: the dynamical matrix of 2 rows^2 rows and its eigenvectors.
            return dense_matrix_memory(2 * integer(p, "rows") * integer(p, "rows"), 2, "2 x rows^2");
        })
        .with_vtk();
}

Scene compress3d_scene()
{
    return Scene{
        "dpm.compress3d",
        "DPM sec. 9.3.4: elastic tetrahedra (eqs. 9.15-9.17), an elastic shell or a spring-network ball "
        "compressed between two plates, F~ against delta/D and its exponents (Fig. 9.11)",
        compress3d_parameters(), run_compress3d}
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
        .with_vtk();
}

Scene shape3d_scene()
{
    return Scene{"dpm.shape3d",
                 "DPM sec. 9.3.1: closed triangulated meshes (Platonic solids, geodesic icosahedra), "
                 "Euler counts and the 3D shape parameter A^3D",
                 shape3d_parameters(), run_shape3d}
        .with_vtk();
}

Scene modes3d_scene()
{
    return Scene{"dpm.modes3d",
                 "DPM eq. (9.2), (9.28): eigenvalues of the dynamical matrix of a single 3D floppy / "
                 "shell / surface-tension particle and its zero modes (Fig. 9.15a), or of a jammed "
                 "bidisperse packing of them (particles > 1, Fig. 9.15b)",
                 modes3d_parameters(), run_modes3d}
        .needing([](const Parameters& p) { return packing3d_memory(p, 2); })
        .with_vtk();
}

Scene shear_modulus3d_scene()
{
    return Scene{"dpm.shear_modulus3d",
                 "DPM sec. 9.4.3: shear modulus G of jammed 3D packings of floppy, shell and "
                 "surface-tension particles from Lees-Edwards strain steps against pressure, fitted "
                 "exponents of G ~ P^eta (Fig. 9.16b)",
                 shear_modulus3d_parameters(), run_shear_modulus3d}
        .needing([](const Parameters& p) { return packing3d_memory(p, 1); })
        .with_vtk();
}

Scene slide3d_scene()
{
    return Scene{"dpm.slide3d",
                 "DPM sec. 9.3.2 in 3D: a rigid 3D particle slid over a flat slab at fixed height, "
                 "energy and F_x/F_z along the path for rough (vertex spheres) and smooth (vertex-face) "
                 "contacts",
                 slide3d_parameters(), run_slide3d}
        .with_vtk();
}

} // namespace softgrain::dpm
