// Appendix A of DPM (Fig. 9.19e): mu_eff of two smooth particles whose shapes are frozen in the configuration
// of the maximum of the simple-shear test (the star of Fig. 9.8d) while mu is translated rigidly.
//
// Vertices (regular octagons of the shear test, section 9.3.3): t = mu's bottom vertex, r = beta's
// upper-right vertex (right end of its flat top edge), r+1 = the upper-left one. The displacement r_{beta r,
// mu t} = r_mu t - r_beta r is varied: horizontally from t above r+1 to t above r; vertically from zero
// vertical separation of r and t (the deepest overlap) to the zero-overlap limit, found for each horizontal
// position by bisection on U_int = 0. At each point mu_eff = F_t/F_n, eqs. (9.10)-(9.12).
#pragma once

#include "dpm/system/system.hpp"

#include <vector>

namespace softgrain::dpm {

struct FrozenContactPoint
{
    double rx = 0, ry = 0;       // r_{beta r, mu t} [sigma]
    double overlap_fraction = 0; // ry / ry_zero(rx): 0 = deepest, 1 = zero-overlap limit
    double mu_eff = 0, normal = 0, tangential = 0;
};

struct FrozenContactScan
{
    std::vector<FrozenContactPoint> points;         // rx outer, ry inner (blocks of `vertical` points)
    Eigen::Vector2d star = Eigen::Vector2d::Zero(); // r_{beta r, mu t} of the frozen configuration
    double mu_eff_star = 0;                         // mu_eff of the frozen configuration itself
    double mu_eff_max_at_star_height = 0;           // max over rx at ry = star.y() (the "x" of Fig. 9.19e)
    double rx_at_max = 0;
    double min_force = 0;           // smallest |F_mb| over the scan, zero-overlap row excluded [k_c sigma]
    double mu_eff_zero_overlap = 0; // largest |mu_eff| in the zero-overlap limit over rx
};

// `system` and `x_star` as returned by simple_shear_test (particle 0 = beta, 1 = mu, N even).
FrozenContactScan frozen_contact_scan(const DpmSystem& system, const Eigen::VectorXd& x_star, int horizontal,
                                      int vertical);

} // namespace softgrain::dpm
