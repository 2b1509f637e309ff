// Decision dpm-packing-minimum: a packing the jamming protocol leaves on a saddle is moved off it
// (leave_saddle) and compressed to the target again (reach_stable_pressure). Checked on energies whose
// saddles and minima are known in closed form, and on a one-dimensional packing whose jamming length
// changes when it leaves its saddle.
#include "core/fire.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/jam_schedule.hpp"
#include "support/quartic_valley.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::quartic_valley;

TEST_CASE("leave_saddle moves a saddle to the lowest energy along its negative mode [decision "
          "dpm-packing-minimum]")
{
    // U = -x^2/2 + x^4/4 + y^2/2: saddle at 0 (lambda = -1 along x), minima at x = +-1. Along x the energy
    // falls monotonically up to |x| = 1, so the lowest amplitude of the grid 1e-6 * 2^k <= 0.1 is the
    // largest, 1e-6 * 2^16 = 0.065536, exactly (powers of two).
    const EnergyWithDerivatives u = quartic_valley(0.0, -1.0, 1.0);
    Eigen::VectorXd x = Eigen::Vector2d::Zero();
    REQUIRE(leave_saddle(u, x, 1.0, 1.0, 1e-10, 0.1));
    CHECK(std::abs(x(0)) == doctest::Approx(0.065536).epsilon(1e-15));
    CHECK(x(1) == 0.0);
    CHECK(u(x, nullptr, nullptr) < 0.0);

    // Relaxed from there, the state falls into a minimum: x = +-1 with U = -1/4.
    FireOptions fire;
    fire.force_tolerance = 1e-12;
    fire_minimise(
        x,
        [&u](const Eigen::VectorXd& r, Eigen::VectorXd& f) {
            f.setZero(r.size());
            const double energy = u(r, &f, nullptr);
            f = -f;
            return energy;
        },
        fire);
    CHECK(std::abs(x(0)) == doctest::Approx(1.0).epsilon(1e-10));
    CHECK(u(x, nullptr, nullptr) == doctest::Approx(-0.25).epsilon(1e-12));
}

TEST_CASE("leave_saddle leaves a minimum, and a negative curvature below the energy's round-off, alone")
{
    // A minimum (U = x^2/2 + y^2/2), entered slightly off it: false, and x is not even polished.
    const Eigen::Vector2d start(1e-3, -2e-3);
    Eigen::VectorXd x = start;
    CHECK_FALSE(leave_saddle(quartic_valley(0.0, 1.0, 0.0), x, 1.0, 1.0, 1e-10, 0.1));
    CHECK(x == Eigen::VectorXd(start));

    // U = 1 - 1e-12 x^2/2 + x^4/4: lambda = -1e-12 lies below -1e-14 (a saddle by the count), but the
    // deepest point along x, at x^2 = 1e-12, lies 1e-24/4 below U(0) = 1, far below its round-off
    // 2 eps = 4.4e-16: no amplitude lowers U, and nothing moves (as on the 2D floppy packing of
    // DPM-Fig9.14def).
    x.setZero();
    CHECK_FALSE(leave_saddle(quartic_valley(1.0, -1e-12, 1.0), x, 1.0, 1.0, 1e-14, 0.1));
    CHECK(x.isZero(0.0));
}

TEST_CASE("reach_stable_pressure compresses again after leaving a saddle [decision dpm-packing-minimum]")
{
    // A one-dimensional packing of box side L: P = max(0, L_j - L) with jamming length L_j = 1 in its first
    // configuration, a saddle, and L_j = 0.98 after leaving it (the packing relaxes to a looser state, as
    // the 16 x 42 shell packing does, whose pressure fell from 1e-7 to 3.5e-12).
    double L = 1.05, saved_L = L, jamming_length = 1.0;
    int checks = 0;
    const CompressiblePacking packing{[&] { return std::max(0.0, jamming_length - L); },
                                      [&](double f) { L *= f; },
                                      [](long) { return 1L; },
                                      [&] { saved_L = L; },
                                      [&] { L = saved_L; },
                                      [&] {
                                          ++checks;
                                          if (jamming_length < 1.0) return false;
                                          jamming_length = 0.98;
                                          return true;
                                      }};
    const double target = 1e-4;
    BoxSchedule schedule;
    schedule.onset = target;
    int escapes = 0;
    reach_stable_pressure(target, schedule, packing, 4, escapes);
    CHECK(escapes == 1);
    CHECK(checks == 2); // the second state is a minimum
    CHECK(packing.pressure() >= target);
    CHECK(packing.pressure() < 1.01 * target);
    CHECK(L < 0.98);

    // With no moves allowed the protocol keeps its first state, on the saddle.
    L = 1.05;
    jamming_length = 1.0;
    escapes = 0;
    BoxSchedule fresh;
    fresh.onset = target;
    reach_stable_pressure(target, fresh, packing, 0, escapes);
    CHECK(escapes == 0);
    CHECK(L > 0.99);
    CHECK(packing.pressure() >= target);
}
