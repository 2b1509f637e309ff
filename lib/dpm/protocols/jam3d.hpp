// Jamming of a small bidisperse packing of 3D deformable particles in a periodic cubic box, DPM section 9.4
// (protocol P-DPM-JAM in 3D, for the packings of Figs. 9.15b and 9.16b): particles placed at random without
// overlap; isotropic compression (particle centres scaled, shapes kept) in steps Delta L/L, FIRE after each,
// undo and halve on overshoot, until 1 <= P/P_t < 1.01 (jam_schedule.hpp); P = Tr(Sigma)/3 of the 3D virial
// stress (system3d.hpp, the analogue of eq. 9.26). Then, optionally, further targets log-spaced up to
// pressure_max, each reached the same way from the previous packing (as in 2D, jam.hpp). A packing that is
// a saddle at a target (a negative eigenvalue of its Hessian) is moved off it and compressed again.
//
// Particles: 50:50 bidisperse, both on the same geodesic mesh, the large ones scaled by size_ratio in
// diameter; vertex diameter sigma = 1 and the small particles' mean edge 0.85 sigma (as the 2D polygons,
// decision dpm-3d-jam-packing). Shape energy eq. (9.2) with Table 9.1's models in 3D (model_shape3d):
// k_v v0^2 = k_c sigma^2 with v0 the small particles' volume (decision dpm-3d-jam-packing), k_a, k_b,
// gamma given in units of k_v v0^(2/3), k_v v0^2, k_v v0^(5/3) as for single particles (Fig. 9.15a).
// Pressure in k_v v0 (the paper's unit), eigenvalues in k_v v0^(4/3). Contacts rough or smooth (the virial
// stress includes either).
#pragma once

#include "core/fire.hpp"
#include "core/resources.hpp"
#include "dpm/analysis/packing_hessian3d.hpp"
#include "dpm/protocols/single_particle3d.hpp"
#include "dpm/relax/newton_relax.hpp"
#include "dpm/system/system3d.hpp"

#include <cstdint>
#include <string>

namespace softgrain::dpm {

struct Jam3dOptions
{
    ShapeModel model = ShapeModel::shell;
    int particles = 8;               // even: half small, half large
    std::string mesh = "geodesic42"; // mesh3d.hpp's names
    double size_ratio = 1.4;         // diameter ratio large/small
    double pressure_onset = 1e-7;    // P_t [k_v v0]
    double pressure_max = 1e-3;      // largest pressure of the compression after onset [k_v v0]
    int pressures = 0;               // targets log-spaced in (P_t, pressure_max] after onset; 0: onset only
    double A0_floppy = 1.04;         // floppy particles' preferred shape parameter A0^3D
    Stiffness3d stiffness;           // k_a, k_b, gamma (units above); k_v v0^2 = k_c sigma^2
    double start_fraction = 0.4;     // sum_mu (2 R_mu + sigma)^3 / L^3 at the random start
    std::uint64_t seed = 1;
    // rough: vertex spheres (eqs. 9.3-9.4); smooth: vertex against faces (interactions3d.hpp)
    InteractionKind interaction = InteractionKind::rough;
    // A packing that is a saddle at a target is moved off it and compressed to the target again, at most
    // this often per target (reach_stable_pressure, decision dpm-packing-minimum); 0: never checked.
    int saddle_escapes = 4;
    // [k_v v0^(4/3)]: below minus it (or the round-off bound) a mode is negative.
    double zero_threshold = 1e-10;
    long fire_budget = 1000000; // FIRE steps per relaxation; beyond them: NumericalError
    double jump_step = 0;       // BoxSchedule::jump_step (0: off)
    // The Hessian of FIRE's time step and of the saddle test (and of dpm.shear_modulus3d's Newton steps):
    // dense up to dense_hessian_limit3d degrees of freedom, sparse above (packing_hessian3d.hpp); tests and
    // dpm.bench force either.
    HessianStorage hessian = HessianStorage::automatic;
    // FIRE alone, or FIRE handing over to the Newton finisher where it crawls (newton_relax.hpp).
    Relaxation relaxation = Relaxation::fire;
    // FIRE's largest time step dt_max = fire_step / sqrt(lambda_max), lambda_max the largest eigenvalue of the
    // Hessian at the random start (omega_max dt_max = fire_step; velocity Verlet is stable below 2, and
    // contacts stiffen the packing later), at most 0.5. 0.3 keeps every stored path; 1 jams 8 x 42 shells
    // at P_t = 1e-7 in 2.9 times fewer FIRE iterations (reproductions/dpm/README.md).
    double fire_step = 0.3;
};

// A relaxed packing at one target pressure.
struct Jam3dState
{
    double phi = 0, pressure = 0; // packing_fraction3d, P [k_v v0]
    Eigen::VectorXd x;
    double box = 0; // its box side [sigma]
};

struct Jam3dResult : RelaxTally // the relaxations' cost
{
    DpmSystem3d system;             // with the box of the packing at P_t
    std::vector<Jam3dState> states; // P_t first, then the targets above it (Jam3dOptions::pressures)
    Eigen::VectorXd x;              // the relaxed packing at P_t
    double pressure_unit = 1;       // k_v v0 in k_c/sigma
    double eigenvalue_unit = 1;     // k_v v0^(4/3) in k_c
    double energy_unit = 1;         // k_v v0^2 in k_c sigma^2
    double length_unit = 1;         // v0^(1/3) in sigma
    double phi = 0;                 // packing_fraction3d
    double pressure = 0;            // P [k_v v0]
    long box_steps = 0;
    int saddle_escapes = 0; // moves off a saddle, over all targets
    long window_jumps = 0;  // overshoots of a target window kept and decompressed (Jam3dOptions::jump_step)
    FireOptions fire;       // the protocol's FIRE settings
};

Jam3dResult jam3d(const Jam3dOptions& options);

// Memory of a 3D packing of `particles` particles of the mesh named `mesh`: the larger of the protocol's
// Hessian in `storage` (two dense 3N x 3N matrices, or its sparse non-zeros) and the `dense_matrices` dense
// 3N x 3N matrices a scene needs after it (a dense spectrum: the matrix and its eigenvectors; 0: none).
MemoryEstimate packing3d_memory(double particles, const std::string& mesh, HessianStorage storage,
                                int dense_matrices);

} // namespace softgrain::dpm
