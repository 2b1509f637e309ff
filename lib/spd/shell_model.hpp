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
#pragma once

#include "core/neighbour_list.hpp"
#include "core/resources.hpp"
#include "core/vector.hpp"
#include "spd/calibration.hpp"
#include "spd/cohesive_link.hpp"

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

// One shell: its vertex range, topology and laws. Stiffnesses of a frozen (rigid) shell are unused.
struct Shell
{
    int first = 0, count = 0; // vertices [first, first + count)
    bool closed = true;       // closed ring, or open chain ending on the absent vertex
    bool rigid = false;       // all vertices frozen, moved kinematically (walls, section 4.1)
    ShellLaws laws;
    double depth = 1;  // out-of-plane length s [m]
    double radius = 0; // vertex disk / sphero-segment radius r [m]
    // Undrained core modulus, eq. (4) [Pa]; 0: no core stiffness; INFINITY: incompressible core, the limit
    // eta -> inf of eq. (24), imposed as the exact constraint A(x) = A0 whose multiplier is the core pressure
    // (ShellModel::step, decision spd-eta-infinity).
    double K_Omega = 0;
    double pressure_applied = 0; // constant (drained) pressure acting inside the shell [Pa]
    int elements() const { return closed ? count : count - 1; }
    bool has_hinge(int local) const { return closed || (local > 0 && local < count - 1); }
    bool incompressible() const { return closed && std::isinf(K_Omega); }
};

// Contact law between shells: normal eq. (6), incremental Coulomb friction eq. (7) when mu > 0 (the scenes of
// sections 3-4 are frictionless: decision spd-ring-walls).
struct ContactLaw
{
    double k_n = 0; // [N/m]
    double k_t = 0; // [N/m]
    double mu = 0;  // friction coefficient
    // Normal viscous damping c_n [N s/m] for quasi-static relaxation only (decision spd-contact-damping): a
    // force -c_n (v_rel . n) while in contact, the total normal force kept repulsive. It vanishes at rest and
    // removes the chatter of a vertex at the edge of a flat contact (not part of eq. (6)).
    double normal_damping = 0;
};

class ShellModel
{
  public:
    // Adds a shell with the given vertex positions (columns) and mass per vertex; the current geometry
    // defines the reference lengths and angles. Returns its index.
    int add_shell(const Points<2>& vertices, Shell shell, double vertex_mass);

    // Freezes one degree of freedom (0 = x, 1 = y) of a vertex: it keeps its velocity (zero by default).
    void freeze(int vertex, int component);
    void set_contact_law(ContactLaw law) { contact_ = law; }
    // Cohesive links between vertices of different shells (section 6, lib/spd/cohesive_link.hpp): their
    // forces are added at each force evaluation, a link whose yield function eq. (39) reaches 0 breaks for
    // good and adds no force from then on (decision spd-tissue-link-breaking). Scenes without links pay
    // nothing.
    void set_cohesive_links(std::vector<CohesiveLink> links, const CohesiveLaw& law)
    {
        links_ = std::move(links);
        link_law_ = law;
    }
    const std::vector<CohesiveLink>& links() const { return links_; }
    const CohesiveLaw& link_law() const { return link_law_; }
    int broken_links() const;
    double link_energy() const; // sum of the intact links' energies k_n u_n^2/2 + k_t u_t^2/2 [J]
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

    // SPD section 2.4: dt_c = sqrt(m / k_max), with k_max the largest of k_s, the bending stiffness
    // 4 k_b / l^2 seen by a vertex, the contact stiffness k_n, the link stiffnesses and the core stiffness
    // K_Omega s^2 sum_k |dA/dx_k|^2 / V0 (the eigenvalue of the rank-one core Hessian, decision
    // spd-dtc-kmax).
    double critical_time_step() const;

    // Largest stable time step of the scheme (decision spd-stability-limit): min(dt_c, the limit of the
    // damped normal contact). The contact damping c_n enters with the half-step velocity, so a vertex on a
    // wall is the damped oscillator v' = v - h (omega^2 x + gamma v), x' = x + h v' (omega^2 = k_n/m,
    // gamma = c_n/m), stable iff h^2 omega^2 + 2 h gamma < 4:
    //   h < (sqrt(gamma^2 + 4 omega^2) - gamma)/omega^2,
    // i.e. 2 (sqrt(2) - 1) sqrt(m/k_n) = 0.83 sqrt(m/k_n) for the critical c_n = 2 sqrt(m k_n). Two free
    // shells can touch vertex to vertex: each vertex then lies within reach of the other's element end, so
    // the contact is counted both ways, and the relative motion of the two vertices (reduced mass m/2) sees
    // 2 k_n and 2 c_n: omega^2 = 4 k_n/m, gamma = 4 c_n/m, the limit (sqrt(5) - 2) sqrt(m/k_n)
    // = 0.236 sqrt(m/k_n) for the critical c_n (decision spd-vertex-pair-stability). Above it the
    // pair flips at every step, a limit cycle that the one-sided normal force keeps bounded.
    double stable_time_step() const;
    // Throws NumericalError (exit 3) naming dt, the limit and dt_c if dt > stable_time_step().
    void check_time_step(double dt) const;

    // Measures.
    double area(int shell) const; // polygon area [m^2], CCW positive
    // Area of a closed shell when it was added (its reference geometry) [m^2].
    double reference_area(int shell) const { return core_V0_[shell] / shells_[shell].depth; }
    double stretch_energy() const; // W_s = sum F^2 / (2 k_s) over elastic shells [J]
    double bending_energy() const; // W_b = sum M^2 / (2 k_b) [J]
    // Elastic energy stored in one shell: its W_s + W_b, plus the core energy V0 p^2 / (2 K_Omega) of the
    // undrained core of eq. (4) (finite K_Omega > 0 only; an incompressible core stores none) [J].
    double elastic_energy(int shell) const;
    // From eq. (4), or the constraint multiplier of an incompressible core; excluding the applied pressure
    // [Pa].
    double core_pressure(int shell) const { return core_p_[shell]; }
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
    Vec2 contact_force_on(int shell) const;
    double contact_normal(int vertex) const { return contact_normal_[vertex]; }
    // A contact of the last force evaluation: vertex against the element (a, b) of another shell, the
    // closest point of the element [m], the normal force f_n (eq. (6)) and tangential force f_t (eq. (7)) [N]
    // and the force on the vertex [N] (the element's ends receive its opposite).
    struct ContactView
    {
        int vertex, a, b;
        Vec2 point;
        double normal_force, tangential_force;
        Vec2 force;
    };
    std::vector<ContactView> active_contacts() const; // in candidate order
    const std::vector<Shell>& shells() const { return shells_; }
    int vertices() const { return static_cast<int>(x_.size() / 2); }
    double element_force(int element_first_vertex) const { return axial_[element_first_vertex]; }
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
    std::size_t contact_candidates() const { return candidates_.size(); }
    int neighbour_list_builds() const { return list_builds_; }
    // Skin of the vertex neighbour list [m] (0 before the first step).
    double neighbour_skin() const { return neighbours_ ? neighbours_->skin() : 0.0; }

  private:
    // Neighbours along a closed shell (local index wrapped without an integer division: these run for every
    // vertex of every step).
    int next(const Shell& s, int local) const { return s.first + (local + 1 == s.count ? 0 : local + 1); }
    int prev(const Shell& s, int local) const { return s.first + (local == 0 ? s.count - 1 : local - 1); }
    void internal_forces(const Shell& s);
    double shell_stretch_energy(const Shell& s) const;
    double shell_bending_energy(const Shell& s) const;
    void core_forces(int index);
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
        std::exception_ptr failure;
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
    // dA/dx_k = perp(x_(k+1) - x_(k-1))/2, perp(d) = (d_y, -d_x), of a closed shell whose vertex coordinates
    // are xs (2 count entries): outward for a CCW polygon [m].
    static Vec2 vertex_area_gradient(const double* xs, int count, int k);
    Eigen::VectorXd area_gradient(const Shell& s, const Eigen::Ref<const Eigen::VectorXd>& xs) const;
    void update_contact_candidates();
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
    Eigen::VectorXd contact_force_;           // per dof: contact force received [N]
    std::vector<double> length_prev_, axial_; // per element (indexed by its first vertex): l at last call, F
    std::vector<double> torque_;              // per vertex: M
    // Per element (indexed by its first vertex): the element vector x_(k+1) - x_k at the last call (state:
    // the rotation since then gives the hinge increments); scratch of internal_forces: its squared length and
    // the rotation of this call.
    std::vector<Vec2> edge_;
    std::vector<double> edge_squared_, edge_rotation_;
    std::vector<double> core_V_prev_, core_p_, core_V0_; // per shell
    std::vector<double> contact_normal_;                 // per vertex: normal contact force received [N]
    std::vector<int> shell_of_;                          // per vertex
    // A (vertex, element) pair that may touch: the element (a, b) of another shell. It keeps the tangential
    // force f_t of eq. (7) [N] (0 while the pair is not in contact) and, per step, the contact it carries.
    struct Candidate
    {
        int vertex, a, b;
        double reach = 0; // r_i + r_j of the vertex and the element [m]
        double friction = 0;
        bool active = false, overlap = false; // in contact; overlap beyond 95% of r_i + r_j (exit 3)
        double fn = 0, w_a = 0, w_b = 0;      // normal force [N], transfer weights of Fig. 5
        double distance = 0;                  // vertex-element distance while active [m]
        Vec2 force = Vec2::Zero();            // force on the vertex [N]
        void transfer(Archive& archive);
    };
    std::vector<Candidate> candidates_; // sorted by (vertex, a)
    // Start of each run of candidates of one vertex against one other shell, then candidates_.size().
    std::vector<std::size_t> contact_groups_;
    std::optional<NeighbourList<2>> neighbours_;
    double list_length_ = 0; // element length bound L of the list's cutoff [m]
    int list_builds_ = 0;
    bool outside_bounding_box(const Candidate& candidate) const;
    void evaluate_contact(Candidate& candidate, double old_friction, double dt) const;
    bool evaluate_contact_group(std::size_t begin, std::size_t end, double dt);
    // Per vertex, the candidates whose contact acts on it (as the contacting vertex or as an end of the
    // element), in candidate order: gather_terms_[gather_offsets_[i] ... gather_offsets_[i + 1]), each the
    // candidate index m shifted left by 2 with its ContactRole in the low bits. touched_[i] is set when a
    // contact acting on vertex i became active in this step (most vertices touch nothing: their gather is
    // one test) and cleared by its gather.
    enum ContactRole : std::uint32_t { role_vertex = 0, role_end_a = 1, role_end_b = 2 };
    std::vector<std::size_t> gather_offsets_;
    std::vector<std::uint32_t> gather_terms_;
    std::vector<unsigned char> touched_;
    void index_candidates();
    void gather_contact_force(int i);
    void throw_overlap() const;
    void add_link_forces();
    std::vector<CohesiveLink> links_;
    CohesiveLaw link_law_;
    ContactLaw contact_;
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
