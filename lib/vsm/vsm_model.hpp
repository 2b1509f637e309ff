// The VSM particle model (Frenning 2022): boundary treatment (section 2.4), mean deformation gradient
// (eqs. (6), (24), (26)), internal forces (eqs. (41)/(42) and (43)), reactions and tractions (section 3.3,
// eq. (39)), contact (stabilisation) forces (eq. (46), Appendix C).
//
// Positions are a 3 x N matrix (one column per real particle). Every deformation gradient is an affine
// function of the positions; the model stores its linear part per particle as 9 x 3 blocks
// dvec(F_a)/dx_c (vec row-major: index 3 i + j for F_ij), in two versions:
//   * stress:  prescribed branch vectors D_ab xbar_ab treated as constants (the derivation of eq. (43));
//   * full:    xbar_ab = 2 (w_ab - x_a) differentiated too (Appendix C, eqs. (66)-(70), the M''_abc).
#pragma once

#include "core/vector.hpp"
#include "vsm/neo_hookean.hpp"
#include "vsm/reference_cells.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace softgrain::vsm {

// Boundary kinds of eq. (14): projection D_ab onto the prescribed components of the ghost branch vector.
enum class BoundaryKind {
    free,         // D = 0 (traction or free surface)
    total,        // D = I
    symmetric,    // D = N (x) N: normal displacement prescribed
    antisymmetric // D = I - N (x) N: tangential displacement prescribed
};

Mat3 boundary_projection(BoundaryKind kind, const Vec3& normal); // D_ab, eq. (14)

// A rigid frictionless plate on a free surface (compare.solid: a ball between plates; not in the paper,
// decision vsm-plate-contact). The plate is the plane normal . w = height(t), normal the unit vector out of
// the body. The boundary point of a free face, w_ab = x_a + x_ab/2 (x_ab the least-squares ghost branch of
// eq. (24) with D = 0), stores the penalty energy A_ab kappa_ab g^2/2 when it lies beyond the plane by
// g = normal . w_ab - height > 0, kappa_ab = penalty E / L_ab [Pa/m]. Its force follows from that energy
// through w_ab's dependence on x_a and on a's neighbours (eq. (22)), so the forces on the particles sum to
// the plate's load and the system keeps its energy.
struct RigidPlate
{
    int label = -1;                         // the faces it can touch
    Vec3 normal = Vec3::UnitZ();            // unit, out of the body
    std::function<double(double t)> height; // m
    double penalty = 25;                    // c_pen, 1
};

struct BoundaryConditions
{
    std::vector<BoundaryKind> kind; // per face label
    // Prescribed displacement u_bar(label, W, t) of a boundary point W on a face with that label [m]
    // (components selected by D); may be empty when no face prescribes a displacement.
    std::function<Vec3(int label, const Vec3& W, double t)> displacement;
    // Nominal traction T_bar(label, W, t) [Pa] on free faces, eq. (39); empty for traction-free surfaces.
    std::function<Vec3(int label, const Vec3& W, double t)> traction;
    std::vector<RigidPlate> plates; // on free faces
};

enum class InternalForce {
    eq43, // angular-momentum-preserving form, eq. (43)
    eq41  // eq. (41) in its pairwise form (42), valid also at boundaries, with reactions: the static form
          // of 3.3
};

struct Material
{
    double young = 0;   // E [Pa]
    double poisson = 0; // nu
    double density = 0; // rho [kg/m^3]
    LameParameters lame() const { return lame_from_young(young, poisson); }
    double p_wave_speed() const;     // c_p = sqrt((lambda + 2 mu)/rho)
    double shear_wave_speed() const; // c_s = sqrt(mu/rho)
};

struct ModelOptions
{
    InternalForce internal = InternalForce::eq43;
    double xi_n = 1, xi_t = 1;   // contact factors of eq. (50)
    double c1 = 0, c2 = 0;       // artificial viscosity constants of eq. (51); 0 = off
    Vec3 gravity = Vec3::Zero(); // g [m/s^2] of the body force m_a g, eqs. (35), (39); zero = off
};

using Block93 = Eigen::Matrix<double, 9, 3>;
struct JacobianTerm
{
    int particle;
    Block93 block; // dvec(F_a)/dx_particle
};

class Model
{
  public:
    Model(ReferenceCells cells, const Domain& domain, BoundaryConditions bc, Material material,
          ModelOptions options);

    std::size_t size() const { return cells_.size(); }
    const ReferenceCells& cells() const { return cells_; }
    const Domain& domain() const { return domain_; }
    const BoundaryConditions& boundary_conditions() const { return bc_; }
    const std::vector<double>& mass() const { return mass_; } // m_a = rho V_a
    const Material& material() const { return material_; }
    const ModelOptions& options() const { return options_; }
    double min_branch_length() const { return min_branch_; }

    // Ghost branch vectors x_ab of eq. (24) for every ghost neighbour of a (zero entries for real
    // neighbours).
    std::vector<Vec3> ghost_branches(const Points<3>& x, int a, double t) const;
    // F_a, eq. (6) with the ghost branch vectors of eq. (24) (equivalently eq. (26)).
    Mat3 deformation_gradient(const Points<3>& x, int a, double t) const;
    std::vector<Mat3> deformation_gradients(const Points<3>& x, double t) const;

    // Forces [N] on every particle at positions x and time t: internal + reactions + tractions (+ contact
    // when xi > 0, + gravity m_a g when g != 0). `step` is reported in a NumericalError when some J_a <= 0.
    // With velocities v (and c1 or c2 > 0) the artificial viscous stress of eq. (51) is added to P_a.
    Points<3> forces(const Points<3>& x, double t, long step = 0, const Points<3>* v = nullptr) const;
    // Rate of F_a: sum_c dF_a/dx_c v_c + dF_a/dt (prescribed boundary motion).
    Mat3 deformation_rate(const Points<3>& x, const Points<3>& v, int a, double t) const;
    // Artificial viscous first Piola-Kirchhoff stress P_visc = J sigma F^-T, sigma = rho (c1 c_p h + c2 h^2
    // |tr d|) d, d = sym(Fdot F^-1), h = shortest reference branch vector of a (eq. (51), section 4). Pa.
    Mat3 viscous_stress(const Mat3& F, const Mat3& F_rate, int a) const;
    // Cauchy pressure p_a = -tr(sigma_a)/3 with sigma_a = P_a F_a^T / J_a (elastic part), Pa.
    std::vector<double> pressures(const Points<3>& x, double t) const;
    // The contact forces alone (eq. (46)) and the energies V^int (eq. (33)) and V^cnt (eq. (34)).
    Points<3> contact_forces(const Points<3>& x, const std::vector<Mat3>& F, double t) const;
    double internal_energy(const Points<3>& x, double t) const;
    double contact_energy_total(const Points<3>& x, double t) const;
    // The load on plate `plate` (of BoundaryConditions::plates): sum of A_ab kappa_ab g over its contacts [N],
    // along its normal, and the number of contacts; and the penalty energy of all plates [J].
    struct PlateLoad
    {
        double force = 0;
        int contacts = 0;
    };
    PlateLoad plate_load(const Points<3>& x, double t, std::size_t plate) const;
    double plate_energy(const Points<3>& x, double t) const;

    const std::vector<std::vector<JacobianTerm>>& stress_jacobian() const { return stress_jacobian_; }
    const std::vector<std::vector<JacobianTerm>>& full_jacobian() const { return full_jacobian_; }

  private:
    struct Ghost
    {
        int slot;  // index in the neighbour list of a
        int label; // boundary condition label
        BoundaryKind kind;
        Mat3 D; // eq. (14)
    };
    // The pairwise contact stabilisation of eqs. (29)-(30), visited once per pair: calls
    // on_real(a, b, K, u, x_ab, X_ab) for each pair of real particles (b > a) and
    // on_ghost(a, ghost, K, u, neighbour) for each ghost on a displacement boundary (free ghosts carry none),
    // with K the stiffness of eq. (50) and u the local non-affine displacement.
    template <class OnReal, class OnGhost>
    void for_each_contact(const Points<3>& x, const std::vector<Mat3>& F, double t, OnReal&& on_real,
                          OnGhost&& on_ghost) const;
    // xbar_ab, section 2.4.
    Vec3 prescribed_branch(const Points<3>& x, int a, const Neighbour& nb, int label, double t) const;
    // Calls on_touch(a, ghost, plate index, k = A_ab kappa_ab, g) for every free boundary point beyond a plate.
    template <class OnTouch>
    void for_each_plate_contact(const Points<3>& x, double t, OnTouch&& on_touch) const;
    // Adds the plate penalty forces -k g normal^T dw_ab/dx_c to f.
    void add_plate_forces(const Points<3>& x, double t, Points<3>& f) const;

    ReferenceCells cells_;
    Domain domain_;
    BoundaryConditions bc_;
    Material material_;
    ModelOptions options_;
    std::vector<double> mass_;
    double min_branch_ = 0;
    std::vector<double> min_branch_of_;       // per particle, for eq. (51)
    std::vector<std::vector<Ghost>> ghosts_;  // per particle: its ghost neighbours
    std::vector<Eigen::MatrixXd> K_prime_;    // per particle: rows E''_a, columns P'_a, eq. (22)
    std::vector<std::vector<int>> free_rows_; // per particle: slot -> row of K' (or -1)
    std::vector<std::vector<JacobianTerm>> stress_jacobian_; // eq. (43) linearisation
    std::vector<std::vector<JacobianTerm>> full_jacobian_;   // Appendix C
};

} // namespace softgrain::vsm
