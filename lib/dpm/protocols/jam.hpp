// Jamming of bidisperse packings in a periodic square box, DPM section 9.4 (Fig. 9.13):
// compress isotropically (particle centres scaled, shapes kept) in steps Delta L/L, FIRE after each; if the
// pressure P = Tr(Sigma)/2 (eq. 9.26) exceeds the target by more than 1 %, return to the state before the
// step and halve Delta L/L; stop at 1 <= P/P_target < 1.01. Onset: P_target = P_t; then further targets
// log-spaced up to pressure_max, each reached the same way from the previous packing.
// Models: smooth_disk = one-vertex particles (purely repulsive linear springs between disk centres, eq. 9.4
// with sigma = disk diameter); rough_disk = rigid regular polygons with rough vertices (rigid.hpp); shell,
// floppy, surface_tension = rough deformable polygons of Table 9.1.
// Bidisperse 50:50 with diameter ratio 1.4 (disks) or polygon-diameter ratio 1.4 (N_small, N_large vertices).
#pragma once

#include "core/fire.hpp"
#include "dpm/relax/newton_relax.hpp"
#include "dpm/system/system.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace softgrain::dpm {

// The particles of a packing: smooth bidisperse disks (one vertex each), rigid polygons of rough vertices
// (rough disks, rigid.hpp), or the rough deformable polygons of Table 9.1.
enum class JamModel { smooth_disk, rough_disk, shell, floppy, surface_tension };
// Each model with the word a scene's `model` parameter names it by, in the order `describe` lists them.
const std::vector<std::pair<std::string, JamModel>>& jam_model_names();
std::string jam_model_name(JamModel model);
// A deformable model as the ShapeModel of Table 9.1 (nothing for the disks), and back.
std::optional<ShapeModel> shape_model(JamModel model);
JamModel jam_model(ShapeModel model);

struct JamOptions
{
    JamModel model = JamModel::smooth_disk;
    int particles = 16;
    int nodes_small = 10, nodes_large = 14;
    double size_ratio = 1.4;
    double pressure_onset = 1e-7; // P_t in units of k_c (disks) or k_a a0 (deformable particles)
    double pressure_max = 1e-3;
    int pressures = 5;       // targets log-spaced in (P_t, pressure_max]
    double phi_start = 0.3;  // disks: packing fraction of the random start
    double A0_floppy = 1.04; // floppy particles: preferred shape parameter (Fig. 9.14)
    // Surface-tension particles: k_l [k_c] (Table 9.1: ~0; decision dpm-jam-surface-kl).
    double kl_surface = 0.01;
    std::uint64_t seed = 1;
    bool decompress = false; // after pressure_max, expand back down through the same targets (Fig. 9.13b-d)
    // FIRE alone, or FIRE handing over to the Newton finisher where it crawls (newton_relax.hpp). The
    // rigid polygons of rough_disk relax over rigid-body coordinates with FIRE alone (fire_newton: InputError).
    Relaxation relaxation = Relaxation::fire;
    // FIRE's largest time step dt_max = fire_step / sqrt(lambda_max), lambda_max the largest eigenvalue of the
    // Hessian at the random start (omega_max dt_max = fire_step; velocity Verlet is stable below 2, and
    // contacts stiffen the packing later), at most 0.5. 0.3 keeps every stored path; 1 jams 8 x 42 shells
    // at P_t = 1e-7 in 2.9 times fewer FIRE iterations (reproductions/dpm/README.md).
    double fire_step = 0.3;
};

struct JamState
{
    double phi = 0, pressure = 0; // pressure in the model's unit
    long fire_iterations = 0;
    Eigen::VectorXd x;          // the relaxed configuration at this pressure
    Eigen::Vector2d box{};      // and its box
    bool decompression = false; // reached by expanding from pressure_max
};

struct JamResult : RelaxTally // the relaxations' cost
{
    std::vector<JamState> states; // onset first, then the compressed states
    DpmSystem system;
    Eigen::VectorXd x;
    double pressure_unit = 1; // k_c (disks) or k_a a0
    FireOptions fire;         // the protocol's FIRE settings, for further steps from its states
};

// Throws InputError for floppy particles with A0_floppy below A_min(N) of either size (naming A0, checked
// first: the only check of it), for rough_disk with fire_newton, and when the particles find no room at the
// start; NumericalError when a relaxation does not converge.
JamResult jam(const JamOptions& options);

// The compression branch of a jam() run (the states after onset, without those of the decompression): the
// bulk modulus B of P = B (phi - phi_c) fitted through the origin and the exponent of P against
// phi - phi_c, both from two states on (core/fits.hpp; nothing below).
struct CompressionBranchFit
{
    std::optional<double> bulk_modulus, pressure_exponent;
};
CompressionBranchFit fit_compression_branch(const std::vector<JamState>& states);

// Packing fraction: disks sum pi sigma^2/4 / A; deformable particles eq. (9.22).
double packing_fraction(const DpmSystem& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
