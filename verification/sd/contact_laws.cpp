// SD contact laws, eqs. (3)-(5): partial derivatives, the three viscous limits, the balanced deflection.
#include "sd/contact_laws.hpp"
#include "sd/pair_dynamics.hpp"
#include "sd/scaling.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <numbers>

using namespace softgrain::sd;
using softgrain::verification::Tolerance;

namespace {
const Material material{1.3, 2.0, 0.7, 4.0 / 9.0}; // R, E, eta not 1, so that a misplaced factor shows
const double pi = std::numbers::pi;
} // namespace

TEST_CASE(
    "partial derivatives F_a, F_delta, a_h, a_delta of eqs. (3), (5) match central differences [SD eq. (8)]")
{
    for (double h : {1e-4, 0.05, 1.0, 30.0})
        for (double delta : {1e-6, 1e-3, 0.2}) {
            CAPTURE(h);
            CAPTURE(delta);
            const InteractionSize s = interaction_size_eq5(material, h, delta);
            // Steps: relative 1e-6 of the scale on which a varies (h-bar + delta), but never across delta = 0
            // (|delta| kink).
            const double eh = 1e-6 * h,
                         ed = std::min(1e-6 * (effective_gap(material.radius, h) + delta), 0.5 * delta);
            const double a_h = (interaction_size_eq5(material, h + eh, delta).a -
                                interaction_size_eq5(material, h - eh, delta).a) /
                               (2 * eh);
            const double a_d = (interaction_size_eq5(material, h, delta + ed).a -
                                interaction_size_eq5(material, h, delta - ed).a) /
                               (2 * ed);
            // Central differences with a relative step 1e-6: truncation ~1e-12, round-off ~1e-10 relative.
            CHECK_CLOSE(s.d_h, a_h, (Tolerance{1e-7, 0.0}));
            CHECK_CLOSE(s.d_delta, a_d, (Tolerance{1e-7, 0.0}));
            const ElasticResponse e = elastic_force_eq3(material, s.a, delta);
            const double ea = 1e-6 * s.a;
            CHECK_CLOSE(e.d_a,
                        (elastic_force_eq3(material, s.a + ea, delta).force -
                         elastic_force_eq3(material, s.a - ea, delta).force) /
                            (2 * ea),
                        (Tolerance{1e-7, 0.0}));
            CHECK_CLOSE(e.d_delta,
                        (elastic_force_eq3(material, s.a, delta + ed).force -
                         elastic_force_eq3(material, s.a, delta - ed).force) /
                            (2 * ed),
                        (Tolerance{1e-7, 0.0}));
        }
}

TEST_CASE("zeta of eq. (4) with a of eq. (5) reproduces the Stokes, Poiseuille and Hertz drags [SD text "
          "before eq. 4]")
{
    const double R = material.radius, eta = material.viscosity;
    const auto zeta = [&](double h, double delta) {
        return friction_coefficient_eq4(material, interaction_size_eq5(material, h, delta).a, h);
    };
    // Stokes: with delta = 0, zeta = 6 pi eta R^2/h-bar = 6 pi eta R (1 + R/h) exactly: correction 1e-4 at h
    // = 1e4 R.
    CHECK_CLOSE(zeta(1e4 * R, 0.0), 6 * pi * eta * R, (Tolerance{2e-4, 0.0}));
    // Poiseuille: 6 pi eta R^2/h-bar = 6 pi eta R^2/h (1 + h/R): correction h/R = 1e-5.
    const double hp = 1e-5 * R;
    CHECK_CLOSE(zeta(hp, 0.0), 6 * pi * eta * R * R / hp, (Tolerance{2e-5, 0.0}));
    // Hertz: 3 pi eta a^4/(2 h^3) with a = sqrt(2 R delta) for delta >> h; corrections h/delta and h/R =
    // 1e-6.
    const double hh = 1e-9 * R, delta = 1e-3 * R;
    const double a = std::sqrt(2 * R * delta);
    CHECK_CLOSE(zeta(hh, delta), 3 * pi * eta * std::pow(a, 4) / (2 * hh * hh * hh), (Tolerance{1e-5, 0.0}));
}

TEST_CASE("balanced deflection: Brent on eq. (1) equals the closed-form cubic root [SD eqs. (1), (3), (5)]")
{
    const ContactLaws laws = paper_contact_laws(material);
    for (double kappa : {1e-6, 1e-3, 0.3})
        for (double h : {1e-6, 1e-2, 1.0, 100.0}) {
            const double F = kappa * material.young_modulus * material.radius * material.radius;
            CAPTURE(kappa);
            CAPTURE(h);
            // Both are solved to ~1e-14 relative (Brent interval 1e-15, cubic polished by Newton).
            CHECK_CLOSE(balanced_deflection(laws, h, F), balanced_deflection_paper(material, h, F),
                        (Tolerance{1e-12, 0.0}));
            const double delta = balanced_deflection(laws, h, F);
            CHECK_CLOSE(elastic_force_eq3(material, interaction_size_eq5(material, h, delta).a, delta).force,
                        F, (Tolerance{1e-12, 0.0}));
        }
}

TEST_CASE("deflection limits: delta/R -> kappa/(alpha sqrt2) (Stokes), (kappa^2/(2 alpha^2))^(1/3) (Hertz) "
          "[SD Fig. 3a]")
{
    const double R = material.radius, alpha = material.alpha;
    const double kappa = 1e-4, F = kappa * material.young_modulus * R * R;
    // Stokes (h >> R): a^2 -> 2R^2, so alpha E R sqrt2 delta = F; a = R sqrt2 (1 - R/(2h) + delta/(2R)): 5e-5
    // at h = 1e4 R.
    CHECK_CLOSE(balanced_deflection_paper(material, 1e4 * R, F) / R, kappa / (alpha * std::sqrt(2.0)),
                (Tolerance{1e-4, 0.0}));
    // Hertz (h << delta): a^2 -> 2 R delta; correction h/(3 delta) ~ 2e-7 at h = 1e-9 R.
    CHECK_CLOSE(balanced_deflection_paper(material, 1e-9 * R, F) / R,
                std::cbrt(kappa * kappa / (2 * alpha * alpha)), (Tolerance{1e-6, 0.0}));
    // Poiseuille (delta << h << R): delta/R = kappa/(alpha sqrt2) (h/R)^(-1/2); at kappa = 1e-7, h = 1e-3 R
    // the corrections are h/(2R) = 5e-4 and delta/(2h) = 2.5e-3.
    const double h = 1e-3 * R, kappa_p = 1e-7, F_p = kappa_p * material.young_modulus * R * R;
    CHECK_CLOSE(balanced_deflection_paper(material, h, F_p) / R,
                kappa_p / (alpha * std::sqrt(2.0)) / std::sqrt(h / R), (Tolerance{4e-3, 0.0}));
}
