#include "spd/ring.hpp"
#include "core/step_count.hpp"

#include "core/errors.hpp"
#include "spd/time_step_limits.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softgrain::spd {

namespace {
constexpr double pi = std::numbers::pi;

// Lowest (ovalisation, n = 2) bending mode of a free ring: omega^2 = (36/5) EI / (rho R^4), rho = m / l0.
double ovalisation_frequency(const RingSetup& setup, const RingScales& sc)
{
    return std::sqrt(7.2 * sc.flexural_rigidity * sc.l0 / (setup.vertex_mass * std::pow(setup.radius, 4)));
}
} // namespace

RingScales ring_scales(const RingSetup& setup)
{
    RingScales sc;
    sc.l0 = 2 * setup.radius * std::sin(pi / setup.nodes);
    sc.laws = calibrate(setup.material, sc.l0);
    sc.flexural_rigidity = sc.laws.k_b * sc.l0;
    sc.K_shell = shell_bulk_modulus(sc.laws.k_s, setup.material.s, setup.nodes);
    sc.K_Omega = setup.eta * sc.K_shell;
    sc.radius_vertex = setup.material.h / 2; // decision spd-vertex-radius: 2r = h
    const double M_star = sc.laws.k_b / setup.radius * sc.l0;
    sc.laws.M_Y = setup.plastic_ratio * M_star;
    sc.laws.F_Y = INFINITY;
    sc.characteristic =
        characteristic_scales(sc.laws.k_b, sc.laws.M_Y, setup.radius, sc.l0, setup.material.s);
    return sc;
}

int add_ring(ShellModel& model, const RingSetup& setup, double pressure_applied)
{
    const RingScales sc = ring_scales(setup);
    Points<2> vertices(2, setup.nodes);
    for (int k = 0; k < setup.nodes; ++k) {
        const double phi = 2 * pi * k / setup.nodes;
        vertices.col(k) = setup.radius * Vec2(std::cos(phi), std::sin(phi));
    }
    Shell ring;
    ring.laws = sc.laws;
    ring.depth = setup.material.s;
    ring.radius = sc.radius_vertex;
    ring.K_Omega = sc.K_Omega;
    ring.pressure_applied = pressure_applied;
    return model.add_shell(vertices, ring, setup.vertex_mass);
}

RingPressureResult ring_under_pressure(const RingSetup& setup, double pressure,
                                       const std::function<void(const ShellModel&, int ring)>& relaxed)
{
    const RingScales sc = ring_scales(setup);
    ShellModel model;
    const int ring = add_ring(model, setup, pressure);
    const double A0 = model.area(ring);
    const double dt = setup.dt_factor * critical_time_step(model);
    check_time_step(model, dt);
    // The uniform load excites only the breathing mode, of radial stiffness per vertex
    // 4 k_s sin^2(pi/N) (eq. (21)) + 2 K_Omega s l0 / R (eq. (4)); damping critical for it.
    const double k_radial = 4 * sc.laws.k_s * std::pow(std::sin(pi / setup.nodes), 2) +
                            2 * sc.K_Omega * setup.material.s * sc.l0 / setup.radius;
    const double damping = 2 * std::sqrt(setup.vertex_mass * k_radial);
    const double tolerance = 1e-5 * pressure * setup.material.s * sc.l0; // above the round-off floor
    RingPressureResult r;
    r.steps = relax(model, dt, damping, tolerance, 5'000'000);
    r.volume_strain = model.area(ring) / A0 - 1.0;
    r.K_measured = pressure / r.volume_strain;
    if (relaxed) relaxed(model, ring);
    return r;
}

RingBetweenWalls ring_between_walls(const RingSetup& setup)
{
    const RingScales sc = ring_scales(setup);
    const double R = setup.radius, r = sc.radius_vertex;
    RingBetweenWalls w;
    w.ring = add_ring(w.model, setup, 0.0);
    // Walls: rigid open shells (reference angle 0), long enough for any contact, radius 0 (their vertex
    // disks are the lines themselves): the ring's sphero-segments touch them at distance r.
    Shell wall;
    wall.closed = false;
    wall.rigid = true;
    Points<2> top(2, 2), bottom(2, 2);
    top << -3 * R, 3 * R, R + r, R + r;
    bottom << 3 * R, -3 * R, -R - r, -R - r;
    w.top_wall = w.model.add_shell(top, wall, 1.0);
    w.bottom_wall = w.model.add_shell(bottom, wall, 1.0);
    // Decisions spd-ring-walls and spd-contact-damping: k_n = k_s, frictionless, normal damping critical for
    // a vertex on the wall, 2 sqrt(m k_n).
    w.model.set_contact_law({sc.laws.k_s, 0.0, 0.0, 2 * std::sqrt(setup.vertex_mass * sc.laws.k_s)});
    return w;
}

double ring_damping(const RingSetup& setup)
{
    return 2 * setup.vertex_mass * ovalisation_frequency(setup, ring_scales(setup));
}

CompressionResult ring_compression(const RingSetup& setup, double strain_max, double strain_step, bool unload,
                                   double relax_tolerance, const std::function<void(double)>& progress,
                                   const CompressionObserver& observe)
{
    const RingScales sc = ring_scales(setup);
    const double R = setup.radius, r = sc.radius_vertex, b0 = 2 * R;
    RingBetweenWalls walls = ring_between_walls(setup);
    ShellModel& model = walls.model;
    const int ring = walls.ring, top_wall = walls.top_wall, bottom_wall = walls.bottom_wall;
    const double A0 = model.area(ring);

    CompressionResult result;
    result.dt_critical = critical_time_step(model);
    result.dt = setup.dt_factor * result.dt_critical;
    check_time_step(model, result.dt); // 0.83 dt_c with the critically damped wall contact
    const double omega2 = ovalisation_frequency(setup, sc);
    const double damping = ring_damping(setup);
    const double force_scale = std::min(sc.flexural_rigidity / (R * R), sc.characteristic.F_2star);
    const double tolerance = relax_tolerance * force_scale;

    // Wall speed: the strain step is applied over two ovalisation periods, lengthened by
    // sqrt(EI/R^2 / F**) for a plastic ring so that inertial forces stay small against F** (decision
    // spd-ring-loading-rate).
    const double slow_down =
        std::sqrt(std::max(1.0, sc.flexural_rigidity / (R * R) / sc.characteristic.F_2star));
    const double move_time = 2 * 2 * pi / omega2 * slow_down;
    const long move_steps = std::max(1L, checked_step_count(std::floor(move_time / result.dt),
                                                            "one load step", "dt_factor", setup.dt_factor));
    const long max_relax = checked_step_count(std::floor(400 * slow_down * 2 * pi / (omega2 * result.dt)),
                                              "the relaxation budget", "dt_factor", setup.dt_factor);

    double gap = b0; // wall gap of the mid-line
    const bool plastic = std::isfinite(setup.plastic_ratio);
    const auto record = [&](bool loading) {
        CompressionState s;
        s.strain = 1 - gap / b0;
        s.loading = loading;
        double xmin = INFINITY, xmax = -INFINITY, ycentre = 0;
        const Shell& sh = model.shells()[ring];
        for (int i = sh.first; i < sh.first + sh.count; ++i) {
            xmin = std::min(xmin, model.vertex(i).x());
            xmax = std::max(xmax, model.vertex(i).x());
            ycentre += model.vertex(i).y() / sh.count;
        }
        s.width = (xmax - xmin) / b0;
        // N': vertices from the leftmost to the rightmost one touching the top wall (inclusive).
        int first = -1, last = -1;
        double x_first = 0, x_last = 0;
        for (int i = sh.first; i < sh.first + sh.count; ++i) {
            if (model.vertex(i).y() <= ycentre || model.contact_normal(i) <= 0) continue;
            const double x = model.vertex(i).x();
            if (first < 0 || x < x_first) first = i, x_first = x;
            if (last < 0 || x > x_last) last = i, x_last = x;
        }
        s.contact_vertices = first < 0 ? 0 : static_cast<int>(std::lround((x_last - x_first) / sc.l0)) + 1;
        s.contact_length = s.contact_vertices * sc.l0 / b0;
        s.volume = model.area(ring) / A0;
        s.wall_force = model.contact_force_on(top_wall).y(); // the ring pushes the top wall up
        s.stretch_energy = model.stretch_energy();
        s.bending_energy = model.bending_energy();
        s.core_pressure = model.core_pressure(ring);
        const double x_centre = first < 0 ? 0.0 : 0.5 * (x_first + x_last);
        // The profile covers the whole contact extent, vertices without force included.
        for (int i = sh.first; i < sh.first + sh.count && first >= 0; ++i) {
            const double x = model.vertex(i).x();
            if (model.vertex(i).y() <= ycentre || x < x_first - 1e-9 * R || x > x_last + 1e-9 * R) continue;
            s.profile_x.push_back(model.vertex(i).x() - x_centre);
            s.profile_pressure.push_back(model.contact_normal(i) / (setup.material.s * sc.l0));
        }
        for (int i = sh.first; i < sh.first + sh.count; ++i) {
            s.shape_x.push_back(model.vertex(i).x());
            s.shape_y.push_back(model.vertex(i).y());
        }
        result.states.push_back(std::move(s));
        if (observe) observe(walls, result.states.back());
    };

    // Moves both walls symmetrically to the gap `target` over move_steps, then relaxes.
    const auto drive_to = [&](double target) {
        const double speed = 0.5 * (gap - target) / (move_steps * result.dt);
        model.set_velocity(top_wall, Vec2(0, -speed));
        model.set_velocity(bottom_wall, Vec2(0, speed));
        for (long n = 0; n < move_steps; ++n)
            model.step(result.dt, damping);
        model.set_velocity(top_wall, Vec2::Zero());
        model.set_velocity(bottom_wall, Vec2::Zero());
        // Remove the round-off of the accumulated wall motion: place the walls exactly.
        model.translate(top_wall, Vec2(0, R + r - 0.5 * (b0 - target) -
                                              model.vertex(model.shells()[top_wall].first).y()));
        model.translate(bottom_wall, Vec2(0, -R - r + 0.5 * (b0 - target) -
                                                 model.vertex(model.shells()[bottom_wall].first).y()));
        gap = target;
        // A perfectly plastic ring (M^Y << M*) is a mechanism: once the walls stop, an elastic spring-back of
        // order M^Y/k_b releases the contact and any shape is in equilibrium. It is therefore recorded at the
        // end of the slow wall motion, in contact (decision spd-plastic-recording).
        if (plastic) return;
        try {
            relax(model, result.dt, damping, tolerance, max_relax);
        } catch (const NumericalError& e) {
            throw NumericalError(
                e.quantity + " at strain " + std::to_string(1 - gap / b0), e.step,
                std::string(e.what()).substr(std::string(e.what()).find("likely cause: ") + 14));
        }
    };

    const int increments = static_cast<int>(std::lround(strain_max / strain_step));
    const int total = unload ? 2 * increments + 1 : increments;
    record(true);
    for (int k = 1; k <= increments; ++k) {
        drive_to(b0 * (1 - strain_max * k / increments));
        record(true);
        progress(static_cast<double>(k) / total);
    }
    if (unload) {
        for (int k = increments - 1; k >= 0; --k) {
            drive_to(b0 * (1 - strain_max * k / increments));
            record(false);
            progress(static_cast<double>(2 * increments - k) / total);
        }
        // Release: walls moved 10% of b0 away, the ring relaxes free of contact.
        drive_to(1.1 * b0);
        Vec2 centroid = Vec2::Zero();
        const Shell& sh = model.shells()[ring];
        for (int i = sh.first; i < sh.first + sh.count; ++i)
            centroid += model.vertex(i) / sh.count;
        for (int i = sh.first; i < sh.first + sh.count; ++i) {
            result.released_x.push_back(model.vertex(i).x());
            result.released_y.push_back(model.vertex(i).y());
        }
        for (int i = sh.first; i < sh.first + sh.count; ++i)
            result.shape_residual =
                std::max(result.shape_residual, std::abs((model.vertex(i) - centroid).norm() - R) / R);
    }
    result.steps = model.steps();
    return result;
}

} // namespace softgrain::spd
