// The scenes of the deformable particle model (MacKeith, Wang, Shattuck, O'Hern): dpm.*, one file each in
// lib/dpm/scenes/ named after the scene, registered by register_dpm_scenes in the order `softgrain list`
// shows them.
#pragma once

#include "core/option_binding.hpp"
#include "core/resources.hpp"
#include "core/scene.hpp"
#include "dpm/analysis/packing_hessian3d.hpp"
#include "dpm/protocols/jam.hpp"

#include <cstddef>

namespace softgrain {

void register_dpm_scenes(SceneRegistry& registry);

} // namespace softgrain

namespace softgrain::dpm {

Scene modes_scene();
Scene shear_friction_scene();
Scene packing_fraction_scene();
Scene crystal_modes_scene();
Scene jam_scene();
Scene bench_scene();
Scene rearrangement_scene();
Scene compress2d_scene();
Scene compress3d_scene();
Scene compress_box_scene();
Scene boundary_jam_scene();
Scene shape3d_scene();
Scene modes3d_scene();
Scene shear_modulus_scene();
Scene shear_modulus3d_scene();
Scene slump_scene();
Scene slide3d_scene();

} // namespace softgrain::dpm

// What several scenes share.
namespace softgrain::dpm {

// The compression scenes report a force-displacement exponent from three samples on: two fit any power law
// exactly, so they would report a number that nothing checks.
constexpr std::size_t minimum_exponent_points = 3;

// The minimiser of a jamming protocol (2D or 3D) after each box step, bound to `relaxation` (a field of
// Options); `note` adds what the scene restricts.
template <class Options, class RelaxationField>
void bind_relaxation(OptionBinding<Options>& binding, RelaxationField relaxation, const std::string& note)
{
    binding.choice(relaxation, "relaxation",
                   {{"fire", Relaxation::fire}, {"fire_newton", Relaxation::fire_newton}},
                   "minimiser after each box step: FIRE alone, or FIRE handing over to a regularised Newton "
                   "finisher on the sparse Hessian where it crawls (newton_relax.hpp" +
                       (note.empty() ? std::string() : "; " + note) + ")");
}

// FIRE's largest time step of a jamming protocol in units of 1/omega_max (JamOptions::fire_step,
// Jam3dOptions::fire_step), bound to `step` (a field of Options).
template <class Options, class StepField>
void bind_fire_step(OptionBinding<Options>& binding, StepField step)
{
    binding
        .real(step, "fire_step", "1",
              "FIRE's largest time step of the jamming protocol, dt_max = fire_step / sqrt(lambda_max) with "
              "lambda_max the largest Hessian eigenvalue at the random start (in 3D at least k_c), and "
              "dt_max <= 0.5; below velocity Verlet's stability limit 2")
        .positive()
        .below(2.0);
}

// The storage of a 3D packing's Hessian (packing_hessian3d.hpp), bound to `storage` (a field of Options)
// under `name`; `uses` says what the scene takes it for.
template <class Options, class StorageField>
void bind_hessian_storage(OptionBinding<Options>& binding, StorageField storage, const std::string& name,
                          const std::string& uses)
{
    binding.choice(storage, name,
                   {{"automatic", HessianStorage::automatic},
                    {"dense", HessianStorage::dense},
                    {"sparse", HessianStorage::sparse}},
                   "the Hessian of " + uses +
                       " (packing_hessian3d.hpp): dense up to 2048 degrees of freedom and sparse above, or "
                       "either throughout");
}

// The parameters of the jamming protocol (jam.hpp) as dpm.jam declares them, bound to the JamOptions that
// `jam` (a field of Options) holds: dpm.jam's own, the protocol dpm.bench times and the one dpm.shear_modulus
// shears. The floppy particles' A0 >= A_min(N) of both sizes is checked by the protocol itself (jam()).
template <class Options, class JamField>
void bind_jam_protocol(OptionBinding<Options>& binding, JamField jam)
{
    const auto field = [jam](auto member) { return path(jam, member); };
    binding.integer(field(&JamOptions::particles), "particles", "1", "particles N, half small, half large")
        .at_least(2);
    binding.integer(field(&JamOptions::nodes_small), "nodes_small", "1", "vertices of the small particles")
        .at_least(3);
    binding.integer(field(&JamOptions::nodes_large), "nodes_large", "1", "vertices of the large particles")
        .at_least(3);
    binding.choice(
        field(&JamOptions::model), "model", jam_model_names(),
        "smooth bidisperse disks, rigid rough polygons (rough disks) or rough deformable particles "
        "of Table 9.1");
    binding.seed(field(&JamOptions::seed), "seed", "seed of the random initial placement");
    binding
        .real(field(&JamOptions::pressure_onset), "pressure_onset", "k_c or k_a a0",
              "P_t: jamming onset pressure")
        .positive();
    binding
        .real(field(&JamOptions::pressure_max), "pressure_max", "k_c or k_a a0",
              "largest pressure of the compression")
        .positive();
    binding.integer(field(&JamOptions::pressures), "pressures", "1", "pressures log-spaced above onset")
        .at_least(1);
    binding
        .real(field(&JamOptions::A0_floppy), "A0", "1",
              "floppy: preferred shape parameter A0 (Fig. 9.14: 1.04)")
        .at_least(1.0)
        .renamed_from("A0_floppy");
    binding
        .real(field(&JamOptions::kl_surface), "kl_surface", "k_c",
              "surface_tension: edge stiffness k_l (Table 9.1: ~0; decision dpm-jam-surface-kl)")
        .non_negative();
    bind_relaxation(binding, field(&JamOptions::relaxation), "rough_disk: fire only");
    bind_fire_step(binding, field(&JamOptions::fire_step));
}

// A bidisperse packing of the parameters particles, nodes_small and nodes_large: half small and half large
// particles, each of its nodes, or one vertex for a disk.
struct BidispersePacking
{
    int particles = 0, nodes_small = 0, nodes_large = 0;
    bool disks = false;
};
// dpm.jam's packing (smooth disks are disks; rough disks are polygons of vertices).
BidispersePacking bidisperse_packing(const JamOptions& options);
// Its vertices, what they are counted in (naming the parameters), and the memory of its system.
double bidisperse_vertices(const BidispersePacking& packing);
const char* bidisperse_basis(const BidispersePacking& packing);
MemoryEstimate bidisperse_memory(const BidispersePacking& packing);

} // namespace softgrain::dpm
