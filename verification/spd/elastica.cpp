// The elastica reference of section 4.2 (ring between flat plates) against the small-deflection ring theory.
#include "spd/elastica.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <numbers>

using namespace softgrain::spd;
using softgrain::verification::Tolerance;

TEST_CASE("elastica at small strain: diametral point loads on a thin ring [Timoshenko: dD = (pi/4 - 2/pi) F "
          "R^3/EI]")
{
    const double pi = std::numbers::pi;
    const double eps = 1e-4;
    const ElasticaState s = elastica_ring_between_plates(eps);
    // Shortening of the loaded diameter 2 eps R = (pi/4 - 2/pi) F R^3/EI and lengthening of the other one
    // (4 - pi)/(2 pi) F R^3/EI (Timoshenko & Goodier; Roark). Nonlinear corrections are O(eps) relative:
    // 1e-3.
    CHECK_CLOSE(s.force, 2 * eps / (pi / 4 - 2 / pi), (Tolerance{1e-3, 0}));
    CHECK_CLOSE(s.width - 1, (4 - pi) / (2 * pi) * s.force / 2, (Tolerance{1e-3, 0}));
    // Inextensible: the area changes at second order only.
    CHECK(std::abs(s.volume - 1) < 10 * eps * eps);
    CHECK(s.contact_length == 0.0);
}

TEST_CASE("elastica flat contact appears once the curvature at the contact point vanishes, then grows")
{
    const double onset = elastica_flat_contact_onset();
    // No independent value to compare with; the shooting must be continuous across the onset: the two
    // branches (point contact, flat contact) give the same state there (to the root-finder tolerance).
    const ElasticaState below = elastica_ring_between_plates(onset - 1e-7);
    const ElasticaState above = elastica_ring_between_plates(onset + 1e-7);
    CHECK(below.contact_length == 0.0);
    CHECK(above.contact_length > 0.0);
    CHECK_CLOSE(above.force, below.force, (Tolerance{1e-5, 0}));
    CHECK_CLOSE(above.width, below.width, (Tolerance{1e-6, 0}));
    // The flat grows with strain and the force increases monotonically.
    double previous_force = 0, previous_contact = 0;
    for (double eps = onset + 0.02; eps < 0.6; eps += 0.05) {
        const ElasticaState s = elastica_ring_between_plates(eps);
        CHECK(s.force > previous_force);
        CHECK(s.contact_length > previous_contact);
        previous_force = s.force, previous_contact = s.contact_length;
    }
}

TEST_CASE("constant-perimeter ellipse of eq. (26) [SPD eq. (26), inventory table]")
{
    // Values of the inventory's derived table (b0 = 1), quoted to 4 decimals.
    CHECK_CLOSE(constant_perimeter_ellipse_width(0.9), 1.0952, (Tolerance{0, 6e-5}));
    CHECK_CLOSE(constant_perimeter_ellipse_width(0.5), 1.3931, (Tolerance{0, 6e-5}));
}
