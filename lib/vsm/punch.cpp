#include "vsm/punch.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "vsm/dynamics.hpp"
#include "vsm/particle_layouts.hpp"
#include "vsm/stability.hpp"

#include <cmath>

namespace softgrain::vsm {

namespace {
constexpr double width = 1.0, height = 0.5, thickness = 0.1;
constexpr int punch_label = 6;

// Downward reaction on the punch: minus the X2 component of the reactions D P_a A_ab on its ghosts.
double punch_reaction(const Model& model, const Points<3>& x, double t)
{
    const LameParameters lame = model.material().lame();
    double force = 0;
    for (int a = 0; a < static_cast<int>(model.size()); ++a)
        for (const Neighbour& nb : model.cells().neighbours[static_cast<std::size_t>(a)])
            if (nb.ghost() && nb.label == punch_label) {
                const Mat3 P = neo_hookean_stress(model.deformation_gradient(x, a, t), lame);
                force += (P * (nb.area * nb.normal)).y(); // reaction on the particle, eq. (42) discussion
            }
    return -force; // the punch pushes the particles down (negative X2): the load is reported positive
}

// Downward load of the contact stabilisation (eq. (46)) on the punch: the derivative of V^cnt (eq. (34)) with
// respect to the punch displacement d = v t at fixed particles. The punch ghosts' prescribed branches enter
// u of eq. (30) affinely, so V^cnt is quadratic in d and the central difference is exact up to round-off.
double punch_stabilisation_load(const Model& model, const Points<3>& x, double t, double velocity,
                                double spacing)
{
    const double dt = 1e-3 * spacing / velocity; // moves the punch by 1e-3 of a spacing
    return (model.contact_energy_total(x, t + dt) - model.contact_energy_total(x, t - dt)) /
           (2 * dt * velocity);
}

void measure(const Model& model, const Points<3>& x, double t, PunchSnapshot& s)
{
    const std::vector<Mat3> F = model.deformation_gradients(x, t);
    s.pressure = model.pressures(x, t);
    double nonaffine = 0, relative = 0, rough = 0, norm = 0;
    for (int a = 0; a < static_cast<int>(model.size()); ++a) {
        const auto ua = static_cast<std::size_t>(a);
        double mean = 0;
        int count = 0;
        for (const Neighbour& nb : model.cells().neighbours[ua]) {
            if (nb.ghost()) continue;
            const auto b = static_cast<std::size_t>(nb.particle);
            mean += s.pressure[b];
            ++count;
            if (nb.particle < a) continue;
            const Vec3 x_ab = x.col(nb.particle) - x.col(a);
            nonaffine += (x_ab - 0.5 * (F[ua] + F[b]) * nb.branch).squaredNorm(); // eq. (29)
            relative += (x_ab - nb.branch).squaredNorm();
        }
        if (count > 0) rough += std::pow(s.pressure[ua] - mean / count, 2);
        norm += s.pressure[ua] * s.pressure[ua];
    }
    s.nonaffine_ratio = std::sqrt(nonaffine / relative);
    s.pressure_roughness = std::sqrt(rough / norm);
}
} // namespace

Domain punch_domain(double w, double h, double th)
{
    Domain d = box_domain(Vec3::Zero(), Vec3(w, h, th));
    for (auto it = d.faces.begin(); it != d.faces.end(); ++it)
        if (it->label == 3) {
            d.faces.erase(it);
            break;
        }
    const auto top = [&](double x0, double x1, int label) {
        d.faces.push_back(BoundaryFace{1, h, +1, Vec3(x0, h, 0), Vec3(x1, h, th), label});
    };
    top(0, w / 3, 3);
    top(w / 3, 2 * w / 3, punch_label);
    top(2 * w / 3, w, 3);
    return d;
}

PunchResult run_punch(const PunchSetup& setup, const std::function<void(const PunchSnapshot&)>& observe,
                      const StepObserver& on_step)
{
    if (setup.counts[0] % 3 != 0)
        throw InputError("per_side_x = " + std::to_string(setup.counts[0]) +
                         " must be divisible by 3 (the punch covers the middle third)");
    if (setup.snapshot_strains.empty()) throw InputError("no snapshot strain");
    const Domain domain = punch_domain(width, height, thickness);
    Rng rng(setup.seed);
    const Points<3> X =
        jittered_lattice(Vec3::Zero(), Vec3(width, height, thickness), setup.counts, setup.jitter, &rng);
    BoundaryConditions bc;
    bc.kind = {BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::free,
               BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::total};
    const double velocity = setup.punch_velocity;
    // The punch (label 6) moves down; symmetric faces prescribe a zero normal displacement.
    bc.displacement = [velocity](int label, const Vec3&, double t) {
        return label == punch_label ? Vec3(0, -velocity * t, 0) : Vec3::Zero();
    };
    const double spacing = (Vec3(width, height, thickness).array() /
                            Eigen::Array3d(setup.counts[0], setup.counts[1], setup.counts[2]))
                               .maxCoeff();
    const Model model(build_reference_cells(X, domain, 2 * spacing), domain, bc, setup.material,
                      setup.options);

    const double dt = setup.cfl * model.min_branch_length() / setup.material.p_wave_speed();
    Leapfrog integrator(model, X, Points<3>::Zero(3, X.cols()), dt, 0.0,
                        setup.time_step_check ? TimeStepCheck::refuse_above_limit : TimeStepCheck::off);
    PunchResult r;
    r.particles = static_cast<int>(X.cols());
    r.dt = dt;
    r.dt_limit = predicted_time_step_limit(model);
    if (on_step) on_step(model, integrator);
    for (double strain : setup.snapshot_strains) {
        const double t_snapshot = strain * height / velocity;
        while (integrator.state().t + 0.5 * dt < t_snapshot) {
            integrator.step();
            if (on_step) on_step(model, integrator);
        }
        PunchSnapshot snap;
        snap.strain = strain;
        snap.t = integrator.state().t;
        snap.x = integrator.positions();
        measure(model, snap.x, snap.t, snap);
        snap.punch_force = punch_reaction(model, snap.x, snap.t);
        snap.punch_load_total =
            snap.punch_force + punch_stabilisation_load(model, snap.x, snap.t, velocity, spacing);
        if (observe) observe(snap);
        r.snapshots.push_back(std::move(snap));
    }
    r.steps = integrator.state().step;
    return r;
}

} // namespace softgrain::vsm
