// The three bodies of DPM Fig. 9.11, each compressed between two plates by the protocol of compress.hpp
// (section 9.3.4, plate law U^plate with k_p/k_c = 4, plates normal to z):
//   tetrahedra:     a surface mesh + central vertex with the strain energy of eq. (9.15)
//                   (elastic_tetrahedra.hpp),
//   shell:          the shape energy of eq. (9.2) with A0 = A_min, k_v, k_a, k_b > 0,
//                   theta_e0 = the mesh's angles,
//   spring_network: a disordered 3D network ball (spring_network.hpp).
// Units (decision dpm-compress3d-units): sigma = 1 = the vertex diameter = the mean edge length of the mesh
// (the node spacing of the network), energies in k_c sigma^2, so forces in k_c sigma and E in k_c/sigma.
// The meshes are rotated so that a vertex (and its antipode) lies on the z axis: the pole vertex is the
// first contact with each plate.
#pragma once

#include "dpm/laws/elastic_tetrahedra.hpp"
#include "dpm/protocols/compress.hpp"
#include "dpm/system/mesh3d.hpp"

#include <optional>
#include <string>

namespace softgrain::dpm {

struct Compression3dOptions
{
    std::string mesh = "geodesic162";     // shell and tetrahedra: surface mesh (mesh_from_name)
    double E = 1.0, nu = 0.3;             // tetrahedra: Young's modulus [k_c/sigma] and Poisson ratio
    double kv = 1e-3, ka = 1.0, kb = 1.0; // shell: k_v [k_c/sigma^4], k_a [k_c/sigma^2], k_b [k_c sigma^2]
    int network_nodes = 2000;             // network: nodes (paper: 3765)
    double cutoff = 1.83;                 // network: spring cutoff [node spacing]
    double network_k = 1.0;               // network: spring k / k_c
    std::uint64_t seed = 1;               // network: node placement
    PlateSchedule schedule;
};

struct Compression3dResult
{
    CompressionResult compression;
    double E = 0, nu = 0; // moduli attributed to the body for F~ (decision dpm-compress3d-moduli)
    int vertices = 0;     // surface vertices (+ 1 central for tetrahedra) or network nodes
    int springs = 0;      // network only
};

// The named mesh, rotated so that vertex 0 is on +z, scaled to mean edge length 1.
TriangleMesh compression_mesh(const std::string& name);

// Sees each relaxed state: the body's coordinates (the tetrahedra's central vertex last), the top plate's
// height, the sample, and the gradient of the body's energy at them (the plates excluded).
using BodyObserver =
    std::function<void(const Eigen::VectorXd&, double, const CompressionSample&, const Eigen::VectorXd&)>;

Compression3dResult compress3d_tetrahedra(const Compression3dOptions& options,
                                          const BodyObserver& observe = {});
Compression3dResult compress3d_shell(const Compression3dOptions& options, const BodyObserver& observe = {});
Compression3dResult compress3d_network(const Compression3dOptions& options, const BodyObserver& observe = {});

// Mean face area of the mesh (the a_0 of the shell's modulus).
double mean_face_area(const TriangleMesh& mesh);

// Largest absolute row sum of a symmetric matrix: an upper bound of its largest eigenvalue (Gershgorin).
double gershgorin_bound(const Eigen::MatrixXd& m);

} // namespace softgrain::dpm
