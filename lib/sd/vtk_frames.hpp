// ParaView frames of Soft Dynamics scenes (`run --vtk`, core/vtk.hpp): a ManySample of several particles.
//
// particles: the centres as points (vertex cells), on the x axis for a line, z = 0, in m (R = 1 m). Point
// data: radius R [m], velocity V_i [m/s], external_force F_i^ext [N]. Cell data: particle_id.
// pairs: one point per bonded pair at the middle of its gap, X_i + (|X_ij| / 2) n_ij (vertex cells). Point
// data: gap h_ij [m], force F_ij = F_ela(a_ij, delta_ij) (> 0 repulsive, eq. (8)) [N], deflection delta_ij
// [m] (eq. (2)), gap_rate h-dot_ij [m/s] (eq. (7)), normal n_ij. Cell data: particle_i, particle_j.
#pragma once

#include "core/vtk.hpp"
#include "sd/approach.hpp"
#include "sd/many.hpp"

#include <vector>

namespace softgrain::sd {

std::vector<vtk::Part> many_particle_frame(const ManyParticleSystem& system, const ManySample& sample);

// A sample of the pair approach (sd.approach) as the frame of two particles on the x axis with centres at
// -X/2 and X/2 (the pair's centre at rest), each pushed toward the other by F_ext: velocities -+X-dot/2.
std::vector<vtk::Part> approach_frame(const ApproachProblem& problem, const ApproachSample& sample);

} // namespace softgrain::sd
