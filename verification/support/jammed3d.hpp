// Support of the tests of 3D packings (DPM sec. 9.4).
//
// check_jammed3d: the checks of a packing at the end of the jamming protocol, shared by the rough and smooth
// jamming tests: 1 <= P/P_t < 1.01; FIRE's stopping rule (rms force below its tolerance); every particle in
// contact. It then polishes the packing by Newton to round-off forces (a residual force f shifts the zero
// modes by ~f R), checks that it is a minimum (no negative mode, decision dpm-packing-minimum) and returns
// the zero modes of the dynamical matrix (eq. 9.28; the smallest non-zero eigenvalue is ~1e-4 k_v v0^(4/3),
// the zero ones ~1e-16, threshold 1e-10 as Fig. 9.15a) and the rattlers, for the caller's count (sec.
// 9.4.3: 3 periodic translations plus 6 per rattler).
#pragma once

#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/jam3d.hpp"

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace softgrain::verification {

struct JammedModes
{
    int zero_modes = 0;
    int rattlers = 0;
};

inline JammedModes check_jammed3d(dpm::Jam3dResult& j, double pressure_onset)
{
    using namespace softgrain::dpm;
    CHECK(j.pressure >= pressure_onset);
    CHECK(j.pressure < 1.01 * pressure_onset);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(j.x.size());
    total_energy3d(j.system, j.x, &g, nullptr);
    CHECK(g.norm() / std::sqrt(double(g.size())) < j.fire.force_tolerance); // FIRE's stopping rule
    for (int c : contact_counts3d(j.system, j.x))
        CHECK(c > 0);
    const EnergyWithDerivatives energy = [&j](const Eigen::VectorXd& y, Eigen::VectorXd* gr,
                                              Eigen::MatrixXd* h) {
        return total_energy3d(j.system, y, gr, h);
    };
    polish_for_modes(energy, j.x, j.pressure_unit);
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(j.x.size(), j.x.size());
    total_energy3d(j.system, j.x, nullptr, &m);
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues() /
        j.eigenvalue_unit;
    const std::vector<int> after = contact_counts3d(j.system, j.x);
    const SpectrumCounts counts = count_modes(lambda, zero_mode_threshold(lambda, 1e-10));
    CHECK(counts.negative == 0);
    const JammedModes modes{counts.zero, static_cast<int>(std::count(after.begin(), after.end(), 0))};
    MESSAGE("phi = " << j.phi << ", box steps " << j.box_steps << ", FIRE iterations " << j.fire_iterations
                     << ", rattlers " << modes.rattlers);
    return modes;
}

// The shape of Table 9.1's model (3D analogues, model_shape3d) on the icosahedron of circumradius 1 with
// k_v = 1 and Stiffness3d's k's; floppy particles with A0 = 1.15 > A_mesh = 1.098, the others with the
// mesh's own A^3D.
inline dpm::ShapeParameters3d icosahedron_shape3d(dpm::ShapeModel model, const dpm::TriangleMesh& mesh)
{
    using namespace softgrain::dpm;
    const Eigen::VectorXd reference = mesh_coordinates(mesh);
    const double A0 = model == ShapeModel::floppy ? 1.15
                                                  : shape_parameter3d(mesh_surface_area(mesh, reference, 0),
                                                                      mesh_volume(mesh, reference, 0));
    return model_shape3d(model, mesh, reference, A0, 1.0, Stiffness3d{});
}

// Fourteen randomly deformed icosahedral particles of the model (icosahedron_shape3d, vertices jittered by up
// to 0.08) at random centres in a periodic cube of side 4.2 under a Lees-Edwards strain of 0.23, vertex
// diameters 0.6-0.9: dense enough for many contacts, also across every face of the box.
inline dpm::DpmSystem3d random_sheared3d(dpm::ShapeModel model, Rng& rng, Eigen::VectorXd& x)
{
    dpm::DpmSystem3d s;
    s.box = 4.2;
    s.lees_edwards_strain = 0.23;
    s.meshes.push_back(dpm::icosahedron_mesh());
    const dpm::ShapeParameters3d shape = icosahedron_shape3d(model, s.meshes[0]);
    for (int m = 0; m < 14; ++m) {
        const Eigen::Vector3d centre(rng.uniform(0, 4.2), rng.uniform(0, 4.2), rng.uniform(0, 4.2));
        Eigen::Matrix3Xd v = s.meshes[0].vertices.colwise() + centre;
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.08 * rng.uniform(-1, 1);
        s.add_particle(0, v, rng.uniform(0.6, 0.9), shape, x);
    }
    return s;
}

// The interaction of `s` at `moved`, from the one list `s` has built (still valid there), against a list
// built afresh at `moved`: energy, gradient, Hessian, virial and contact counts the same bit for bit, since
// the contact loops' terms, order and images do not depend on the list (vertex_pairs3d.hpp).
inline void check_same_with_fresh_list3d(const dpm::DpmSystem3d& s, const Eigen::VectorXd& moved)
{
    const auto n = moved.size();
    Eigen::VectorXd old_gradient = Eigen::VectorXd::Zero(n), fresh_gradient = Eigen::VectorXd::Zero(n);
    Eigen::MatrixXd old_hessian = Eigen::MatrixXd::Zero(n, n), fresh_hessian = Eigen::MatrixXd::Zero(n, n);
    Eigen::Matrix3d old_virial = Eigen::Matrix3d::Zero(), fresh_virial = Eigen::Matrix3d::Zero();
    const double old_energy = dpm::interaction_energy3d(s, moved, &old_gradient, &old_hessian, &old_virial);
    REQUIRE(s.contacts.builds() == 1);
    dpm::DpmSystem3d fresh = s;
    fresh.contacts = {};
    const double fresh_energy =
        dpm::interaction_energy3d(fresh, moved, &fresh_gradient, &fresh_hessian, &fresh_virial);
    REQUIRE(fresh.contacts.builds() == 1);
    CHECK(old_energy == fresh_energy);
    CHECK(old_gradient == fresh_gradient);
    CHECK(old_hessian == fresh_hessian);
    CHECK(old_virial == fresh_virial);
    CHECK(dpm::contact_counts3d(s, moved) == dpm::contact_counts3d(fresh, moved));
}

} // namespace softgrain::verification
