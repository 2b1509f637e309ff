// Jammed packings of 2D deformable particles in a periodic square box (section 9.4, simplified onset
// criterion, decision dpm-jam-energy-onset): random non-overlapping placement, isotropic compression
// steps (particle centres scaled, shapes kept) each followed by FIRE; a step that brings the energy per
// particle above 2 U_t is undone and halved; stop at the first relaxed state with U_t < U/N < 2 U_t.
#pragma once

#include "dpm/system/system.hpp"

#include <cstdint>

namespace softgrain::dpm {

struct PackingOptions
{
    int particles = 7;
    int nodes = 5;
    double C = 0.726; // R/sigma (sigma = 1, k_c = 1)
    InteractionKind interaction = InteractionKind::rough;
    ShapeModel model = ShapeModel::shell;
    std::optional<double> A0;          // preferred shape parameter; absent: A_min(N)
    double kl = 2, kb = 0.3, ka = 0.9; // k_l/k_c, k_b/(k_c sigma^2), k_a a0^2/(k_c sigma^2) (Fig. 9.12)
    double phi_start = 0.1;            // area of the polygons / L^2 at placement
    double energy_onset = 1e-10;       // U_t per particle [k_c sigma^2]
    std::uint64_t seed = 1;
};

struct Packing
{
    DpmSystem system;
    Eigen::VectorXd x;
    long fire_iterations = 0;
    int compression_steps = 0;
};

Packing jam_packing(const PackingOptions& options);

} // namespace softgrain::dpm
