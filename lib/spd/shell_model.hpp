// SPD shell model (Trivino et al., section 2): particles and walls as closed or open chains of mass points.
//
// State is stored flat: positions x, velocities v and forces f are vectors of 2 * (number of vertices)
// entries; each shell owns a contiguous range of vertices. An open shell ends on an "absent" vertex
// (section 2.1, Fig. 2): its last element and the bending hinges at its two ends do not exist. A wall is a
// rigid open shell (reference angles 0) whose vertices are frozen (inverse mass 0) and move with a
// prescribed velocity. Internal laws are incremental (eqs. (1)-(4)): the history (axial forces, hinge
// torques, core pressure) lives in per-element, per-vertex and per-shell records updated at each force
// evaluation from the change of geometry since the previous one. Cohesive links between shells (section 6)
// are optional per-link records (lib/spd/cohesive_link.hpp) with their broken state.
//
// ShellModel owns the vertex state, the shells' laws (eqs. (1)-(3)) and the time step (velocity Verlet, its
// RATTLE form with an incompressible core); three parts do one job each: the cores (ShellCores,
// spd/shell_cores.hpp: eq. (4), the RATTLE constraint of an incompressible core), the contacts
// (ShellContacts, spd/shell_contacts.hpp: candidates, eqs. (6)-(7), the gather) and the cohesive links
// (ShellLinks, spd/shell_links.hpp). The time-step limits (dt_c and the stability limit a run's dt is checked
// against) are functions of the model, spd/time_step_limits.hpp.
#pragma once

#include "core/resources.hpp"
#include "core/vector.hpp"
#include "spd/calibration.hpp"
#include "spd/cohesive_link.hpp"
#include "spd/shell.hpp"
#include "spd/shell_contacts.hpp"
#include "spd/shell_cores.hpp"
#include "spd/shell_links.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace softgrain {
class Archive;
}

namespace softgrain::spd {

// The memory of a ShellModel of `vertices` vertices (the scene's parameters named in `what`): 530 B per
// vertex, measured as the growth of peak RSS between spd.bench runs of 200 and 3200 rings of 32 vertices
// (vertex state, laws, cell list and contact candidates).
MemoryEstimate shell_model_memory(double vertices, const std::string& what);

class ShellModel
{
  public:
    // Adds a shell with the given vertex positions (columns) and mass per vertex; the current geometry
    // defines the reference lengths and angles. Returns its index.
    int add_shell(const Points<2>& vertices, Shell shell, double vertex_mass);

    // Freezes one degree of freedom (0 = x, 1 = y) of a vertex: it keeps its velocity (zero by default).
    void freeze(int vertex, int component);
    void set_contact_law(ContactLaw law) { contacts_.set_law(law); }
    const ContactLaw& contact_law() const { return contacts_.law(); }
    // Cohesive links between vertices of different shells (section 6, lib/spd/cohesive_link.hpp): their
    // forces are added at each force evaluation, a link whose yield function eq. (39) reaches 0 breaks for
    // good and adds no force from then on (decision spd-tissue-link-breaking). Scenes without links pay
    // nothing.
    void set_cohesive_links(std::vector<CohesiveLink> links, const CohesiveLaw& law)
    {
        links_.set(std::move(links), law);
    }
    const std::vector<CohesiveLink>& links() const { return links_.links(); }
    const CohesiveLaw& link_law() const { return links_.law(); }
    int broken_links() const { return links_.broken(); }
    // Sum of the intact links' energies k_n u_n^2/2 + k_t u_t^2/2 [J].
    double link_energy() const { return links_.energy(view()); }
    // A constant external force on a vertex [N] (a point load, section 3).
    void set_applied_force(int vertex, const Vec2& force) { applied_.segment<2>(2 * vertex) = force; }

    // Forces at the current positions; updates the incremental state (eqs. (1)-(4), (7)) from the geometry
    // change since the previous call; dt converts the (half-step) velocities into the tangential
    // displacement increments of eq. (7). Called once per time step by step().
    void compute_forces(double dt);

    // One velocity-Verlet step (section 2.4) with viscous damping c v [N s/m] on the free vertices; with an
    // incompressible core, its RATTLE form (step_constrained). Throws NumericalError (exit 3) on a non-finite
    // state, naming dt/dt_c, and, with contacts, on a vertex that moved farther than its contact radius in
    // the step (a blow-up that can pass through elements), naming the vertex and its particle.
    void step(double dt, double damping);

    // Measures.
    double area(int shell) const; // polygon area [m^2], CCW positive
    // Area of a closed shell when it was added (its reference geometry) [m^2].
    double reference_area(int shell) const { return cores_.reference_volume(shell) / shells_[shell].depth; }
    double stretch_energy() const; // W_s = sum F^2 / (2 k_s) over elastic shells [J]
    double bending_energy() const; // W_b = sum M^2 / (2 k_b) [J]
    // Elastic energy stored in one shell: its W_s + W_b, plus the core energy V0 p^2 / (2 K_Omega) of the
    // undrained core of eq. (4) (finite K_Omega > 0 only; an incompressible core stores none) [J].
    double elastic_energy(int shell) const;
    // From eq. (4), or the constraint multiplier of an incompressible core; excluding the applied pressure
    // [Pa].
    double core_pressure(int shell) const { return cores_.pressure(shell); }
    double kinetic_energy() const;
    // Largest unbalanced force on a free degree of freedom, damping excluded [N].
    double max_free_force() const;
    int max_free_force_vertex() const;        // the vertex holding max_free_force()
    std::string describe_vertex(int i) const; // "vertex i of particle p", for diagnoses
    Vec2 vertex(int i) const { return {x_[2 * i], x_[2 * i + 1]}; }
    std::vector<Vec2> outline(int shell) const; // the vertex positions of a shell, in order [m]
    Vec2 velocity(int i) const { return {v_[2 * i], v_[2 * i + 1]}; }
    Vec2 force(int i) const { return {f_[2 * i], f_[2 * i + 1]}; }
    // Sum of contact forces received by the vertices of `shell` from other shells, and per vertex.
    Vec2 contact_force_on(int shell) const { return contacts_.force_on(shells_[shell]); }
    double contact_normal(int vertex) const { return contacts_.normal(vertex); }
    // A contact of the last force evaluation (spd/shell_contacts.hpp); the active ones in candidate order.
    using ContactView = spd::ContactView;
    std::vector<ContactView> active_contacts() const { return contacts_.active(view()); }
    const std::vector<Shell>& shells() const { return shells_; }
    int vertices() const { return static_cast<int>(x_.size() / 2); }
    double element_force(int element_first_vertex) const { return axial_[element_first_vertex]; }
    // Length of an element at the last force evaluation [m].
    double element_length(int element_first_vertex) const { return length_prev_[element_first_vertex]; }
    // The stiffness of a shell's finite core, K_Omega s^2 sum_k |dA/dx_k|^2 / V0 (ShellCores::stiffness, for
    // dt_c: spd/time_step_limits.hpp); 0 without one [N/m].
    double core_stiffness(int shell) const { return cores_.stiffness(view(), shell); }
    double hinge_torque(int vertex) const { return torque_[vertex]; }

    // Sets the velocities of all free degrees of freedom to zero (a packing released at rest).
    void stop();
    // Replaces the laws of a shell (e.g. switching plasticity on after an elastic deposition); the current
    // forces and torques are kept and clamped by the new thresholds at the next force evaluation.
    void set_laws(int shell, const ShellLaws& laws) { shells_[shell].laws = laws; }

    // Kinematic control of a rigid shell: sets the velocity of all its vertices.
    void set_velocity(int shell, const Vec2& velocity);
    // Sets the velocity of one vertex (a frozen vertex then moves kinematically, e.g. a clamped boundary).
    void set_vertex_velocity(int i, const Vec2& velocity) { v_.segment<2>(2 * i) = velocity; }
    // Moves one vertex (a prescribed configuration, e.g. for finite-difference checks of the forces).
    void set_vertex(int i, const Vec2& position) { x_.segment<2>(2 * i) = position; }
    void translate(int shell, const Vec2& displacement);
    std::int64_t steps() const { return steps_; }
    double min_vertex_mass() const; // over free vertices [kg]
    // Writes or reads the complete state (positions, velocities, forces, the incremental histories of eqs.
    // (1)-(4) and (7), the contact list) for a checkpoint (core/checkpoint.hpp).
    void transfer(Archive& archive);

    // Contact detection cost (decision spd-contact-detection): (vertex, element) pairs checked per step, and
    // rebuilds of the vertex neighbour list so far.
    std::size_t contact_candidates() const { return contacts_.candidates(); }
    int neighbour_list_builds() const { return contacts_.list_builds(); }
    // Skin of the vertex neighbour list [m] (0 before the first step).
    double neighbour_skin() const { return contacts_.skin(); }

  private:
    // The state its parts read: the cores, the contacts and the links.
    ShellView view() const { return {x_, v_, shells_, shell_of_}; }
    void internal_forces(const Shell& s);
    double shell_stretch_energy(const Shell& s) const;
    double shell_bending_energy(const Shell& s) const;
    void step_constrained(double dt, double damping);
    // Parallel regions open above this many vertices: below, a region costs more than it saves.
    static constexpr int parallel_vertices = 2000;
    // What the threads of a parallel region found, shared by them: each thread ORs its own findings in
    // (atomic writes); the region's owner acts on them after it.
    struct RegionFlags
    {
        bool list_stale = false; // a vertex moved beyond half the skin: the contact candidates are rebuilt
        bool overlap = false;    // a contact overlaps beyond 95% of r_i + r_j (exit 3 after the region)
        bool non_finite = false; // a position or velocity is not finite (exit 3)
        bool too_long = false;   // a vertex moved farther than its contact radius in one step (exit 3)
        // One slot per stage that can fail, each written at one place only: a thread that has passed a
        // stage's barrier may run ahead and fail in the next stage while another thread still reads the
        // previous stage's slot, and both must take the same branch (else their barriers no longer pair).
        std::exception_ptr list_failure;  // rebuilding the contact candidates
        std::exception_ptr failure;       // the contact groups (work-shared loop)
        std::exception_ptr links_failure; // the cohesive links
        long failed_iteration = -1;       // of the contact groups: the lowest one that failed is kept
        // The first failure in the order a serial evaluation meets them; null when none.
        const std::exception_ptr& first_failure() const
        {
            return list_failure ? list_failure : failure ? failure : links_failure;
        }
    };
    // The force evaluation inside an open parallel region, with two per-vertex hooks that let a time step
    // share its loops over the vertices: before(i) runs before vertex i's force is reset, after(i) once its
    // force is complete.
    template <class BeforeVertex, class AfterVertex>
    void forces_in_region(double dt, RegionFlags& flags, BeforeVertex&& before, AfterVertex&& after);
    void throw_region_failure(const RegionFlags& flags, double dt) const;
    bool step_too_long(int i, double dt) const;
    double speed_squared(int i) const { return v_[2 * i] * v_[2 * i] + v_[2 * i + 1] * v_[2 * i + 1]; }
    bool vertex_finite(int i) const
    {
        return std::isfinite(x_[2 * i]) && std::isfinite(x_[2 * i + 1]) && std::isfinite(v_[2 * i]) &&
               std::isfinite(v_[2 * i + 1]);
    }
    void throw_step_too_long(double dt) const;
    int first_non_finite_vertex() const; // -1 if every position and velocity is finite
    void throw_non_finite(double dt) const;
    int shell_of(int vertex) const { return shell_of_[vertex]; }
    // The free degree of freedom with the largest |f| (damping excluded) and that |f|.
    std::pair<Eigen::Index, double> largest_free_force() const;
    void add_force(int i, const Vec2& F)
    {
        f_[2 * i] += F.x();
        f_[2 * i + 1] += F.y();
    }

    std::vector<Shell> shells_;
    Eigen::VectorXd x_, v_, f_, inverse_mass_, applied_;
    std::vector<double> length_prev_, axial_; // per element (indexed by its first vertex): l at last call, F
    std::vector<double> torque_;              // per vertex: M
    // Per element (indexed by its first vertex): the element vector x_(k+1) - x_k at the last call (state:
    // the rotation since then gives the hinge increments); scratch of internal_forces: its squared length and
    // the rotation of this call.
    std::vector<Vec2> edge_;
    std::vector<double> edge_squared_, edge_rotation_;
    std::vector<int> shell_of_; // per vertex
    ShellCores cores_;
    ShellContacts contacts_;
    ShellLinks links_;
    std::int64_t steps_ = 0;
};

// Quasi-static relaxation (section 4.1, "complete relaxation after each strain increment"): damped
// velocity-Verlet steps until the largest unbalanced force on a free degree of freedom (damping excluded)
// is below force_tolerance [N]; checked every 16 steps. Throws NumericalError if max_steps do not suffice,
// naming the vertex that holds the residual and whether its force reverses at every step (one step more).
// Returns the number of steps taken. A long relaxation can be resumed: `taken` steps were taken before (a
// multiple of 16), and `after_check(n)` is called after each unsuccessful check with the steps taken so far
// (where a checkpoint may be written).
long relax(ShellModel& model, double dt, double damping, double force_tolerance, long max_steps,
           long taken = 0, const std::function<void(long)>& after_check = {});

} // namespace softgrain::spd
