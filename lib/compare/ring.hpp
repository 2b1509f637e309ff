// compare.ring: one physical problem solved by two methods. A thin elastic ring (radius R, wall thickness
// h, Young modulus E, Poisson ratio nu) is squeezed between two rigid frictionless plates, quasi-statically,
// to the strain eps = 1 - b/b0 (b the plate gap of the mid-line, b0 = 2R), by
//   * SPD (Trivino et al., section 4): the eta = 0 elastic ring of lib/spd/ring.hpp, relaxed by damped
//     velocity Verlet after each wall increment (spd::ring_compression, unchanged);
//   * DPM (MacKeith et al., eq. 9.1): the 2D shell of edge and bending penalties without area term, relaxed
//     by FIRE between two plates of vertex repulsion (dpm::compress_between_plates).
// Both take their constants from the same E, h through SPD eqs. (10)-(11): edge spring
// k_s = k_l = E h/(1-nu^2) [N/m] and hinge k_b = E h^3/(12(1-nu^2)) [N m], so that both have the bending
// rigidity B = k_b l0 and the stretching rigidity k_s l0 (l0 = 2R sin(pi/N)), with
// B/(k_s l0 R^2) = (h/R)^2/12 as for a continuous shell (decision compare-ring-mapping). The vertex disks
// have diameter h and touch the plates through a linear spring k_s in both (decision compare-ring-plates).
//
// The reference is the inextensible elastica (lib/spd/elastica.hpp) at the same eps. Observables, per
// recorded strain: F R^2/B (F the force on one plate), a/b0 (a the width of the vertex cloud), V/V0 (area
// ratio, V0 the undeformed polygon's) and L_c/b0, L_c the distance between the outermost vertices that
// touch the top plate (the elastica: the flat length 2c).
#pragma once

#include "core/vtk.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace softgrain::compare {

enum class RingMethod { spd, dpm };

struct RingComparisonSetup
{
    RingMethod method = RingMethod::spd;
    int nodes = 128;                     // N, a multiple of 4 (a vertex on each plate at eps = 0)
    double radius = 1;                   // R [m]
    double E = 1e6, nu = 0.3, h = 0.005; // [Pa], 1, [m]
    double dt_factor = 0.5;              // SPD: dt/dt_c
    double strain_max = 0.6, strain_step = 0.05;
    // Relaxation criterion: largest unbalanced force on a degree of freedom below relax_tolerance B/R^2
    // (SPD directly; DPM through FIRE's rms force, required below that bound over sqrt(2N)).
    double relax_tolerance = 1e-5;
};

struct RingObservation
{
    double strain = 0;         // eps = 1 - b/b0
    double force = 0;          // F R^2/B
    double width = 0;          // a/b0
    double volume = 0;         // V/V0
    double contact_length = 0; // L_c/b0
};

struct RingComparison
{
    std::vector<RingObservation> states; // eps = 0, strain_step, ..., strain_max (loading)
    double bending_rigidity = 0;         // B = k_b l0 [N m^2]
    long steps = 0;                      // SPD time steps or DPM FIRE iterations
    // SPD only (NaN for DPM): the time step, dt_c = sqrt(m/k_max) and the stability limit of the scheme.
    double dt = 0, dt_critical = 0, dt_stable = 0;
};

// Sees each recorded state (eps = 0, strain_step, ...) with its datasets for ParaView (`run --vtk`): SPD the
// ring, the walls and the contacts (spd::shell_frame: "particles", "walls", "contacts"); DPM the shell
// (dpm::dpm_particles: "particles") and the plates (dpm::plates: "plates", bottom at y = 0).
using RingFrameObserver = std::function<void(const RingObservation&, std::vector<vtk::Part>)>;

// Runs the compression; progress(fraction) after each strain increment. Throws NumericalError (exit 3) when
// a relaxation fails or the SPD time step is above its stability limit.
RingComparison compress_ring(const RingComparisonSetup& setup, const std::function<void(double)>& progress,
                             const RingFrameObserver& frame = {});

// Deviations from the elastica at the observation's strain: relative in F and a, absolute in V/V0 and
// L_c/b0.
struct RingErrors
{
    double force = 0, width = 0, volume = 0, contact_length = 0;
};
RingErrors elastica_errors(const RingObservation& observation);

// Whether a strain is one of those the observables are reported at: eps = 0.1, 0.2, ...
bool reported_strain(double strain);

// The largest deviations from the elastica over the states at the reported strains; absent without such a
// state (strain_max < 0.1).
std::optional<RingErrors> largest_elastica_errors(const RingComparison& comparison);

} // namespace softgrain::compare
