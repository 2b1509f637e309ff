// Contact detection of SPD assemblies (section 2.3, decision spd-contact-detection): the cell-list
// candidates find every sphero-segment contact of the all-pairs search while the rings move, the forces do
// not depend on the number of OpenMP threads, and the work per vertex stays bounded as the assembly grows
// (O(N)).
#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "core/rng.hpp"
#include "spd/assembly.hpp"
#include "spd/force_laws.hpp"
#include "spd/time_step_limits.hpp"
#include "support/tolerance.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace softgrain;
using namespace softgrain::spd;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {
// Thick rings (h = 0.1 R) of 16 vertices, slightly polydisperse (Delta R/R = 0.02), on a square lattice of
// pitch 2 (R_max + r) in a box, launched with random velocities of 0.05 r per time step so that they collide
// within a few tens of steps; contact damping off (the normal force is then a function of the positions only,
// eq. (6)).
struct Jostling
{
    Assembly a;
    double dt, k_n;
};
Jostling jostling_rings(int particles, double speed_per_step)
{
    AssemblySetup setup;
    setup.particles = particles;
    setup.ring.nodes = 16;
    setup.radius_spread = 0.02;
    setup.ring.material.h = 0.1; // vertex radius r = 0.05 R: contacts last many steps
    setup.seed = 3;
    Jostling j{rings_in_box(setup, static_cast<int>(std::ceil(std::sqrt(particles)))), 0, 0};
    const RingScales sc = ring_scales(setup.ring);
    j.k_n = sc.laws.k_s;
    j.a.model.set_contact_law({j.k_n, 0.0, 0.0, 0.0});
    j.dt = 0.5 * critical_time_step(j.a.model);
    Rng rng(7);
    for (int shell : j.a.particles) {
        const double angle = rng.uniform(0, 2 * std::numbers::pi);
        j.a.model.set_velocity(shell, speed_per_step * sc.radius_vertex / j.dt *
                                          Vec2(std::cos(angle), std::sin(angle)));
    }
    return j;
}

// All-pairs reference of section 2.3: every vertex against every element of every other shell (not both
// rigid), eq. (6) without damping, a contact at an element end counted once (with the element starting there,
// or ending there for the last vertex of an open shell), and one contact per (vertex, other shell): its
// nearest touching element, the first in index order on a tie (decision spd-contact-nearest-element). Returns
// the normal force received by each vertex.
std::vector<double> all_pairs_normal_forces(const ShellModel& model, double k_n, int& contacts)
{
    const auto& shells = model.shells();
    std::vector<double> fn(static_cast<std::size_t>(model.vertices()), 0.0);
    contacts = 0;
    for (std::size_t p = 0; p < shells.size(); ++p)
        for (std::size_t q = 0; q < shells.size(); ++q) {
            const Shell &sp = shells[p], &sq = shells[q];
            if (p == q || (sp.rigid && sq.rigid)) continue;
            const double reach = sp.radius + sq.radius;
            for (int i = sp.first; i < sp.first + sp.count; ++i) {
                double nearest = INFINITY;
                for (int k = 0; k < sq.elements(); ++k) {
                    const int a = sq.first + k, b = sq.first + (k + 1) % sq.count;
                    const SegmentProximity prox =
                        point_segment_proximity(model.vertex(i), model.vertex(a), model.vertex(b));
                    if (prox.distance >= reach) continue;
                    if (prox.branch == SegmentBranch::end_b && !(!sq.closed && k == sq.elements() - 1))
                        continue;
                    nearest = std::min(nearest, prox.distance);
                }
                if (nearest == INFINITY) continue;
                fn[i] += normal_contact_force(k_n, nearest, reach);
                ++contacts;
            }
        }
    return fn;
}
} // namespace

TEST_CASE("cell-list candidates find every contact of the all-pairs search [SPD section 2.3]")
{
    Jostling j = jostling_rings(36, 0.05);
    ShellModel& model = j.a.model;
    int checked_contacts = 0;
    for (int block = 0; block < 12; ++block) {
        for (int n = 0; n < 50; ++n)
            model.step(j.dt, 0.0);
        int contacts = 0;
        const std::vector<double> reference = all_pairs_normal_forces(model, j.k_n, contacts);
        checked_contacts += contacts;
        for (int i = 0; i < model.vertices(); ++i)
            // Same law, same summation order (elements in increasing index): equal up to a few ulps.
            CHECK_CLOSE(model.contact_normal(i), reference[static_cast<std::size_t>(i)],
                        (Tolerance{8 * round_off, 0.0}));
    }
    // The check is not empty: rings touched each other and the walls (208 contacts in the 12 snapshots when
    // written), and the list was rebuilt many times.
    MESSAGE("contacts checked: " << checked_contacts << ", list builds: " << model.neighbour_list_builds());
    CHECK(checked_contacts > 100);
    CHECK(model.neighbour_list_builds() > 5);
}

TEST_CASE("forces and trajectories do not depend on the number of OpenMP threads")
{
    // Contacts are evaluated in parallel into their own records and summed in one fixed order; shells write
    // only their own vertices: the trajectory is the same bit for bit (tolerance 0) with 1 and 2 threads.
    const auto trajectory = [](int threads) {
        omp_set_num_threads(threads);
        Jostling j = jostling_rings(144, 0.05); // 2304 vertices: above the 2000 of the parallel region
        REQUIRE(j.a.model.vertices() > 2000);
        for (int n = 0; n < 400; ++n)
            j.a.model.step(j.dt, 0.0);
        std::vector<double> x;
        for (int i = 0; i < j.a.model.vertices(); ++i) {
            x.push_back(j.a.model.vertex(i).x());
            x.push_back(j.a.model.vertex(i).y());
        }
        return x;
    };
    const int threads_before = omp_get_max_threads();
    const std::vector<double> one = trajectory(1), two = trajectory(2);
    omp_set_num_threads(threads_before);
    REQUIRE(one.size() == two.size());
    std::size_t differing = 0;
    for (std::size_t k = 0; k < one.size(); ++k)
        differing += one[k] != two[k];
    CHECK(differing == 0);
}

TEST_CASE("contact detection costs O(N): candidates per vertex stay bounded as the assembly grows")
{
    // An all-pairs search checks every vertex against all elements: 16 times more per vertex for 16 times
    // more rings. The cell list checks a vertex against the elements near it only: the candidates per vertex
    // grow only because a larger box has a larger share of interior rings (more neighbours than edge rings);
    // bound 1.5.
    const auto candidates_per_vertex = [](int particles) {
        Jostling j = jostling_rings(particles, 0.0);
        j.a.model.compute_forces(j.dt);
        return static_cast<double>(j.a.model.contact_candidates()) / j.a.model.vertices();
    };
    const double small = candidates_per_vertex(16), large = candidates_per_vertex(256);
    MESSAGE("candidates per vertex: 16 rings " << small << ", 256 rings " << large);
    CHECK(large < 1.5 * small);
}

TEST_CASE("a contact element gone non-finite is diagnosed (exit 3), not a crash, with 1 and 2 threads")
{
    // The contacts are evaluated inside an OpenMP region, from which no exception may escape (the process
    // terminated, exit 134, when a wall jumped to infinity). An element of a touching contact with a NaN
    // vertex makes point_segment_proximity throw there; the step must end in the non-finite diagnosis.
    for (const int threads : {1, 2}) {
        CAPTURE(threads);
        const int threads_before = omp_get_max_threads();
        omp_set_num_threads(threads);
        for (const int particles : {16, 144}) { // 144: above the 2000 vertices of the parallel region
            CAPTURE(particles);
            Jostling j = jostling_rings(particles, 0.05);
            while (j.a.model.active_contacts().empty())
                j.a.model.step(j.dt, 0.0);
            const int element_end = j.a.model.active_contacts().front().a;
            j.a.model.set_vertex(element_end, Vec2(NAN, NAN));
            try {
                j.a.model.step(j.dt, 0.0);
                FAIL("a step with a non-finite vertex went through");
            } catch (const NumericalError& e) {
                CHECK(std::string(e.what()).find("non-finite") != std::string::npos);
            }
        }
        omp_set_num_threads(threads_before);
    }
}
