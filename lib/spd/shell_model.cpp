#include "spd/shell_model.hpp"

#include "core/checkpoint.hpp"
#include "core/errors.hpp"
#include "core/integrators.hpp"
#include "spd/force_laws.hpp"
#include "spd/time_step_limits.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

namespace softgrain::spd {

int ShellModel::add_shell(const Points<2>& vertices, Shell shell, double vertex_mass)
{
    const int n0 = this->vertices();
    const int n = static_cast<int>(vertices.cols());
    shell.first = n0;
    shell.count = n;
    x_.conservativeResize(2 * (n0 + n));
    v_.conservativeResize(2 * (n0 + n));
    f_.conservativeResize(2 * (n0 + n));
    applied_.conservativeResize(2 * (n0 + n));
    inverse_mass_.conservativeResize(2 * (n0 + n));
    for (int k = 0; k < n; ++k) {
        x_.segment<2>(2 * (n0 + k)) = vertices.col(k);
        v_.segment<2>(2 * (n0 + k)).setZero();
        f_.segment<2>(2 * (n0 + k)).setZero();
        applied_.segment<2>(2 * (n0 + k)).setZero();
        inverse_mass_.segment<2>(2 * (n0 + k)).setConstant(shell.rigid ? 0.0 : 1.0 / vertex_mass);
    }
    length_prev_.resize(n0 + n, 0.0);
    edge_.resize(n0 + n, Vec2::Zero());
    edge_squared_.resize(n0 + n, 0.0);
    edge_rotation_.resize(n0 + n, 0.0);
    axial_.resize(n0 + n, 0.0);
    torque_.resize(n0 + n, 0.0);
    shell_of_.resize(n0 + n, static_cast<int>(shells_.size()));
    contacts_.add_vertices(n);
    for (int k = 0; k < shell.elements(); ++k) {
        edge_[n0 + k] = vertex(next_vertex(shell, k)) - vertex(n0 + k);
        length_prev_[n0 + k] = edge_[n0 + k].norm();
    }
    shells_.push_back(shell);
    const int index = static_cast<int>(shells_.size()) - 1;
    cores_.add(view(), index);
    return index;
}

std::vector<Vec2> ShellModel::outline(int shell) const
{
    const Shell& s = shells_[shell];
    std::vector<Vec2> vertices;
    for (int i = s.first; i < s.first + s.count; ++i)
        vertices.push_back(vertex(i));
    return vertices;
}

void ShellModel::freeze(int vertex, int component)
{
    inverse_mass_[2 * vertex + component] = 0.0;
}

void ShellModel::set_velocity(int shell, const Vec2& velocity)
{
    const Shell& s = shells_[shell];
    for (int i = s.first; i < s.first + s.count; ++i)
        v_.segment<2>(2 * i) = velocity;
}

void ShellModel::translate(int shell, const Vec2& displacement)
{
    const Shell& s = shells_[shell];
    for (int i = s.first; i < s.first + s.count; ++i)
        x_.segment<2>(2 * i) += displacement;
}

double ShellModel::area(int shell) const
{
    return shell_area(view(), shells_[shell]);
}

// SPD eqs. (1) and (3): incremental stretch force and hinge torque, applied as axial forces and as two
// couples (eqs. (8)-(9)). The increment of the turning angle theta_k = angle(e_k) - angle(e_(k-1)) since the
// last call is the difference of the rotations of its two elements, each measured from the element's
// previous vector (no wrapping of theta across +-pi is needed).
void ShellModel::internal_forces(const Shell& s)
{
    // Raw views: kept in registers across the stores into f (members would be reloaded after each store).
    const double* x = x_.data();
    double* f = f_.data();
    const auto add = [f](int i, const Vec2& F) {
        f[2 * i] += F.x();
        f[2 * i + 1] += F.y();
    };
    Vec2* edge = edge_.data();
    double *edge_squared = edge_squared_.data(), *edge_rotation = edge_rotation_.data();
    const ShellLaws laws = s.laws;
    for (int k = 0; k < s.elements(); ++k) {
        const int i = s.first + k, j = next_vertex(s, k);
        const Vec2 e(x[2 * j] - x[2 * i], x[2 * j + 1] - x[2 * i + 1]);
        edge_rotation[i] = element_rotation(edge[i], e);
        edge[i] = e;
        edge_squared[i] = e.squaredNorm();
        const double l = std::sqrt(edge_squared[i]);
        const double contraction = length_prev_[i] - l; // compression positive (section 2.2)
        const double F = elastoplastic_update(axial_[i], laws.k_s * contraction, laws.F_Y);
        axial_[i] = F;
        length_prev_[i] = l;
        const Vec2 push = F * e / l; // a compressed element pushes its ends apart
        add(j, push);
        add(i, -push);
    }
    for (int k = 0; k < s.count; ++k) {
        if (!s.has_hinge(k)) continue;
        const int i = s.first + k, a = previous_vertex(s, k), b = next_vertex(s, k);
        const double dtheta = edge_rotation[i] - edge_rotation[a];
        const double M = elastoplastic_update(torque_[i], laws.k_b * dtheta, laws.M_Y);
        torque_[i] = M;
        const ThreeForces couples = edge_couples(edge[a], edge_squared[a], edge[i], edge_squared[i], M);
        add(a, couples.previous);
        add(i, couples.centre);
        add(b, couples.next);
    }
}

namespace {
// Runs `task` on one thread of a parallel region; an exception cannot leave the region, so it is kept in
// `failure` and rethrown by the caller after the region.
template <class Task>
void on_one_thread(std::exception_ptr& failure, Task&& task)
{
#pragma omp single
    try {
        task();
    } catch (...) {
        failure = std::current_exception();
    }
}

// Keeps the exception of iteration `iteration` of a work-shared loop if no earlier iteration failed: the
// region reports the same failure whatever the number of threads.
template <class Flags>
void keep_first_failure(Flags& flags, long iteration, std::exception_ptr failure)
{
#pragma omp critical(spd_region_failure)
    if (!flags.failure || iteration < flags.failed_iteration) {
        flags.failure = std::move(failure);
        flags.failed_iteration = iteration;
    }
}

// Sets flag to true from one thread of a region (flags only ever turn true within a region).
void raise_flag(bool& flag)
{
#pragma omp atomic write
    flag = true;
}
} // namespace

// The force evaluation inside an open parallel region (orphaned work-sharing: serial when none is open).
// Each shell writes the forces of its own vertices only, each contact group its own records, and each vertex
// gathers its contact forces in candidate order: the results do not depend on the number of threads, bit
// for bit. Three barriers when the candidates stay: after the reset (the list check must be agreed on),
// after the contacts, after the gather.
template <class BeforeVertex, class AfterVertex>
void ShellModel::forces_in_region(double dt, RegionFlags& flags, BeforeVertex&& before, AfterVertex&& after)
{
    const bool contacts = contacts_.enabled();
    const int n = vertices();
    bool stale = contacts && !contacts_.listed(); // this thread's share of flags.list_stale
#pragma omp for schedule(static) nowait
    for (int i = 0; i < n; ++i) {
        before(i);
        f_.segment<2>(2 * i) = applied_.segment<2>(2 * i);
    }
    // The same static schedule: each thread checks the vertices it has just moved (no barrier needed).
    if (contacts && !stale) {
#pragma omp for schedule(static) nowait
        for (int i = 0; i < n; ++i)
            if (contacts_.moved_beyond_half_skin(i, vertex(i))) stale = true;
    }
    if (stale) raise_flag(flags.list_stale);
#pragma omp barrier
    if (flags.list_stale)
        on_one_thread(flags.list_failure, [&] { contacts_.update_candidates(view(), steps_); });
    if (flags.list_failure) return; // written only in the single: every thread sees it after its barrier
    const int n_shells = static_cast<int>(shells_.size());
    const long n_groups = contacts ? contacts_.groups() : 0;
#pragma omp for schedule(dynamic, 4) nowait
    for (int p = 0; p < n_shells; ++p) {
        const Shell& s = shells_[p];
        if (s.rigid) continue;
        internal_forces(s);
        cores_.add_forces(view(), p, f_);
    }
    bool overlap = false;
#pragma omp for schedule(static)
    for (long g = 0; g < n_groups; ++g) {
        try {
            overlap = contacts_.evaluate_group(view(), g, dt) || overlap;
        } catch (...) { // e.g. a degenerate element of a state gone non-finite
            keep_first_failure(flags, g, std::current_exception());
        }
    }
    if (overlap) raise_flag(flags.overlap); // acted on after the region
    if (flags.failure) return;              // set before the barrier that ends the loop: every thread sees it
    if (!links_.empty()) on_one_thread(flags.links_failure, [&] { links_.add_forces(view(), f_); });
    if (flags.links_failure) return;
#pragma omp for schedule(static) nowait // the region ends next, or its owner goes on with the same vertices
    for (int i = 0; i < n; ++i) {
        if (contacts)
            add_force(i, contacts_.gather(i));
        else
            contacts_.clear(i);
        after(i);
    }
}

void ShellModel::compute_forces(double dt)
{
    RegionFlags flags;
    const auto nothing = [](int) {};
#pragma omp parallel if (vertices() > parallel_vertices)
    forces_in_region(dt, flags, nothing, nothing);
    throw_region_failure(flags, dt);
}

void ShellModel::step(double dt, double damping)
{
    if (steps_ == 0) compute_forces(dt);
    const bool constrained =
        std::any_of(shells_.begin(), shells_.end(), [](const Shell& s) { return s.incompressible(); });
    // Only a vertex faster than r_min/dt (r_min the smallest contact radius of the free shells) can have
    // moved farther than its own radius: the cheap first test of step_too_long.
    double r_min = INFINITY;
    if (contacts_.enabled())
        for (const Shell& s : shells_)
            if (!s.rigid && s.radius > 0) r_min = std::min(r_min, s.radius);
    const double speed_squared_limit = r_min * r_min / (dt * dt);
    const auto moved_too_far = [&](int i) {
        return speed_squared(i) > speed_squared_limit && step_too_long(i, dt);
    };
    RegionFlags flags;
    if (constrained) {
        step_constrained(dt, damping);
        for (int i = 0; i < vertices(); ++i) {
            flags.non_finite = flags.non_finite || !vertex_finite(i);
            flags.too_long = flags.too_long || moved_too_far(i);
        }
    } else {
        // Velocity Verlet (kick-drift-kick, core/integrators.hpp) with the viscous damping -c v acting on the
        // free degrees of freedom (the inverse mass masks the frozen ones), the operations of
        // velocity_verlet_step in its order, written per vertex so that the whole step is one parallel
        // region: the first half-kick and the drift run in the loop that resets the forces, the second
        // half-kick and the checks of the new state in the loop that completes them.
        const double half_dt = 0.5 * dt;
        double *const x = x_.data(), *const v = v_.data();
        const double *const f = f_.data(), *const inverse_mass = inverse_mass_.data();
        const auto kick = [=](int k) { v[k] += half_dt * inverse_mass[k] * (f[k] - damping * v[k]); };
#pragma omp parallel if (vertices() > parallel_vertices)
        {
            bool non_finite = false, too_long = false; // this thread's findings
            forces_in_region(
                dt, flags,
                [&](int i) {
                    kick(2 * i);
                    kick(2 * i + 1);
                    x[2 * i] += dt * v[2 * i];
                    x[2 * i + 1] += dt * v[2 * i + 1];
                },
                [&](int i) {
                    kick(2 * i);
                    kick(2 * i + 1);
                });
            // The checks of the new state, each thread on the vertices it has just kicked (the static
            // schedule of the gather loop); a tight loop of its own costs less than the checks inside it.
            if (!flags.first_failure()) { // no slot is written after the last barrier of the evaluation
#pragma omp for schedule(static) nowait
                for (int i = 0; i < vertices(); ++i) {
                    non_finite = non_finite || !vertex_finite(i);
                    too_long = too_long || moved_too_far(i);
                }
            }
            if (non_finite) raise_flag(flags.non_finite);
            if (too_long) raise_flag(flags.too_long);
        }
    }
    ++steps_;
    throw_region_failure(flags, dt);
}

// In the order a serial step meets them: an exception of a task, a contact overlap (during the force
// evaluation), a non-finite state, a step longer than a contact radius. A task that failed on a non-finite
// state (a contact with an element of non-finite length) failed because of it: the state is the diagnosis.
void ShellModel::throw_region_failure(const RegionFlags& flags, double dt) const
{
    if (flags.first_failure()) {
        if (first_non_finite_vertex() < 0) std::rethrow_exception(flags.first_failure());
        throw_non_finite(dt);
    }
    if (flags.overlap) contacts_.throw_overlap(view(), steps_);
    if (flags.non_finite) throw_non_finite(dt);
    if (flags.too_long) throw_step_too_long(dt);
}

int ShellModel::first_non_finite_vertex() const
{
    for (int i = 0; i < vertices(); ++i)
        if (!vertex_finite(i)) return i;
    return -1;
}

void ShellModel::throw_non_finite(double dt) const
{
    const int bad = first_non_finite_vertex();
    std::ostringstream cause;
    cause << "vertex " << bad << " of particle " << shell_of(bad)
          << " first: time step above the stability limit (dt/dt_c = " << dt / critical_time_step(*this)
          << ", dt_c = sqrt(m/k_max) = " << critical_time_step(*this) << " s) or an unstable load";
    throw NumericalError("vertex positions (non-finite)", steps_, cause.str());
}

// A vertex that moves farther than its contact radius r in one step can pass through an element: the
// sphero-segment law (section 2.3) sees a contact only while the vertex stays on its side. Such a step is the
// sign of an energy blow-up (a time step above the stability limit, an exploding load), long before the
// state turns non-finite: exit 3 naming the vertex, its particle and the step. Frozen vertices (walls,
// clamps) move as prescribed and are not checked.
bool ShellModel::step_too_long(int i, double dt) const
{
    const double r = shells_[shell_of(i)].radius;
    if (r == 0 || (inverse_mass_[2 * i] == 0 && inverse_mass_[2 * i + 1] == 0)) return false;
    return speed_squared(i) * dt * dt > r * r;
}

void ShellModel::throw_step_too_long(double dt) const
{
    for (int i = 0; i < vertices(); ++i) {
        if (!step_too_long(i, dt)) continue;
        const double moved = velocity(i).norm() * dt;
        std::ostringstream cause;
        cause << "vertex " << i << " of particle " << shell_of(i) << " moved " << moved
              << " m in one step, more than its contact radius r = " << shells_[shell_of(i)].radius
              << " m (it can pass through an element): an energy blow-up, e.g. dt/dt_c = "
              << dt / critical_time_step(*this) << " above the stable "
              << stable_time_step(*this) / critical_time_step(*this) << ", or an exploding load";
        throw NumericalError("vertex step length", steps_, cause.str());
    }
}

// RATTLE (H. C. Andersen, J. Comput. Phys. 52 (1983) 24) for incompressible cores, eq. (4) in the limit
// K_Omega -> inf (eta = inf, eq. (24), decision spd-eta-infinity): velocity Verlet with the constraint force
// mu dA/dx on each incompressible shell, its two stages imposed by the cores (spd/shell_cores.hpp): the
// position stage corrects the half-step velocities so that the drift keeps the areas A0, the velocity stage
// keeps dA/dt = 0 at the new positions and leaves the constraint force in f_, so that the stored force is the
// one the shell feels (relaxation criterion).
void ShellModel::step_constrained(double dt, double damping)
{
    Eigen::VectorXd f = f_;
    add_viscous_damping(f, v_, damping);
    v_.array() += 0.5 * dt * inverse_mass_.array() * f.array();
    cores_.constrain_positions(view(), inverse_mass_, dt, v_, steps_);
    x_ += dt * v_;
    compute_forces(dt);
    f = f_;
    add_viscous_damping(f, v_, damping);
    v_.array() += 0.5 * dt * inverse_mass_.array() * f.array();
    cores_.constrain_velocities(view(), inverse_mass_, dt, v_, f_);
}

double ShellModel::min_vertex_mass() const
{
    double m = INFINITY;
    for (Eigen::Index d = 0; d < inverse_mass_.size(); ++d)
        if (inverse_mass_[d] > 0) m = std::min(m, 1.0 / inverse_mass_[d]);
    return m;
}

double ShellModel::shell_stretch_energy(const Shell& s) const
{
    double W = 0;
    for (int k = 0; k < s.elements(); ++k)
        W += axial_[s.first + k] * axial_[s.first + k] / (2 * s.laws.k_s);
    return W;
}

double ShellModel::shell_bending_energy(const Shell& s) const
{
    double W = 0;
    for (int k = 0; k < s.count; ++k)
        if (s.has_hinge(k)) W += torque_[s.first + k] * torque_[s.first + k] / (2 * s.laws.k_b);
    return W;
}

double ShellModel::stretch_energy() const
{
    double W = 0;
    for (const Shell& s : shells_)
        if (!s.rigid) W += shell_stretch_energy(s);
    return W;
}

double ShellModel::bending_energy() const
{
    double W = 0;
    for (const Shell& s : shells_)
        if (!s.rigid) W += shell_bending_energy(s);
    return W;
}

double ShellModel::elastic_energy(int shell) const
{
    const Shell& s = shells_[shell];
    if (s.rigid) return 0.0;
    return shell_stretch_energy(s) + shell_bending_energy(s) + cores_.energy(view(), shell);
}

void ShellModel::stop()
{
    for (Eigen::Index d = 0; d < v_.size(); ++d)
        if (inverse_mass_[d] > 0) v_[d] = 0;
}

double ShellModel::kinetic_energy() const
{
    double K = 0;
    for (Eigen::Index d = 0; d < v_.size(); ++d)
        if (inverse_mass_[d] > 0) K += 0.5 * v_[d] * v_[d] / inverse_mass_[d];
    return K;
}

std::pair<Eigen::Index, double> ShellModel::largest_free_force() const
{
    std::pair<Eigen::Index, double> largest{0, 0.0};
    for (Eigen::Index d = 0; d < f_.size(); ++d)
        if (inverse_mass_[d] > 0 && std::abs(f_[d]) > largest.second) largest = {d, std::abs(f_[d])};
    return largest;
}

double ShellModel::max_free_force() const
{
    return largest_free_force().second;
}

int ShellModel::max_free_force_vertex() const
{
    return static_cast<int>(largest_free_force().first / 2);
}

std::string ShellModel::describe_vertex(int i) const
{
    return "vertex " + std::to_string(i) + " of particle " + std::to_string(shell_of(i));
}

MemoryEstimate shell_model_memory(double vertices, const std::string& what)
{
    return per_item_memory(vertices, 530.0, what);
}

} // namespace softgrain::spd

namespace softgrain::spd {

void ShellModel::transfer(Archive& archive)
{
    archive(shells_);
    for (Eigen::VectorXd* state : {&x_, &v_, &f_, &inverse_mass_, &applied_})
        archive(*state);
    contacts_.transfer_forces(archive);
    archive(edge_);
    for (std::vector<double>* history : {&length_prev_, &axial_, &torque_})
        archive(*history);
    cores_.transfer(archive);
    contacts_.transfer_normals(archive);
    archive(shell_of_);
    contacts_.transfer_candidates(archive, shell_of_, steps_);
    if (archive.loading()) { // the scratch of the forces
        edge_squared_.assign(vertices(), 0.0);
        edge_rotation_.assign(vertices(), 0.0);
    }
    links_.transfer(archive);
    contacts_.transfer_law(archive);
    archive(steps_);
}

long relax(ShellModel& model, double dt, double damping, double force_tolerance, long max_steps, long taken,
           const std::function<void(long)>& after_check)
{
    for (long n = taken + 1; n <= max_steps; ++n) {
        model.step(dt, damping);
        if (n % 16 != 0) continue;
        if (model.max_free_force() < force_tolerance) return n;
        if (after_check) after_check(n);
    }
    // Which vertex holds the residual, and whether its force reverses from one step to the next (one more
    // step is taken to see it): the period-2 mode of a contact configuration above its limit (decision
    // spd-vertex-pair-stability) rather than a slow approach to rest.
    const int i = model.max_free_force_vertex();
    const double residual = model.max_free_force();
    const Vec2 before = model.force(i);
    model.step(dt, damping);
    const bool reverses = model.force(i).dot(before) < -0.5 * before.squaredNorm();
    std::ostringstream cause;
    cause << "relaxation not reached in " << max_steps << " steps (largest unbalanced force " << residual
          << " N > tolerance " << force_tolerance << " N, on " << model.describe_vertex(i) << ")";
    if (reverses)
        cause << ": its force reverses at every step, the period-2 oscillation of the scheme: dt = "
              << dt / critical_time_step(model)
              << " dt_c is above the stability limit of the contacts there (the limit checked is "
              << stable_time_step(model) / critical_time_step(model) << " dt_c)";
    else
        cause << ": damping too weak or too strong for the slowest mode, or dt = "
              << dt / critical_time_step(model) << " dt_c too close to the stability limit "
              << stable_time_step(model) / critical_time_step(model) << " dt_c (contact chatter)";
    throw NumericalError("quasi-static relaxation", model.steps(), cause.str());
}

} // namespace softgrain::spd
