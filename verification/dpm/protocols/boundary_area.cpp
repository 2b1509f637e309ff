// DPM Fig. 9.18(f): a boundary with the area term of eq. (9.1) and preferred shape parameter A0 keeps A0
// while it shrinks around the disks (l0 and sqrt(a0) scaled together), so at jamming its shape parameter
// p^2/(4 pi a) equals A0 up to the stretch the jamming energy allows:
//   k_a/2 (a - a0)^2 <= U  ->  |a - a0| <= sqrt(2 U/k_a);   sum k_l/2 (l_i - l0)^2 <= U  ->  |p - N l0| <=
//   sqrt(2 N U/k_l); with U < 2e-8 k_c d^2, N = 100, a0 ~ 20 d^2, p ~ 16 d: relative errors 1e-5 (a)
//   and 1.3e-4 (p), so A within 3e-4 of A0 (2 dp/p + da/a), rounded up to 5e-4.
#include "dpm/protocols/boundary_jam.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

TEST_CASE("boundary with k_a > 0 jams at its preferred shape parameter A0 [DPM Fig. 9.18(f), eq. 9.1]")
{
    for (const double A0 : {1.05, 1.09}) {
        BoundaryJamOptions o;
        o.ka = 1;
        o.A0 = A0;
        const BoundaryJamResult r = jam_in_boundary(o);
        const Particle& ring = r.system.particles.back();
        const double p = particle_perimeter(r.x, ring.first, ring.count),
                     a = particle_area(r.x, ring.first, ring.count);
        CHECK(r.energy < 2e-8);
        CHECK_CLOSE(shape_parameter(p, a), A0, (Tolerance{5e-4, 0}));
        // The preferred values themselves still define A0 exactly (the shrink keeps the ratio).
        CHECK_CLOSE(std::pow(ring.count * ring.shape.l0, 2) / (4 * std::numbers::pi * ring.shape.a0), A0,
                    (Tolerance{100 * verification::round_off, 0}));
    }
}
