// Reference solution for SPD section 4.2: an inextensible elastic ring (elastica, bending rigidity EI, radius
// R) squeezed between two flat frictionless plates (the paper's ref. [37]; the classical elastica problem).
//
// By symmetry one quarter of the ring is solved, from the top of the ring (or the end of the flat contact)
// to the lateral point where the tangent is vertical. With psi the clockwise tangent angle and s the arc
// length, x' = cos psi, y' = -sin psi and psi' = kappa(s), where the bending moment balances the wall
// force F (per plate; each half-ring carries F/2 through its two lateral sections):
//   phase 1, point contact:  kappa = kappa_0 + lambda x, 0 <= kappa_0 <= 1/R, lambda = F/(2 EI);
//   phase 2, flat contact of half-length c: kappa = lambda (x - c) on the free arc (kappa = 0 at lift-off,
//            where the moment is continuous with the flat part); the plate force is concentrated at the two
//            ends of the flat (no pressure inside it: constant moment, zero shear).
// Unknown lambda is fixed by psi = pi/2 at the quarter arc length pi R/2 - c (inextensibility); the wall gap
// b = 2 int sin psi ds, the width a = 2 x(end), the area 4 int x sin psi ds. Solved with GSL (rk8pd ODE
// steps, Brent root finding) to ~1e-9.
// Sign: the strain eps = 1 - b/b0 and the plate force F are positive in compression. Units: F R^2/EI, a/b0,
// L_c/b0 and V/V0 are dimensionless, so one solution serves every R and EI.
// Valid for an inextensible, unshearable ring (thin: h/R -> 0) and frictionless plates, for 0 <= eps < 0.9;
// a ring of finite thickness departs from it by its stretching, O((h/R)^2) in F.
#pragma once

namespace softgrain::spd {

struct ElasticaState
{
    double strain = 0;         // eps = 1 - b/b0, b0 = 2R
    double width = 0;          // a/b0
    double contact_length = 0; // L_c/b0 = 2c/(2R) (length of the flat contact)
    double volume = 0;         // V/V0 (area ratio)
    double force = 0;          // F R^2 / EI (force per plate)
};

// The elastica at the strain eps in [0, 0.9).
ElasticaState elastica_ring_between_plates(double strain);

// The strain at which the flat contact appears (the curvature at the contact point reaches 0).
double elastica_flat_contact_onset();

// SPD eq. (26), ellipse of constant perimeter (Ramanujan): 2 b0 = 3(a + b) - sqrt((a + 3b)(3a + b)), solved
// for a/b0 >= b/b0 at a given b/b0 in (0, 1] (full axis lengths).
double constant_perimeter_ellipse_width(double b_over_b0);

} // namespace softgrain::spd
