// Parameters that several spd.* scenes share, declared once: the shell material of eqs. (10)-(11) and the
// single ring of section 4 (spd.beam, spd.ring_pressure, spd.ring_compression), and the memory of an
// assembly of rings (spd.bench, spd.compaction).
#pragma once

#include "core/option_binding.hpp"
#include "spd/assembly.hpp"
#include "spd/calibration.hpp"
#include "spd/ring.hpp"
#include "spd/shell_model.hpp"

namespace softgrain::spd {

// E, nu, h, s into `material`, a field of Options holding a ShellMaterial (sigma_Y stays as it is).
template <class Options, class MaterialField>
void bind_shell_material(OptionBinding<Options>& binding, MaterialField material)
{
    binding
        .real(path(material, &ShellMaterial::E), "E", "Pa",
              "Young modulus of the shell material, eqs. (10)-(11)")
        .positive();
    binding.real(path(material, &ShellMaterial::nu), "nu", "1", "Poisson ratio, eqs. (10)-(11)")
        .non_negative()
        .below(0.5);
    binding.real(path(material, &ShellMaterial::h), "h", "m", "shell thickness, eqs. (10)-(11)").positive();
    binding.real(path(material, &ShellMaterial::s), "s", "m", "out-of-plane length of the particle")
        .positive();
}

// The ring's resolution, radius, core, time step and material into `ring`, a field of Options holding a
// RingSetup.
template <class Options, class RingField>
void bind_ring(OptionBinding<Options>& binding, RingField ring)
{
    binding
        .integer(path(ring, &RingSetup::nodes), "nodes", "1",
                 "vertices N of the ring; 128 keeps F, a/b0 and V/V0 within 1% of the elastica up to "
                 "eps = 0.5 (spd-work-precision)")
        .at_least(8);
    binding.real(path(ring, &RingSetup::radius), "R", "m", "initial radius R0").positive();
    // inf: incompressible core, exact area constraint (decision spd-eta-infinity).
    binding
        .real(path(ring, &RingSetup::eta), "eta", "1",
              "core-to-shell stiffness ratio K_Omega/K_shell, eq. (24); inf: incompressible core "
              "(exact area constraint, the pressure its multiplier)")
        .non_negative()
        .infinity_allowed();
    binding
        .real(path(ring, &RingSetup::dt_factor), "dt_factor", "1",
              "time step over dt_c = sqrt(m/k_max) (section 2.4)")
        .positive();
    bind_shell_material(binding, path(ring, &RingSetup::material));
}

// The memory of `particles` rings of `nodes` vertices each.
inline MemoryEstimate rings_memory(const AssemblySetup& assembly)
{
    return shell_model_memory(double(assembly.particles) * double(assembly.ring.nodes),
                              "vertices (particles x nodes)");
}

} // namespace softgrain::spd
