// The elastic-solid surface model of DPM section 9.3.4 (Fig. 9.11c): a closed triangulated surface of N
// vertices plus one central vertex (index N), forming 2N - 4 tetrahedra (central vertex, surface face f),
// with the strain energy of eq. (9.15)
//
//   U = sum_f sum_{mnqr} v_f/2 eps_{f,mn} C_mnqr eps_{f,qr}
//     = sum_f v_f (lambda/2 (tr eps_f)^2 + mu eps_f:eps_f),
//
// eps_f = (J_f^T J_f - I)/2 (Green-Lagrange strain), J_f = Y_f X_f^T (X_f X_f^T)^-1 = Y_f X_f^-1 (X_f is
// square and invertible) with the edge matrices of eqs. (9.16)-(9.17): columns r_{f,k} - r_{N+1}, k = 1..3,
// in the reference (X_f) and the deformed (Y_f) state. C is isotropic with Lame constants
// lambda = E nu/((1 + nu)(1 - 2 nu)), mu = E/(2 (1 + nu)), so the energy is that of a Saint Venant-Kirchhoff
// solid, piecewise homogeneous in each tetrahedron (decision dpm-tetra-energy: v_f is the reference volume).
// Sign: eps_f > 0 in extension; U >= 0 for lambda + 2 mu/3 >= 0 and mu >= 0 (E > 0, -1 < nu < 1/2);
// tetrahedra_energy adds the gradient dU/dx = minus the forces.
// Units: lengths [L], E [energy/L^3]; returns energies [energy]. Valid for any deformation with det J_f > 0
// (Saint Venant-Kirchhoff softens in strong compression, beyond ~40 % uniaxial strain). Only the reference
// state is checked (elastic_tetrahedra() refuses an inverted tetrahedron); the energy does not check J_f.
#pragma once

#include "dpm/laws/local_derivatives.hpp"
#include "dpm/system/mesh3d.hpp"

#include <Eigen/Dense>

#include <vector>

namespace softgrain::dpm {

struct IsotropicElasticity
{
    double lambda = 0, mu = 0; // Lame constants [energy/L^3]
    static IsotropicElasticity from_young(double E, double nu)
    {
        return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
    }
};

// Strain energy density eps:C:eps/2 = lambda/2 (tr eps)^2 + mu eps:eps at deformation gradient J.
template <class Scalar>
Scalar saint_venant_kirchhoff_density(const Eigen::Matrix<Scalar, 3, 3>& J, const IsotropicElasticity& c)
{
    const Eigen::Matrix<Scalar, 3, 3> strain =
        Scalar(0.5) * (J.transpose() * J - Eigen::Matrix<Scalar, 3, 3>::Identity());
    const Scalar trace = strain.trace();
    const Scalar contraction = strain.cwiseProduct(strain).sum();
    return Scalar(0.5 * c.lambda) * trace * trace + Scalar(c.mu) * contraction;
}

// One term of eq. (9.15): x = (r_{f,1}, r_{f,2}, r_{f,3}, r_centre) (12 coordinates).
struct TetrahedronStrainEnergy
{
    Eigen::Matrix3d reference_inverse; // X_f^-1, eq. (9.16)
    double reference_volume = 0;       // v_f = det X_f / 6
    IsotropicElasticity material;

    // Deformation gradient J_f = Y_f X_f^-1, eq. (9.17).
    template <class Scalar>
    Eigen::Matrix<Scalar, 3, 3> deformation_gradient(const Eigen::Matrix<Scalar, 12, 1>& x) const
    {
        Eigen::Matrix<Scalar, 3, 3> edges;
        for (int k = 0; k < 3; ++k)
            edges.col(k) = x.template segment<3>(3 * k) - x.template segment<3>(9);
        const Eigen::Matrix<Scalar, 3, 3> inverse = reference_inverse.cast<Scalar>();
        return edges * inverse;
    }
    template <class Scalar>
    Scalar operator()(const Eigen::Matrix<Scalar, 12, 1>& x) const
    {
        const Eigen::Matrix<Scalar, 3, 3> J = deformation_gradient(x);
        return Scalar(reference_volume) * saint_venant_kirchhoff_density(J, material);
    }
};

// The particle: a surface mesh (vertices 0 .. N-1) and a central vertex N, reference state `reference`
// (3(N + 1) coordinates; the central vertex at the centroid of the mesh's vertices).
struct ElasticTetrahedra
{
    TriangleMesh mesh;
    Eigen::VectorXd reference;
    std::vector<TetrahedronStrainEnergy> tetrahedra; // one per face, in the mesh's face order
    int centre() const { return mesh.vertex_count(); }
};

// Builds the 2N - 4 tetrahedra of a closed outward-oriented mesh at its current vertex positions; throws
// NumericalError if a tetrahedron is degenerate or inverted (the mesh is not star-shaped about its centroid).
ElasticTetrahedra elastic_tetrahedra(const TriangleMesh& mesh, const IsotropicElasticity& material);

// Eq. (9.15) at coordinates x (3(N + 1)); adds the gradient and the Hessian when given.
double tetrahedra_energy(const ElasticTetrahedra& body, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                         Eigen::MatrixXd* hessian);

// The points of tetrahedron f: its face's three vertices, then the central vertex.
std::array<int, 4> tetrahedron_points(const ElasticTetrahedra& body, int f);

} // namespace softgrain::dpm
