#include "sd/vtk_frames.hpp"

#include <Eigen/Core>

namespace softgrain::sd {

std::vector<vtk::Part> many_particle_frame(const ManyParticleSystem& system, const ManySample& sample)
{
    const int d = system.dimension;
    const auto n = static_cast<int>(sample.positions.size()) / d;
    const auto centre = [&](int i) {
        Eigen::Vector3d r = Eigen::Vector3d::Zero();
        for (int c = 0; c < d; ++c)
            r(c) = sample.positions[static_cast<std::size_t>(d * i + c)];
        return r;
    };
    const auto flat = [&](const std::vector<double>& values, int i) {
        Eigen::Vector3d r = Eigen::Vector3d::Zero();
        for (int c = 0; c < d; ++c)
            r(c) = values[static_cast<std::size_t>(d * i + c)];
        return r;
    };
    std::vector<double> external(sample.positions.size(), 0.0), rate(sample.positions.size(), 0.0);
    if (system.external) system.external(sample.t, external, rate);

    vtk::PolyData particles;
    std::vector<double> velocity, force;
    std::vector<std::int64_t> ids;
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d r = centre(i), v = flat(sample.rates.velocity, i), f = flat(external, i);
        particles.add_vertex(particles.add_point(r.x(), r.y(), r.z()));
        velocity.insert(velocity.end(), {v.x(), v.y(), v.z()});
        force.insert(force.end(), {f.x(), f.y(), f.z()});
        ids.push_back(i);
    }
    particles.point_scalars("radius",
                            std::vector<double>(static_cast<std::size_t>(n), system.material.radius));
    particles.point_vectors("velocity", std::move(velocity));
    particles.point_vectors("external_force", std::move(force));
    particles.cell_ids("particle_id", std::move(ids));

    vtk::PolyData pairs;
    std::vector<double> normal;
    std::vector<std::int64_t> first, second;
    for (const auto& [i, j] : system.bonds) {
        const Eigen::Vector3d X = centre(j) - centre(i), n_ij = X.normalized(), mid = centre(i) + 0.5 * X;
        pairs.add_vertex(pairs.add_point(mid.x(), mid.y(), mid.z()));
        normal.insert(normal.end(), {n_ij.x(), n_ij.y(), n_ij.z()});
        first.push_back(i);
        second.push_back(j);
    }
    pairs.point_scalars("gap", sample.gaps);
    pairs.point_scalars("force", sample.rates.pair_force);
    pairs.point_scalars("deflection", sample.rates.deflection);
    pairs.point_scalars("gap_rate", sample.rates.gap_rate);
    pairs.point_vectors("normal", std::move(normal));
    pairs.cell_ids("particle_i", std::move(first));
    pairs.cell_ids("particle_j", std::move(second));
    return {{"particles", std::move(particles)}, {"pairs", std::move(pairs)}};
}

std::vector<vtk::Part> approach_frame(const ApproachProblem& problem, const ApproachSample& sample)
{
    ManyParticleSystem pair;
    pair.material = problem.material;
    pair.laws = problem.laws;
    pair.dimension = 1;
    pair.bonds = {{0, 1}};
    const double force = sample.F_ext;
    pair.external = [force](double, std::vector<double>& external, std::vector<double>& rate) {
        external = {force, -force};
        rate.assign(external.size(), 0.0); // not drawn
    };
    ManySample state;
    state.t = sample.t;
    state.positions = {-0.5 * sample.X, 0.5 * sample.X};
    state.gaps = {sample.h};
    state.rates.velocity = {-0.5 * sample.rates.X_dot, 0.5 * sample.rates.X_dot};
    state.rates.gap_rate = {sample.rates.h_dot};
    state.rates.pair_force = {sample.rates.F_ela};
    state.rates.deflection = {sample.rates.delta};
    return many_particle_frame(pair, state);
}

} // namespace softgrain::sd
