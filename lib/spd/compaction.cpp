#include "spd/compaction.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::spd {

namespace {
// Lowest (ovalisation) bending frequency of a free ring, omega^2 = (36/5) EI / (rho R^4), rho = m / l0.
double ovalisation_frequency(const RingSetup& ring)
{
    const RingScales sc = ring_scales(ring);
    return std::sqrt(7.2 * sc.flexural_rigidity * sc.l0 / (ring.vertex_mass * std::pow(ring.radius, 4)));
}
} // namespace

CompactionResult compaction(const CompactionSetup& setup, const std::function<void(double)>& progress)
{
    AssemblySetup deposit = setup.assembly;
    deposit.ring.eta = 0;
    deposit.ring.plastic_ratio = INFINITY;
    deposit.loose = true;
    deposit.row_spacing = 1.1;
    const int columns =
        std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(deposit.particles)))));
    Assembly a = rings_in_box(deposit, columns);
    ShellModel& model = a.model;
    const RingSetup& ring = setup.assembly.ring;
    const RingScales sc = ring_scales(ring);
    const double m = ring.vertex_mass, omega2 = ovalisation_frequency(ring),
                 F_star = sc.characteristic.F_star;
    const double s = ring.material.s;

    // Deposition under gravity (decision spd-compaction-deposition).
    const int rows = (deposit.particles + columns - 1) / columns;
    const double g = setup.gravity_load * F_star / (rows * ring.nodes * m);
    std::vector<int> free_vertices;
    for (int p : a.particles)
        for (int i = model.shells()[p].first; i < model.shells()[p].first + model.shells()[p].count; ++i)
            free_vertices.push_back(i);
    for (int i : free_vertices)
        model.set_applied_force(i, Vec2(0, -m * g));
    CompactionResult result;
    const double dt_deposit = ring.dt_factor * model.critical_time_step();
    model.check_time_step(dt_deposit);
    const double damping = setup.damping * m * omega2;
    const long max_relax = static_cast<long>(2000 * 2 * M_PI / (omega2 * dt_deposit));
    result.deposition_steps = relax(model, dt_deposit, damping, 0.01 * m * g, max_relax);
    progress(0.1);
    for (int i : free_vertices)
        model.set_applied_force(i, Vec2::Zero());
    result.deposition_steps += relax(model, dt_deposit, damping, 1e-4 * F_star, max_relax);
    progress(0.2);

    // The run's laws (eta, M^Y/M*) on the common packing.
    for (std::size_t k = 0; k < a.particles.size(); ++k) {
        RingSetup ring_k = ring;
        ring_k.radius = a.radii[k];
        const RingScales sk = ring_scales(ring_k);
        model.set_shell_laws(a.particles[k], sk.laws, sk.K_Omega);
    }
    result.dt_critical = model.critical_time_step();
    result.dt = ring.dt_factor * result.dt_critical;
    model.check_time_step(result.dt);

    // Top wall on the highest particle: H0 at first contact.
    double top = 0;
    for (int i : free_vertices)
        top = std::max(top, model.vertex(i).y());
    top += sc.radius_vertex;
    model.translate(a.top, Vec2(0, top - model.vertex(model.shells()[a.top].first).y()));
    const auto height = [&] { return model.vertex(model.shells()[a.top].first).y(); };
    result.H0 = height();
    result.width = a.width;
    result.sigma_star = sc.characteristic.sigma_star;
    const auto solid_volume = [&] {
        double V = 0;
        for (int p : a.particles)
            V += particle_volume(model, p);
        return V;
    };
    const double Vs0 = solid_volume(), V0 = a.width * result.H0 * s;
    result.e0 = (V0 - Vs0) / Vs0;

    const auto record = [&](bool loading) {
        CompactionState st;
        const double H = height(), Vs = solid_volume(), V = a.width * H * s;
        st.strain = std::log(result.H0 / H);
        st.loading = loading;
        st.stress = model.contact_force_on(a.top).y() / (a.width * s);
        st.stress_bottom = -model.contact_force_on(a.bottom).y() / (a.width * s);
        st.void_ratio = (V - Vs) / Vs;
        st.volume_change_ratio = V0 - V > 0 ? (Vs0 - Vs) / (V0 - V) : NAN;
        st.kinetic_energy = model.kinetic_energy();
        result.states.push_back(st);
    };

    const double speed = setup.wall_speed * ring.radius * omega2;
    const int records = static_cast<int>(std::lround(setup.strain_max / setup.strain_record));
    record(true);
    // Loading: H = H0 exp(-eps) at the records; the wall speed is constant between them.
    for (int direction : {-1, +1}) {
        for (int k = 1; k <= records; ++k) {
            const double eps_target =
                direction < 0 ? setup.strain_record * k : setup.strain_max - setup.strain_record * k;
            const double H_target = result.H0 * std::exp(-eps_target);
            const long n = std::max(1L, std::lround(std::abs(H_target - height()) / (speed * result.dt)));
            model.set_velocity(a.top, Vec2(0, (H_target - height()) / (n * result.dt)));
            for (long j = 0; j < n; ++j)
                model.step(result.dt, damping);
            model.set_velocity(a.top, Vec2::Zero());
            model.translate(a.top, Vec2(0, H_target - height())); // round-off of the accumulated motion
            record(direction < 0);
            progress(0.2 + 0.8 * ((direction < 0 ? 0 : records) + k) / (2.0 * records));
        }
        if (direction < 0) {
            for (int p : a.particles) {
                result.energy_at_max.push_back(model.elastic_energy(p));
                std::vector<double> xs, ys;
                for (int i = model.shells()[p].first; i < model.shells()[p].first + model.shells()[p].count;
                     ++i) {
                    xs.push_back(model.vertex(i).x());
                    ys.push_back(model.vertex(i).y());
                }
                result.shape_x.push_back(xs);
                result.shape_y.push_back(ys);
            }
        }
    }
    result.steps = model.steps();
    return result;
}

} // namespace softgrain::spd
