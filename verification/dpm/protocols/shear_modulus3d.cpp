// Shear modulus by Lees-Edwards strain steps in 3D (DPM sec. 9.4.3, Fig. 9.16b) against the analytic modulus
// of a compressed face-centred cubic crystal of one-vertex particles (spheres of diameter sigma with the
// linear repulsion of eq. 9.4), sheared in x along y about its cubic axes. Every site is a centre of
// inversion, so the response is affine; a bond d = (x, y, z) of length r and compressive force
// f = k (sigma - r) contributes d^2U/dgamma^2 = k (x y/r)^2 - f (y^2/r - x^2 y^2/r^3). Of the 12 neighbours
// at distance a, the 4 in the xy plane give k a^2/4 - f a/4 each, the 4 in the yz plane -f a/2 each, those
// in the xz plane nothing; per site (half the bonds, volume a^3/sqrt(2)):
//   G = (sqrt(2)/a^3) (k a^2/2 - 3 f a/2) = k/(sqrt(2) a) - (3/4) P,   P = (1/3V) sum f r = 2 sqrt(2) f/a^2.
#include "core/errors.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/protocols/shear_modulus.hpp"
#include "dpm/protocols/shear_modulus_ensemble.hpp"
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

// The 3D protocol stops on the pressure Tr(Sigma)/3 alone, and in a box of 8 icosahedra the packing of
// DPM-Fig9.16b's third shell member (seed 3) reaches its first two pressures with every contact force along
// z: Sigma_xx and Sigma_yy are round-off against Sigma_zz = 3 P. At the second (P = 4.7e-4 k_v v0) no
// contact crosses the box boundary along y, so U does not depend on the Lees-Edwards strain: the affine
// term, Xi and G vanish exactly (linear response), and the strain steps give G ~ 1e-9 of round-off. The
// summary's tables show it as stress_min ~ 0 (smallest_normal_stress); once compressed to 1e-2 the packing
// is loaded along every axis (stress_min 0.84) and stiff (G = 0.029 k_v v0).
TEST_CASE("a packing jammed along z alone: stress_min ~ 0 and G = 0 exactly [DPM sec. 9.4.3, Fig. 9.16b]")
{
    Jam3dOptions o;
    o.particles = 8;
    o.mesh = "icosahedron";
    o.model = ShapeModel::shell;
    o.pressure_onset = 1e-4;
    o.pressure_max = 1e-2;
    o.pressures = 3;
    o.seed = 3;
    const Jam3dResult j = jam3d(o);
    const ModulusMember m = moduli_at_states(j.system, j.states, j.pressure_unit, 5e-9, 2, 1e-10);
    REQUIRE(m.normal_stress_min.size() == 4);
    MESSAGE("stress_min " << m.normal_stress_min[0] << " " << m.normal_stress_min[1] << " "
                          << m.normal_stress_min[2] << " " << m.normal_stress_min[3] << "; G " << m.modulus[1]
                          << ", linear " << m.modulus_linear[1] << "; at 1e-2 " << m.modulus[3]);
    // Round-off of an unloaded axis: contact forces below FIRE's tolerance (rms 1e-4 P_t per coordinate)
    // give |Sigma_aa| / P below 1e-4; the loaded axis alone gives 3.
    CHECK(std::abs(m.normal_stress_min[1]) < 1e-4);
    CHECK(m.modulus_linear[1] == 0.0);
    CHECK(std::abs(m.modulus[1]) < 1e-6 * m.modulus[3]);
    CHECK(m.normal_stress_min[3] > 0.1);
    CHECK(m.modulus[3] > 0);
}
