// Shear modulus of a jammed periodic packing, DPM section 9.4.3 (Fig. 9.16a in 2D, 9.16b in 3D): simple shear
// steps x'_i = x_i + dgamma y_i with Lees-Edwards boundaries (dgamma = 5e-9), an energy minimisation after
// each, shear stress Sigma~ = -Sigma_xy (eq. 9.26 in 2D, its 3D analogue in system3d.hpp) and
// G = d Sigma~ / d gamma (least-squares slope over the steps). The minimisation after each step is Newton's
// method with the pseudo-inverse of the dynamical matrix (polish_newton) from the previous equilibrium: for a
// step of 5e-9 the quadratic model is exact to O(dgamma^2), so it reaches the minimum FIRE would approach, to
// round-off (decision dpm-shear-modulus). In 3D above dense_hessian_limit3d degrees of freedom (or by
// choice) the steps are regularised Newton steps on the sparse matrix (polish_newton_sparse), whose memory
// and time grow with its non-zeros instead of n^2 and n^3. Where Newton cannot reach the tolerance in its 30
// damped steps, FIRE relaxes the packing first (ShearablePacking::relax) and Newton tries again: near onset
// a packing's smallest non-zero eigenvalue can be 1e-8 of its largest, and full Newton steps open and close
// contacts of overlap ~1e-6, so the damped steps crawl (DPM-Fig9.16a's first floppy packing jammed with
// fire_step = 1, at P = 1e-6: 409 steps to the tolerance, each lowering the largest force by about 1 %).
// The procedure is written once, on the operations it needs from a packing (ShearablePacking); 2D and 3D
// systems provide them. Units: G and Sigma in the stress unit of the system, [E/L^2] in 2D, [E/L^3] in 3D.
#pragma once

#include "core/fire.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/packing_hessian3d.hpp"
#include "dpm/system/system.hpp"
#include "dpm/system/system3d.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace softgrain::dpm {

struct ShearModulusResult
{
    double modulus = 0;               // G [stress unit]
    std::vector<double> shear_stress; // -Sigma_xy at gamma = 0, dgamma, 2 dgamma, ...
    double force_max = 0;             // largest force component after the last minimisation
    Eigen::VectorXd equilibrium;      // x after the minimisation at gamma = 0 (linear_shear_modulus.hpp)
};

// What the procedure needs from a periodic packing of any dimension; each operation acts on the packing's own
// (Lees-Edwards) box, which shear changes.
struct ShearablePacking
{
    // Newton from x to a largest force component below the tolerance; returns the largest force reached.
    std::function<double(Eigen::VectorXd&, double)> minimise;
    std::function<void(Eigen::VectorXd&, double)> shear;  // x_i += dgamma y_i; the box strain grows by dgamma
    std::function<double(const Eigen::VectorXd&)> stress; // Sigma~ = -Sigma_xy (symmetric part)
    // FIRE from x to an rms force below the tolerance, where Newton falls short (header); empty: none.
    std::function<void(Eigen::VectorXd&, double)> relax;
};

// Called after each minimisation with the step (0: the polished, unsheared packing), the minimum and Sigma~.
using ShearStepObserver = std::function<void(int step, const Eigen::VectorXd& x, double shear_stress)>;
// The same for a system, which carries the box and its Lees-Edwards strain step x dgamma.
template <class System>
using ShearedSystemObserver =
    std::function<void(int step, const System& system, const Eigen::VectorXd& x, double shear_stress)>;

// Applies `steps` strain steps of `dgamma` from x (which must be in equilibrium: it is Newton-polished first,
// to `force_tolerance`). Where Newton falls short, packing.relax (if given) takes x to an rms force of 1e-3
// of the tolerance, and Newton polishes from there to 1e-4 of it, the round-off level where Newton
// converges: on the floppy packing of the header, Newton from FIRE's 1e-2 still crawled (largest force
// 9.5e-12 after 30 steps), from 1e-3 (55 465 FIRE iterations) it reached 7e-15. So the residual force,
// which the finite-strain stress carries amplified by 1/dgamma, is as small as on Newton's own path.
// NumericalError if the tolerance is still not reached.
ShearModulusResult shear_modulus(const ShearablePacking& packing, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearStepObserver& observe = {});

// The same on a copy of a 2D or a 3D system (rough or smooth contacts, any shape model); `fire`, when given,
// the FIRE settings of the fallback relaxation (those of the jamming protocol that made the packing, with
// their force tolerance replaced).
ShearModulusResult shear_modulus(DpmSystem system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance, const ShearedSystemObserver<DpmSystem>& observe = {},
                                 const std::optional<FireOptions>& fire = {});
ShearModulusResult shear_modulus(DpmSystem3d system, Eigen::VectorXd x, double dgamma, int steps,
                                 double force_tolerance,
                                 const ShearedSystemObserver<DpmSystem3d>& observe = {},
                                 HessianStorage storage = HessianStorage::automatic,
                                 const std::optional<FireOptions>& fire = {});

} // namespace softgrain::dpm
