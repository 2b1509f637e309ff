// Shear modulus by Lees-Edwards strain steps in 3D (DPM sec. 9.4.3, Fig. 9.16b) against the analytic modulus
// of a compressed face-centred cubic crystal of one-vertex particles (spheres of diameter sigma with the
// linear repulsion of eq. 9.4), sheared in x along y about its cubic axes. Every site is a centre of
// inversion, so the response is affine; a bond d = (x, y, z) of length r and compressive force
// f = k (sigma - r) contributes d^2U/dgamma^2 = k (x y/r)^2 - f (y^2/r - x^2 y^2/r^3). Of the 12 neighbours
// at distance a, the 4 in the xy plane give k a^2/4 - f a/4 each, the 4 in the yz plane -f a/2 each, those
// in the xz plane nothing; per site (half the bonds, volume a^3/sqrt(2)):
//   G = (sqrt(2)/a^3) (k a^2/2 - 3 f a/2) = k/(sqrt(2) a) - (3/4) P,   P = (1/3V) sum f r = 2 sqrt(2) f/a^2.
#include "core/errors.hpp"
#include "dpm/protocols/shear_modulus.hpp"
#include "support/packings.hpp"
#include "support/run_softgrain.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <string>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::fcc_crystal;
using softgrain::verification::Tolerance;

TEST_CASE("3D G from Lees-Edwards steps of 5e-9 = k_c/(sqrt(2) a) - 3/4 P for a compressed fcc sphere "
          "crystal, with dense and sparse Newton steps [DPM sec. 9.4.3, eq. (9.4)]")
{
    // The sparse path (polish_newton_sparse) is what packings above dense_hessian_limit3d degrees of freedom
    // take; forced here on the crystal (324 degrees of freedom) so that both meet the analytic G.
    for (const HessianStorage storage : {HessianStorage::dense, HessianStorage::sparse})
        for (double a : {0.999, 0.98}) {
            Eigen::VectorXd x;
            const DpmSystem3d s = fcc_crystal(a, 3, x);
            const double f = s.kc * (1 - a);
            const double p = pressure3d(stress_tensor3d(s, x));
            const ShearModulusResult g = shear_modulus(s, x, 5e-9, 2, 1e-13, {}, storage);
            CAPTURE(a);
            CAPTURE(storage == HessianStorage::sparse);
            // Analytic pressure of the crystal first (checks the setup: 12 contacts per site, none beyond).
            CHECK_CLOSE(p, 2 * std::sqrt(2.0) * f / (a * a), (Tolerance{1e-12, 0}));
            // Stress change per step G dgamma ~ 3.5e-9 against stress round-off ~1e-16 x 1e-2 and the O(dgamma)
            // nonlinearity of the stress (relative 5e-9): 1e-5 relative covers both with margin.
            CHECK_CLOSE(g.modulus, s.kc / (std::sqrt(2.0) * a) - 0.75 * p, (Tolerance{1e-5, 0}));
        }
}

TEST_CASE("dpm.shear_modulus3d refuses A0 below the mesh's own shape parameter, naming A0 and its old name "
          "[DPM sec. 9.3.1: A_min^3D(icosahedron) = 1.0984]")
{
    // Exit 2 before any packing is jammed; the message names the scene's key, its value and the bound.
    const auto [exit_code, output] =
        verification::run_softgrain("run dpm.shear_modulus3d --set model=all --set A0=1.05 --set "
                                    "packings=1 --out /tmp/softgrain-dpm-shear-modulus3d-input --quiet");
    CAPTURE(output);
    CHECK(exit_code == exit_bad_input);
    CHECK(output.find("'A0' (old name 'A0_floppy') = '1.05") != std::string::npos);
    CHECK(output.find("1.098") != std::string::npos); // the icosahedron's A_min^3D
}
