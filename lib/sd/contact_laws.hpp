// Soft Dynamics (Rognon & Gay): the laws of one lubricated contact between two identical elastic spheres.
//
//   F_ela(a, delta) = alpha E a delta                                                (3)
//   F_vis = -zeta h-dot,  zeta(a, h) = 3 pi eta a^4 / (2 h-bar^3),  h-bar = R h/(R + h)  (4)
//   a(h, delta) = sqrt(2 R (h-bar + |delta|))                                        (5)
//
// The paper stresses that F_ela(a, delta), F_adh(a, h) and a(h, delta) "can be changed at will"; the
// dynamics (eqs. 7, 9) only need their values and partial derivatives. ContactLaws therefore holds them as
// replaceable functions; paper_contact_laws() gives the paper's choices (eqs. 3, 4, 5, F_adh = 0).
//
// Conventions (the paper's): h is the surface-to-surface gap (m), delta the surface deflection of each
// particle, positive in compression (m), a the radius of the interacting region (m). Forces are normal,
// positive when they push the particles apart (F_ext compressive, F_ela repulsive), in N. zeta in N s/m.
// Valid for h > 0 (zeta diverges as h-bar^-3 at contact) and small deflections delta << R (the paper leaves
// out delta ~ R, kappa > 1); a has a kink at delta = 0, where da/ddelta is taken as 0.
#pragma once

#include <functional>

namespace softgrain::sd {

// Material of two identical particles in a Newtonian fluid.
struct Material
{
    double radius = 1.0;        // R (m)
    double young_modulus = 1.0; // E (Pa)
    double viscosity = 1.0;     // eta (Pa s)
    double alpha = 4.0 / 9.0;   // geometrical constant of eq. (3), "4/9 for elastic solids"
};

// An elastic force and its partial derivatives, the F_a^ela and F_delta^ela of eq. (8).
struct ElasticResponse
{
    double force = 0;   // F_ela (N)
    double d_a = 0;     // dF_ela/da (N/m)
    double d_delta = 0; // dF_ela/ddelta (N/m)
};

// The size of the interacting region and its partial derivatives, the a_h and a_delta of eq. (8).
struct InteractionSize
{
    double a = 0;       // a (m)
    double d_h = 0;     // da/dh (1)
    double d_delta = 0; // da/ddelta (1)
};

struct ContactLaws
{
    std::function<ElasticResponse(double a, double delta)> elastic; // F_ela(a, delta)
    std::function<double(double a, double h)> remote;            // F_adh(a, h), not transmitted by the fluid
    std::function<InteractionSize(double h, double delta)> size; // a(h, delta)
    std::function<double(double a, double h)> friction;          // zeta(a, h) of F_vis = -zeta h-dot
};

// h-bar = R h / (R + h) (m), the interpolated gap of eqs. (4)-(5): h for h << R, R for h >> R.
double effective_gap(double radius, double h);

// SD eq. (3): F_ela = alpha E a delta, with dF/da = alpha E delta and dF/ddelta = alpha E a.
// A scaling form (Hertz: elastic energy ~ E a delta^2 in a volume of size a); valid for delta << R.
ElasticResponse elastic_force_eq3(const Material& m, double a, double delta);

// SD eq. (5): a = sqrt(2 R (h-bar + |delta|)), with da/dh = (R/a) dh-bar/dh = (R/a) R^2/(R + h)^2 and
// da/ddelta = R sign(delta)/a. Interpolates a = R sqrt(2) (Stokes), sqrt(2 R h) (Poiseuille),
// sqrt(2 R |delta|) (Hertz). Requires h > 0.
InteractionSize interaction_size_eq5(const Material& m, double h, double delta);

// SD eq. (4): zeta = 3 pi eta a^4 / (2 h-bar^3). With eq. (5) it reproduces exactly the Stokes drag
// 6 pi eta R (h >> R), the Poiseuille lubrication 6 pi eta R^2/h (delta << h << R) and the parallel-disk
// squeeze film 3 pi eta a^4/(2 h^3) (delta >> h). Requires h > 0.
double friction_coefficient_eq4(const Material& m, double a, double h);

// The paper's choices: eqs. (3), (4), (5) and no remote force (F_adh = 0).
ContactLaws paper_contact_laws(const Material& m);

} // namespace softgrain::sd
