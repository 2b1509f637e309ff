// SD note [20]: the many-particle system. Two particles reproduce the pair dynamics (eqs. 7, 9); a line
// carries the same force in every bond; a symmetric triangle stays symmetric; the mean velocity is zero.
#include "sd/approach.hpp"
#include "sd/many.hpp"
#include "sd/pair_dynamics.hpp"
#include "support/tolerance.hpp"

#include <algorithm>
#include <cmath>

using namespace softgrain::sd;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {
const Material material;
} // namespace

TEST_CASE("two particles: relative velocity and gap rate equal the pair's X-dot (eq. 9) and h-dot (eq. 7) "
          "[SD note 20]")
{
    const double F = 1e-3;
    for (double h : {10.0, 0.1, 1e-4}) {
        CAPTURE(h);
        // Two particles at rest at gap h under F: the line of sd.many, positions 0 and X = 2R + h - 2 delta.
        const BalancedStart line = compressed_line(material, 2, F, h);
        const ManyParticleSystem& s = line.system;
        const double X = line.distance;
        const ManyParticleRates many = many_particle_rates(s, 0.0, line.positions, {h});
        const PairRates pair = soft_dynamics_rates(s.laws, 1.0, X, h, F, 0.0);
        // Same formulas, one linear solve: agreement to round-off of the solve (condition ~1).
        CHECK_CLOSE(many.velocity[1] - many.velocity[0], pair.X_dot, (Tolerance{1e3 * round_off, 0.0}));
        CHECK_CLOSE(many.gap_rate[0], pair.h_dot, (Tolerance{1e3 * round_off, 0.0}));
        CHECK(std::abs(many.velocity[0] + many.velocity[1]) <= 1e3 * round_off * std::abs(pair.X_dot));
        CHECK(many.residual <= 1e3 * round_off);
    }
}

TEST_CASE("a line of 5 compressed at its ends: every gap follows the pair under the same force; mean "
          "velocity 0 [note 20]")
{
    const double F = 1e-3, h0 = 1.0;
    const BalancedStart line = compressed_line(material, 5, F, h0);
    const ManyParticleSystem& s = line.system;
    const double delta0 = line.deflection;
    const std::vector<double>& x = line.positions;
    const ApproachProblem pair{material, s.laws, constant_loading(F), h0, 1e-3};
    const double t_end = approach_time_reference(pair, h0, 1e-3);
    long steps = 0;
    const auto samples =
        integrate_many(s, x, std::vector<double>(4, h0), {0.01 * t_end, 0.1 * t_end, 0.5 * t_end, t_end},
                       1e-4, 1e-10, delta0, steps);
    REQUIRE(samples.size() == 5);
    for (const ManySample& m : samples) {
        CAPTURE(m.t);
        double mean = 0, scale = 0;
        for (double v : m.rates.velocity)
            mean += v / 5, scale = std::max(scale, std::abs(v));
        CHECK(std::abs(mean) <= 1e3 * round_off * scale); // the replaced equation, to round-off
        for (std::size_t b = 0; b < m.gaps.size(); ++b) {
            // Every bond carries F (statics of a line) and so follows t(h) of the pair; the reference is the
            // quadrature of eq. (7) from h0 (1e-13), the integration has rk8pd tolerance 1e-10 over ~1e2
            // steps.
            const double t_ref = m.gaps[b] < h0 ? approach_time_reference(pair, h0, m.gaps[b]) : 0.0;
            CHECK(std::abs(m.rates.gap_rate[b]) * std::abs(m.t - t_ref) / m.gaps[b] <= 1e-7);
            CHECK_CLOSE(m.rates.pair_force[b], F, (Tolerance{1e-7, 0.0}));
        }
    }
}

TEST_CASE("a triangle pushed to its centre stays symmetric, bonds carry F/sqrt3, zero mean velocity and "
          "rotation [note 20]")
{
    const double F = 1e-2, h0 = 0.5, Fb = F / std::sqrt(3.0);
    ManyParticleSystem s{material, paper_contact_laws(material), 2, {{0, 1}, {1, 2}, {2, 0}}, {}};
    const double delta0 = balanced_deflection(s.laws, h0, Fb);
    const double rho = (2 + h0 - 2 * delta0) / std::sqrt(3.0);
    std::vector<double> x;
    for (int i = 0; i < 3; ++i) {
        // A generic orientation, not pushed_triangle's (particle 0 on the y axis): nothing may depend on the
        // axes.
        const double angle = 0.3 + 2 * std::acos(-1.0) * i / 3;
        x.push_back(rho * std::cos(angle));
        x.push_back(rho * std::sin(angle));
    }
    const std::vector<double> x0 = x;
    s.external = [F, x0](double, std::vector<double>& force, std::vector<double>& rate) {
        for (int i = 0; i < 3; ++i) {
            const double r = std::hypot(x0[2 * i], x0[2 * i + 1]);
            force[2 * i] = -F * x0[2 * i] / r;
            force[2 * i + 1] = -F * x0[2 * i + 1] / r;
        }
        std::fill(rate.begin(), rate.end(), 0.0);
    };
    const ApproachProblem pair{material, s.laws, constant_loading(Fb), h0, 1e-3};
    const double t_end = approach_time_reference(pair, h0, 1e-3);
    long steps = 0;
    const auto samples =
        integrate_many(s, x, std::vector<double>(3, h0), {0.1 * t_end, t_end}, 1e-4, 1e-10, delta0, steps);
    for (const ManySample& m : samples) {
        CAPTURE(m.t);
        const auto [lo, hi] = std::minmax_element(m.gaps.begin(), m.gaps.end());
        CHECK((*hi - *lo) / *lo <= 1e-8); // symmetric to the solver tolerance (rk8pd, 1e-10 per step)
        double vx = 0, vy = 0, spin = 0, scale = 0;
        for (int i = 0; i < 3; ++i) {
            vx += m.rates.velocity[2 * i];
            vy += m.rates.velocity[2 * i + 1];
            spin += m.positions[2 * i] * m.rates.velocity[2 * i + 1] -
                    m.positions[2 * i + 1] * m.rates.velocity[2 * i];
            scale = std::max(scale, std::hypot(m.rates.velocity[2 * i], m.rates.velocity[2 * i + 1]));
        }
        CHECK(std::hypot(vx, vy) <= 1e3 * round_off * scale);
        CHECK(std::abs(spin) <= 1e3 * round_off * scale * rho);
        // Each particle moves radially (towards the centre): velocity parallel to its position.
        for (int i = 0; i < 3; ++i) {
            const double cross = m.positions[2 * i] * m.rates.velocity[2 * i + 1] -
                                 m.positions[2 * i + 1] * m.rates.velocity[2 * i];
            CHECK(std::abs(cross) <= 1e-8 * scale * rho);
        }
        for (std::size_t b = 0; b < 3; ++b) {
            CHECK_CLOSE(m.rates.pair_force[b], Fb, (Tolerance{1e-7, 0.0}));
            const double t_ref = m.gaps[b] < h0 ? approach_time_reference(pair, h0, m.gaps[b]) : 0.0;
            CHECK(std::abs(m.rates.gap_rate[b]) * std::abs(m.t - t_ref) / m.gaps[b] <= 1e-7);
        }
    }
}

TEST_CASE("sd.many's balanced starts: every bond of the line carries F, of the triangle F/sqrt3, at h0 "
          "[note 20, eqs. 1, 2]")
{
    const double F = 1e-3, h0 = 1.0;
    for (const BalancedStart& start :
         {compressed_line(material, 5, F, h0), pushed_triangle(material, F, h0)}) {
        CAPTURE(start.system.dimension);
        CHECK(start.pair_force == (start.system.dimension == 1 ? F : F / std::sqrt(3.0)));
        const std::vector<double> gaps(start.system.bonds.size(), h0);
        const ManyParticleRates rates = many_particle_rates(start.system, 0.0, start.positions, gaps);
        // The deflection is recovered from the centre distance |X| = 2R + h0 - 2 delta0 (eq. 2), whose
        // rounding (a few eps |X|, the triangle's corners through cos and sin) is relative error
        // eps |X| / delta0 of delta0 and, through F_ela(delta) of order delta^(3/2), of the bond force.
        const double tolerance = 10 * round_off * start.distance / start.deflection;
        for (std::size_t bond = 0; bond < gaps.size(); ++bond) {
            CAPTURE(bond);
            CHECK_CLOSE(rates.deflection[bond], start.deflection, (Tolerance{tolerance, 0.0}));
            CHECK_CLOSE(rates.pair_force[bond], start.pair_force, (Tolerance{tolerance, 0.0}));
        }
    }
}
