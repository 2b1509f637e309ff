#include "spd/compaction.hpp"
#include "core/step_count.hpp"

#include "core/checkpoint.hpp"
#include "core/errors.hpp"
#include "core/fire.hpp"
#include "core/geometry.hpp"
#include "core/neighbour_list.hpp"
#include "core/rng.hpp"
#include "spd/time_step_limits.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace softgrain::spd {

namespace {
constexpr double pi = std::numbers::pi;

// Harmonic repulsion k/2 overlap^2 of rigid disks (used only to build the packing of step (1)): adds its
// energy and forces on the two disks to (U, f).
void disk_pair_energy(const Vec2& xi, const Vec2& xj, double reach, double k, double& U, Vec2& fi, Vec2& fj)
{
    const Vec2 d = xj - xi;
    const double distance = d.norm();
    if (distance >= reach) return;
    const double overlap = reach - distance;
    U += 0.5 * k * overlap * overlap;
    const Vec2 push = k * overlap * d / distance; // on j, away from i
    fj += push;
    fi -= push;
}

// A disk against a wall: overlap = radius - distance to the wall line along the inward normal n.
void disk_wall_energy(double distance, double radius, const Vec2& n, double k, double& U, Vec2& f)
{
    if (distance >= radius) return;
    const double overlap = radius - distance;
    U += 0.5 * k * overlap * overlap;
    f += k * overlap * n;
}

// Mean ring radius of an assembly.
double mean_radius(const std::vector<double>& radii)
{
    double sum = 0;
    for (double R : radii)
        sum += R;
    return sum / static_cast<double>(radii.size());
}

double top_of_particles(const Assembly& a)
{
    double top = -INFINITY;
    for (int p : a.particles) {
        const Shell& s = a.model.shells()[p];
        for (int i = s.first; i < s.first + s.count; ++i)
            top = std::max(top, a.model.vertex(i).y() + s.radius);
    }
    return top;
}

double wall_height(const Assembly& a, int wall)
{
    return a.model.vertex(a.model.shells()[wall].first).y();
}
} // namespace

double compaction_box_width(const std::vector<double>& radii)
{
    double area = 0;
    for (double R : radii)
        area += pi * R * R;
    return std::sqrt(area / 0.82);
}

double solid_area(const ShellModel& model, int shell)
{
    const Shell& s = model.shells()[shell];
    Points<2> polygon(2, s.count);
    for (int k = 0; k < s.count; ++k)
        polygon.col(k) = model.vertex(s.first + k);
    return polygon_signed_area(polygon) + polygon_perimeter(polygon) * s.radius + pi * s.radius * s.radius;
}

DiskPacking deposit_disks(const std::vector<double>& radii, double width, std::uint64_t seed)
{
    const int n = static_cast<int>(radii.size());
    const double R_mean = mean_radius(radii), R_max = *std::max_element(radii.begin(), radii.end());
    // Stiff enough that the overlaps under a column of sqrt(n) disks stay below 1e-3 sqrt(n) R: the rings
    // placed at these centres start with overlaps far below their contact reach 2r.
    const double k = 1e4 / R_mean;
    const int columns = std::max(1, static_cast<int>(width / (2.1 * R_max)));
    const double pitch_x = width / columns, pitch_y = 2.1 * R_max;
    Rng rng(seed + 7919); // a stream independent of the radii's
    Eigen::VectorXd x(2 * n);
    for (int i = 0; i < n; ++i) {
        const double spare = 0.5 * (pitch_x - 2 * R_max);
        x[2 * i] = (i % columns + 0.5) * pitch_x + rng.uniform(-spare, spare);
        x[2 * i + 1] = (i / columns + 0.5) * pitch_y + rng.uniform(0, 0.1 * R_max);
    }
    NeighbourList<2> list(2 * R_max, 0.5 * R_mean);
    const auto energy_and_force = [&](const Eigen::VectorXd& xs, Eigen::VectorXd& f) {
        const Points<2> positions = Eigen::Map<const Points<2>>(xs.data(), 2, n);
        list.update(positions);
        f.setZero(2 * n);
        double U = 0;
        for (int i = 0; i < n; ++i) {
            const Vec2 c = positions.col(i);
            Vec2 fi = Vec2(0, -1.0); // unit weight
            U += c.y();
            disk_wall_energy(c.y(), radii[i], Vec2(0, 1), k, U, fi);
            disk_wall_energy(c.x(), radii[i], Vec2(1, 0), k, U, fi);
            disk_wall_energy(width - c.x(), radii[i], Vec2(-1, 0), k, U, fi);
            f.segment<2>(2 * i) += fi;
        }
        for (const auto& [i, j] : list.pairs()) {
            Vec2 fi = Vec2::Zero(), fj = Vec2::Zero();
            disk_pair_energy(positions.col(i), positions.col(j), radii[i] + radii[j], k, U, fi, fj);
            f.segment<2>(2 * i) += fi;
            f.segment<2>(2 * j) += fj;
        }
        return U;
    };
    FireOptions options;
    options.dt_initial = 0.05 / std::sqrt(k);
    options.dt_max = 0.2 / std::sqrt(k);
    options.force_tolerance = 1e-6; // of the unit weight
    options.kinetic_tolerance = 1e-14;
    options.max_iterations = 5'000'000;
    const FireResult r = fire_minimise(x, energy_and_force, options);
    if (!r.converged) {
        std::ostringstream cause;
        cause << "rigid-disk deposition: FIRE stopped after " << r.iterations << " iterations at rms force "
              << r.force_rms << " of the disk weight (tolerance 1e-6)";
        throw NumericalError("disk deposition", r.iterations, cause.str());
    }
    DiskPacking packing;
    packing.iterations = r.iterations;
    packing.top = -INFINITY;
    for (int i = 0; i < n; ++i) {
        packing.centres.emplace_back(x[2 * i], x[2 * i + 1]);
        packing.top = std::max(packing.top, x[2 * i + 1] + radii[i]);
    }
    return packing;
}

Deposit place_rings(const CompactionSetup& setup)
{
    const std::vector<double> radii = ring_radii(setup.assembly);
    const RingScales sc = ring_scales(setup.assembly.ring);
    const double r = sc.radius_vertex;
    std::vector<double> outer;
    for (double R : radii)
        outer.push_back(R + r);
    const double width = compaction_box_width(outer);
    Deposit d;
    d.disks = deposit_disks(outer, width, setup.assembly.seed);
    // The rings are elastic while they settle (decision spd-compaction-deposition).
    AssemblySetup elastic = setup.assembly;
    elastic.ring.plastic_ratio = INFINITY;
    const double R = setup.assembly.ring.radius;
    d.assembly = rings_at(elastic, radii, d.disks.centres, width, d.disks.top + 2 * R);
    ShellModel& model = d.assembly.model;
    const int nodes = setup.assembly.ring.nodes;
    d.weight = setup.gravity * sc.flexural_rigidity / (R * R);
    for (int p : d.assembly.particles) {
        const Shell& s = model.shells()[p];
        for (int i = s.first; i < s.first + s.count; ++i)
            model.set_applied_force(i, Vec2(0, -d.weight / nodes));
    }
    d.dt = setup.assembly.ring.dt_factor * critical_time_step(model);
    check_time_step(model, d.dt);
    return d;
}

void settle(const CompactionSetup& setup, Deposit& d, const std::function<void(const Deposit&)>& after_check)
{
    ShellModel& model = d.assembly.model;
    // Damped relaxation (decision spd-compaction-deposition): global viscous damping 5% of the critical
    // damping of the ovalisation mode, 2 m omega_2 (ring_damping), so that the rings still fall and rearrange
    // (rigid-body motion is not over-damped); budget 4000 ovalisation periods.
    const double omega2 = ring_damping(setup.assembly.ring) / (2 * setup.assembly.ring.vertex_mass);
    const long budget =
        checked_step_count(std::floor(4000 * 2 * pi / (omega2 * d.dt)), "the deposition budget", "dt_factor",
                           setup.assembly.ring.dt_factor);
    d.steps = relax(model, d.dt, 0.05 * ring_damping(setup.assembly.ring), setup.rest_tolerance * d.weight,
                    budget, d.steps, [&](long n) {
                        d.steps = n;
                        if (after_check) after_check(d);
                    });
    d.residual_force = model.max_free_force();
    d.bottom_force = -model.contact_force_on(d.assembly.bottom).y();
}

Deposit deposit(const CompactionSetup& setup)
{
    Deposit d = place_rings(setup);
    settle(setup, d, {});
    return d;
}

namespace {
// Where a compaction run is: its stage, the steps taken in that stage and the strain of the next snapshot.
// With the result so far (which holds the model), this is the whole state of a checkpoint.
struct Stage
{
    enum Name : std::int32_t { settling, loading, unloading, done } name = settling;
    long steps = 0;
    double next_snapshot = 0;
};

// Gravity off, plasticity on with the set's laws, the top wall in contact with the highest ring (H = H0),
// the time step and wall speed of the loading.
void start_loading(const CompactionSetup& setup, CompactionResult& result)
{
    Assembly& a = result.deposit.assembly;
    ShellModel& model = a.model;
    const RingSetup& ring = setup.assembly.ring;
    for (int p : a.particles) {
        const Shell& s = model.shells()[p];
        for (int i = s.first; i < s.first + s.count; ++i)
            model.set_applied_force(i, Vec2::Zero());
        RingSetup own = ring; // M^Y = plastic_ratio M* of the ring's own R_i and l0 (eq. (32))
        own.radius = a.radii[p];
        model.set_laws(p, ring_scales(own).laws);
    }
    model.stop();
    result.height0 = top_of_particles(a);
    model.translate(a.top, Vec2(0, result.height0 - wall_height(a, a.top)));
    result.width = a.width;
    result.solid_area0 = 0;
    for (int p : a.particles)
        result.solid_area0 += solid_area(model, p);
    result.dt = ring.dt_factor * critical_time_step(model);
    check_time_step(model, result.dt);
    const double omega2 = ring_damping(ring) / (2 * ring.vertex_mass);
    result.wall_speed = setup.wall_speed * ring.radius * omega2;
}
} // namespace

CompactionResult compaction(const CompactionSetup& setup,
                            const std::function<void(const Assembly&, const CompactionState&)>& observe,
                            const std::function<void(double)>& progress, Checkpoints* checkpoints)
{
    CompactionResult result;
    Stage stage;
    const auto whole_state = [&](Archive& archive) {
        archive(result);
        archive(stage);
    };
    const auto checkpoint = [&] {
        if (checkpoints && checkpoints->due()) checkpoints->save(whole_state);
    };
    if (!checkpoints || !checkpoints->resume(whole_state)) result.deposit = place_rings(setup);
    Assembly& a = result.deposit.assembly;
    ShellModel& model = a.model;

    const auto state = [&](bool loading) {
        CompactionState st;
        st.height = wall_height(a, a.top);
        st.strain = std::log(result.height0 / st.height);
        st.force_top = model.contact_force_on(a.top).y();
        st.force_bottom = -model.contact_force_on(a.bottom).y();
        st.solid_area = 0;
        for (int p : a.particles)
            st.solid_area += solid_area(model, p);
        st.kinetic_energy = model.kinetic_energy();
        st.loading = loading;
        st.time = static_cast<double>(model.steps() - result.deposit.steps) * result.dt;
        return st;
    };
    const auto record = [&](bool loading) {
        result.states.push_back(state(loading));
        observe(a, result.states.back());
    };
    const auto take_snapshot = [&] {
        CompactionSnapshot snap;
        snap.height = wall_height(a, a.top);
        snap.strain = std::log(result.height0 / snap.height);
        for (int p : a.particles) {
            snap.particles.push_back(model.outline(p));
            snap.energy.push_back(model.elastic_energy(p));
        }
        result.snapshots.push_back(std::move(snap));
    };
    if (stage.name == Stage::settling) {
        settle(setup, result.deposit, [&](const Deposit&) { checkpoint(); });
        start_loading(setup, result);
        stage = {Stage::loading, 0, setup.strain_max / 3}; // Fig. 26: thirds of the loading
        record(true);
        take_snapshot();
    }

    const RingSetup& ring = setup.assembly.ring;
    const double H_min = result.height0 * std::exp(-setup.strain_max);
    const long half_steps =
        checked_step_count(std::ceil((result.height0 - H_min) / (result.wall_speed * result.dt)),
                           "one half cycle", "dt_factor", setup.assembly.ring.dt_factor);
    const long interval = std::max(1L, half_steps / setup.records);
    // One half cycle: the top wall at `speed` until the height passes `target`; the last step is shortened
    // by placing the wall exactly at the target. It continues after the stage's steps already taken.
    const double force_cap =
        setup.stress_max * ring_scales(ring).characteristic.sigma_star * a.width * ring.material.s;
    const auto drive = [&](double speed, double target, bool loading, double progress_offset) {
        model.set_velocity(a.top, Vec2(0, speed));
        for (long n = stage.steps + 1;; ++n) {
            const double H = wall_height(a, a.top);
            bool last = speed < 0 ? H + speed * result.dt <= target : H + speed * result.dt >= target;
            if (last) model.translate(a.top, Vec2(0, target - H - speed * result.dt));
            model.step(result.dt, 0.0);
            if (loading && model.contact_force_on(a.top).y() >= force_cap) last = true; // stress cap
            if (loading && !last && std::log(result.height0 / wall_height(a, a.top)) >= stage.next_snapshot) {
                take_snapshot();
                stage.next_snapshot += setup.strain_max / 3;
            }
            if (last || n % interval == 0) record(loading);
            if (n % interval == 0) progress(progress_offset + 0.5 * static_cast<double>(n) / half_steps);
            stage.steps = n;
            if (last) break;
            checkpoint();
        }
        model.set_velocity(a.top, Vec2::Zero());
    };
    if (stage.name == Stage::loading) {
        drive(-result.wall_speed, H_min, true, 0.0);
        take_snapshot();
        stage = {Stage::unloading, 0, stage.next_snapshot};
    }
    if (stage.name == Stage::unloading) {
        drive(result.wall_speed, result.height0, false, 0.5);
        stage.name = Stage::done;
    }
    result.steps = model.steps();
    return result;
}

void transfer(Archive& archive, DiskPacking& packing)
{
    archive(packing.centres);
    archive(packing.top);
    archive(packing.iterations);
}

void transfer(Archive& archive, Deposit& deposit)
{
    archive(deposit.assembly);
    archive(deposit.disks);
    for (double* value : {&deposit.weight, &deposit.dt, &deposit.residual_force, &deposit.bottom_force})
        archive(*value);
    archive(deposit.steps);
}

void transfer(Archive& archive, CompactionSnapshot& snapshot)
{
    archive(snapshot.strain);
    archive(snapshot.height);
    archive(snapshot.particles);
    archive(snapshot.energy);
}

void transfer(Archive& archive, CompactionResult& result)
{
    archive(result.deposit);
    for (double* value :
         {&result.height0, &result.width, &result.solid_area0, &result.dt, &result.wall_speed})
        archive(*value);
    archive(result.states);
    archive(result.snapshots);
    archive(result.steps);
}

double top_stress_over_sigma_star(const CompactionSetup& setup, const CompactionResult& result,
                                  const CompactionState& state)
{
    const RingSetup& ring = setup.assembly.ring;
    return state.force_top / (result.width * ring.material.s) / ring_scales(ring).characteristic.sigma_star;
}

double bottom_stress_over_sigma_star(const CompactionSetup& setup, const CompactionResult& result,
                                     const CompactionState& state)
{
    const RingSetup& ring = setup.assembly.ring;
    return state.force_bottom / (result.width * ring.material.s) /
           ring_scales(ring).characteristic.sigma_star;
}

double void_ratio(const CompactionResult& result, const CompactionState& state)
{
    return (result.width * state.height - state.solid_area) / state.solid_area;
}

double solid_volume_share(const CompactionResult& result, const CompactionState& state)
{
    return state.height < result.height0
               ? (result.solid_area0 - state.solid_area) / (result.width * (result.height0 - state.height))
               : NAN;
}

CompactionMeasures measure_compaction(const CompactionSetup& setup, const CompactionResult& result)
{
    CompactionMeasures measures;
    double force_max = 0;
    for (const CompactionState& state : result.states) {
        if (state.loading) {
            measures.end_of_loading = state;
            measures.stress_max =
                std::max(measures.stress_max, top_stress_over_sigma_star(setup, result, state));
            const double share = solid_volume_share(result, state);
            if (std::isfinite(share) && state.strain >= 0.05)
                measures.volume_share_peak = std::max(measures.volume_share_peak, share);
            measures.wall_force_mismatch =
                std::max(measures.wall_force_mismatch, std::abs(state.force_top - state.force_bottom));
            force_max = std::max(force_max, state.force_top);
        } else if (std::isnan(measures.residual_strain) && state.force_top <= 0) {
            measures.residual_strain = state.strain;
        }
    }
    measures.wall_force_mismatch /= force_max;
    std::vector<double> log_stress, void_ratios;
    for (const CompactionState& state : result.states) {
        const double stress = top_stress_over_sigma_star(setup, result, state);
        if (state.loading && stress >= 0.01 * measures.stress_max) {
            log_stress.push_back(std::log10(stress));
            void_ratios.push_back(void_ratio(result, state));
        }
    }
    measures.compressibility = fit_line(log_stress, void_ratios);
    measures.compressibility_points = log_stress.size();
    return measures;
}

CompactionSetup compaction_scene_defaults()
{
    CompactionSetup setup;
    setup.assembly.particles = 40;
    setup.assembly.radius_spread = 0.15;
    setup.assembly.ring.nodes = 16;
    setup.assembly.ring.material.h = 0.1;
    setup.assembly.ring.dt_factor = 0.2;
    return setup;
}

} // namespace softgrain::spd
