// DPM section 9.4.2, Fig. 9.13(b, e, f): compression of a jammed smooth-disk packing is reversible along an
// elastic branch and irreversible at a rearrangement (a discontinuity of P(phi), a changed contact network).
// Also the contact network of disks (eq. 9.4: a contact is an overlap) under periodic minimum images.
#include "dpm/protocols/rearrangement.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/relax/newton_relax.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

TEST_CASE("disk contacts are the overlapping pairs, across the periodic boundary too [DPM eq. (9.4)]")
{
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.box = Eigen::Vector2d(10, 10);
    Eigen::VectorXd x;
    const auto disk = [&](double px, double py, double sigma) {
        Eigen::Matrix2Xd c(2, 1);
        c << px, py;
        s.add_particle(c, sigma, ShapeParameters{}, x);
    };
    disk(0.2, 5.0, 1.0);  // 0: touches 1 through the left/right boundary (r = 0.95 < sigma = 1)
    disk(9.25, 5.0, 1.0); // 1
    disk(1.2, 5.0, 1.4);  // 2: overlaps 0 by 0.2 (sigma_02 = 1.2, r = 1.0)
    disk(5.0, 5.0, 1.0);  // 3: alone
    const ContactNetwork all = disk_contacts(s, x, 0.0);
    CHECK(all == ContactNetwork{{0, 1}, {0, 2}});
    // Threshold between the two overlaps (0.05 and 0.2): only the deeper contact counts.
    CHECK(disk_contacts(s, x, 0.1) == ContactNetwork{{0, 2}});
    const NetworkChange change = compare_networks(all, ContactNetwork{{0, 2}, {2, 3}}, 4);
    CHECK(change.only_before == std::vector<ContactPair>{{0, 1}});
    CHECK(change.only_after == std::vector<ContactPair>{{2, 3}});
    CHECK(change.particles_changed == 4);
}

TEST_CASE("a compression step is reversible on an elastic branch and not at a rearrangement [DPM Fig. 9.13]")
{
    RearrangementOptions o;
    o.jam.particles = 32;
    o.jam.pressure_onset = 1e-6;
    o.jam.seed = 1;
    const RearrangementResult r = find_rearrangement(o);
    REQUIRE(r.found);
    // The step before the rearrangement, compressed and expanded back: the same packing, the same pressure.
    DpmSystem s = r.system;
    *s.box = r.previous.box;
    Eigen::VectorXd x = r.previous.x;
    const double phi = r.previous.phi;
    scale_packing(s, x, std::sqrt(phi / (phi + o.dphi)));
    CHECK(relax_fire(s, x, r.fire).converged);
    scale_packing(s, x, std::sqrt((phi + o.dphi) / phi));
    CHECK(relax_fire(s, x, r.fire).converged);
    const double p_round_trip = pressure(stress_tensor(s, x));
    // FIRE stops at an rms force of 1e-4 P_t per degree of freedom; the pressure of the relaxed packing is
    // then determined to about that fraction of the typical contact force (~P = 5e-4): 2e-7, with a factor
    // 10 for the sum over the contacts -> rel 2e-6 (measured 1.2e-7).
    CHECK_CLOSE(p_round_trip, r.previous.pressure, (Tolerance{2e-6, 0}));
    CHECK(disk_contacts(s, x, r.min_overlap) == r.previous.contacts);
    // At the rearrangement the round trip misses: the contact network and P(phi) stay changed, by far more
    // than the reproducibility above (1e-3 = 500 times its tolerance).
    CHECK(r.reversed.contacts != r.before.contacts);
    CHECK(std::abs(r.reversed.pressure - r.before.pressure) > 1e-3 * r.before.pressure);
    CHECK(std::abs(r.reversed.phi - r.before.phi) < 1e-12);
}
