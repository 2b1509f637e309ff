#include "dpm/protocols/frozen_contact.hpp"

#include "core/errors.hpp"
#include "dpm/protocols/shear_friction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace softgrain::dpm {

namespace {

// mu translated rigidly so that r_{beta r, mu t} = (rx, ry).
Eigen::VectorXd place_mu(const DpmSystem& system, const Eigen::VectorXd& x_star, int r, int t,
                         const Eigen::Vector2d& displacement)
{
    Eigen::VectorXd x = x_star;
    const Particle& mu = system.particles[1];
    const Eigen::Vector2d shift = displacement - (x_star.segment<2>(2 * t) - x_star.segment<2>(2 * r));
    for (int v = mu.first; v < mu.first + mu.count; ++v)
        x.segment<2>(2 * v) += shift;
    return x;
}

} // namespace

FrozenContactScan frozen_contact_scan(const DpmSystem& system, const Eigen::VectorXd& x_star, int horizontal,
                                      int vertical)
{
    const Particle &beta = system.particles[0], &mu = system.particles[1];
    const int r = beta.first + beta.count / 2, r_next = r + 1, t = mu.first;
    FrozenContactScan scan;
    scan.star = x_star.segment<2>(2 * t) - x_star.segment<2>(2 * r);
    const double rx_first = x_star(2 * r_next) - x_star(2 * r); // t above r+1
    const auto at = [&](double rx, double ry) {
        return contact_force_on_mu(system, place_mu(system, x_star, r, t, Eigen::Vector2d(rx, ry)));
    };
    // Zero-overlap limit: the smallest ry above which U_int vanishes (bisection; U_int(0) > 0).
    const auto zero_overlap_height = [&](double rx) {
        double low = 0, high = 2 * beta.sigma;
        if (at(rx, low).energy <= 0 || at(rx, high).energy > 0)
            throw NumericalError("frozen contact scan: U_int at zero and two vertex diameters of separation",
                                 0,
                                 "the frozen configuration is not the smooth-contact regime of Appendix A");
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (low + high);
            (at(rx, mid).energy > 0 ? low : high) = mid;
        }
        return low;
    };
    const auto mu_eff = [](const ContactForce& f) { return f.tangential / f.normal; };
    scan.mu_eff_star = mu_eff(at(scan.star.x(), scan.star.y()));
    scan.min_force = std::numeric_limits<double>::infinity();
    for (int i = 0; i < horizontal; ++i) {
        const double rx = rx_first * (1 - double(i) / (horizontal - 1));
        const double ry_zero = zero_overlap_height(rx);
        for (int j = 0; j < vertical; ++j) {
            const double fraction = j + 1 < vertical ? double(j) / (vertical - 1) : 1 - 1e-6;
            const ContactForce f = at(rx, fraction * ry_zero);
            FrozenContactPoint point{rx, fraction * ry_zero, fraction, mu_eff(f), f.normal, f.tangential};
            scan.points.push_back(point);
            if (j + 1 < vertical)
                scan.min_force = std::min(scan.min_force, std::hypot(f.normal, f.tangential));
            else
                scan.mu_eff_zero_overlap = std::max(scan.mu_eff_zero_overlap, std::abs(point.mu_eff));
        }
    }
    // The line through the star: mu_eff against rx at the star's vertical separation, finely sampled.
    scan.mu_eff_max_at_star_height = scan.mu_eff_star;
    scan.rx_at_max = scan.star.x();
    const int fine = 20 * horizontal;
    for (int i = 0; i < fine; ++i) {
        const double rx = rx_first * (1 - double(i) / (fine - 1));
        const ContactForce f = at(rx, scan.star.y());
        if (f.normal > 0 && mu_eff(f) > scan.mu_eff_max_at_star_height) {
            scan.mu_eff_max_at_star_height = mu_eff(f);
            scan.rx_at_max = rx;
        }
    }
    return scan;
}

} // namespace softgrain::dpm
