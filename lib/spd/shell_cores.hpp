// The cores of the SPD shell model (Trivino et al., section 2.4, eq. (4)): the fluid inside each closed
// shell. An undrained core of finite modulus K_Omega answers a change of its volume V = s A with the pressure
// increment dp = -K_Omega dV/V0; an incompressible core (K_Omega = inf, the limit eta -> inf of eq. (24),
// decision spd-eta-infinity) keeps its area A0 exactly, its pressure being the multiplier of the constraint
// A(x) = A0, imposed by the two RATTLE stages below; a constant applied (drained) pressure acts in either.
// The pressure p acts on the vertices as p dV/dx_k = p s dA/dx_k. Part of ShellModel (spd/shell_model.hpp),
// which owns the vertex state, adds the core forces in its force evaluation and runs the RATTLE stages within
// its velocity-Verlet step.
#pragma once

#include "core/vector.hpp"
#include "spd/shell.hpp"
#include "spd/shell_contacts.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace softgrain {
class Archive;
}

namespace softgrain::spd {

// Signed area A of a shell's polygon, CCW positive [m^2].
double shell_area(const ShellView& model, const Shell& shell);

class ShellCores
{
  public:
    // Shell `shell` of the model was added: its current volume s A (0 for an open shell) is its reference
    // V0 and the volume of the last evaluation; its pressure is 0.
    void add(const ShellView& model, int shell);

    // From eq. (4), or the constraint multiplier of an incompressible core; excluding the applied pressure
    // [Pa].
    double pressure(int shell) const { return pressure_[shell]; }
    double reference_volume(int shell) const { return V0_[shell]; } // V0 = s A0 [m^3]

    // Eq. (4): updates the pressure of a finite core from its volume change since the last call and adds the
    // pressure forces (with the applied pressure) to f (x and y of each vertex, interleaved); an
    // incompressible core receives only the applied pressure here. Nothing for a shell without core
    // stiffness or applied pressure. Runs inside the parallel force region: writes the forces of the shell's
    // own vertices only, and throws nothing.
    void add_forces(const ShellView& model, int shell, Eigen::VectorXd& f);

    // The core energy V0 p^2 / (2 K_Omega) of a finite core (eq. (4)); 0 otherwise (an incompressible core
    // stores none) [J].
    double energy(const ShellView& model, int shell) const;
    // The core's stiffness K_Omega s^2 sum_k |dA/dx_k|^2 / V0 at the current positions, the eigenvalue of the
    // rank-one core Hessian (decision spd-dtc-kmax); 0 without a finite core (an incompressible core is a
    // constraint, decision spd-eta-infinity) [N/m].
    double stiffness(const ShellView& model, int shell) const;

    // RATTLE (H. C. Andersen, J. Comput. Phys. 52 (1983) 24) for the incompressible cores, velocity Verlet
    // with the constraint force mu dA/dx on each incompressible shell, mu = s p. Position stage, after the
    // first half-kick: corrects the half-step velocities v (the model's, in place; model.v is not read) so
    // that the drift x + dt v keeps every area at A0. Throws NumericalError (exit 3, at `step`) if no
    // multiplier does.
    void constrain_positions(const ShellView& model, const Eigen::VectorXd& inverse_mass, double dt,
                             Eigen::VectorXd& v, std::int64_t step) const;
    // Velocity stage, after the second half-kick at the new positions: corrects v so that dA/dt = 0, adds
    // the constraint force to f (so that the stored force is the one the shell feels) and records the
    // multiplier as the core pressure.
    void constrain_velocities(const ShellView& model, const Eigen::VectorXd& inverse_mass, double dt,
                              Eigen::VectorXd& v, Eigen::VectorXd& f);

    // The per-shell records (V of the last evaluation, p, V0), where ShellModel::transfer has always written
    // them.
    void transfer(Archive& archive);

  private:
    std::vector<double> V_previous_, pressure_, V0_; // per shell [m^3], [Pa], [m^3]
};

} // namespace softgrain::spd
