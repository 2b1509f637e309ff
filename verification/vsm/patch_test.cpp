// Patch tests A, B, C (Frenning 2022, section 6.1, Table 1) on random irregular arrangements.
//
// The exact solution is the homogeneous state F = I + alpha M of eq. (52). Round-off bounds (the paper's
// Table 1 gives 1.6e-10 N, 3.1e-16 "mm", 2.1e-16 "mm"; see data/vsm/decisions.toml, patch-units):
//   A: a position rounding delta ~ eps |X| (|X| <= 1 m) produces a force K delta through the contact
//   stiffness
//      K ~ E h of eq. (50) and through F_a; summed over ~15-20 faces: bound 20 E h eps (1 m) (observed 5-6).
//   B, C: coordinates of O(1 m) carry eps; the damped run stops at the force floor of A, and the stiffness
//      condition number (~10 for 27-64 particles) amplifies: bound 50 eps (1 m) = 1.1e-14 m (observed <= 9
//      eps).
#include "vsm/patch_test.hpp"
#include "core/errors.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

using namespace softgrain;
using namespace softgrain::vsm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

PatchResult run(PatchVariant variant, int per_side, std::uint64_t seed, InternalForce internal)
{
    PatchSetup s;
    s.variant = variant;
    s.per_side = per_side;
    s.seed = seed;
    s.options.internal = internal;
    // The equilibrium does not depend on the ramp; a short ramp and hold keep the test fast (damping 40/s,
    // near critical for the slowest mode of the cube standing on X3 = 0; the error is at round-off after 3 s
    // of hold, and was still 1e-10 m with 100/s, overdamped). The scene uses the paper's 50 s.
    s.ramp_time = 2;
    s.hold_time = 3;
    s.damping = 40;
    return run_patch_test(s);
}

} // namespace

TEST_CASE(
    "patch test A: exact linear field gives force equilibrium of every particle [VSM Table 1, eq. (52)]")
{
    for (int per_side : {3, 4})
        for (std::uint64_t seed : {1u, 2u, 3u})
            for (InternalForce internal : {InternalForce::eq41, InternalForce::eq43}) {
                const PatchResult r = run(PatchVariant::A, per_side, seed, internal);
                const double bound = 20 * 1e6 * (1.0 / per_side) * round_off * 1.0;
                CAPTURE(per_side);
                CAPTURE(seed);
                CHECK_CLOSE(r.max_error, 0.0, (Tolerance{0, bound}));
            }
}

TEST_CASE("patch test B: displacement on every face, free particles reach the exact state [VSM Table 1]")
{
    // Random layouts of 27 and 64 particles; eq. (43) reduces to (42) when every ghost is prescribed (eq.
    // (45)).
    for (auto [per_side, seed, internal] :
         std::vector<std::tuple<int, std::uint64_t, InternalForce>>{{3, 1, InternalForce::eq41},
                                                                    {3, 2, InternalForce::eq41},
                                                                    {3, 3, InternalForce::eq41},
                                                                    {4, 1, InternalForce::eq41},
                                                                    {3, 1, InternalForce::eq43}}) {
        const PatchResult r = run(PatchVariant::B, per_side, seed, internal);
        CAPTURE(per_side);
        CAPTURE(seed);
        CHECK_CLOSE(r.max_error, 0.0, (Tolerance{0, 50 * round_off}));
    }
}

TEST_CASE("patch test C: displacement on X3 = 0, exact tractions elsewhere [VSM Table 1, eqs. (39), (42)]")
{
    for (auto [per_side, seed] : std::vector<std::pair<int, std::uint64_t>>{{3, 1}, {3, 2}, {3, 3}, {4, 1}}) {
        const PatchResult r = run(PatchVariant::C, per_side, seed, InternalForce::eq41);
        CAPTURE(per_side);
        CAPTURE(seed);
        CHECK_CLOSE(r.max_error, 0.0, (Tolerance{0, 50 * round_off}));
    }
}

TEST_CASE("patch test C is failed by eq. (43) with nominal tractions A_ab T_ab [finding, see decisions.toml]")
{
    // Eq. (43) is the exact gradient of V_int with least-squares ghosts (verified in forces.cpp); the
    // traction term A_ab T_ab of eq. (39) is not its work conjugate at free ghosts, so a constant stress is
    // not in equilibrium. The paper uses (43) only for dynamics; the static form (42) passes C (above).
    const PatchResult r = run(PatchVariant::C, 3, 1, InternalForce::eq43);
    INFO("eq. (43) patch test C error " << r.max_error << " m (exact displacement up to 2.4e-3 m)");
    CHECK(r.max_error > 1e-6);
}

TEST_CASE(
    "patch test relative error: A to E alpha h^2, B and C to the corner displacement alpha |M (1, 1, 1)| "
    "[VSM eq. (52)]")
{
    PatchSetup setup;
    setup.alpha = 1e-4;
    PatchResult result;
    result.max_error = 3e-9;
    result.force_scale = 11.0;
    // One division each: the results are within one rounding of the quotients written here; the corner
    // displacement alpha (1 + 2 + 3, 4 + 5 + 6, 7 + 8 + 9) = alpha (6, 15, 24) has norm alpha sqrt(837).
    setup.variant = PatchVariant::A;
    CHECK_CLOSE(patch_relative_error(setup, result), 3e-9 / 11.0, (Tolerance{round_off, 0}));
    for (PatchVariant variant : {PatchVariant::B, PatchVariant::C}) {
        setup.variant = variant;
        CHECK_CLOSE(patch_relative_error(setup, result), 3e-9 / (1e-4 * std::sqrt(837.0)),
                    (Tolerance{4 * round_off, 0}));
    }
    // A force scale that under- or overflows (E = 4.9e-324 Pa) leaves no error to measure: a diagnosis, not
    // 0/0.
    setup.variant = PatchVariant::A;
    for (double scale : {0.0, std::numeric_limits<double>::infinity()}) {
        result.force_scale = scale;
        CHECK_THROWS_AS(patch_relative_error(setup, result), NumericalError);
    }
}
