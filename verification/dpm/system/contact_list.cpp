// The vertex-level Verlet list of 2D DPM contacts (dpm/system/contact_list.hpp), against an independent
// brute-force reference that visits every vertex pair of every particle pair through the particle pair's
// nearest image (the traversal the list replaced, kept here only): energy, gradient (the analytic FIRE path
// and the AutoDiff one), Hessian and virial of eqs. (9.4)-(9.9) agree to round-off on random overlapping
// periodic configurations, in open space, under Lees-Edwards strains where the image shift matters (gamma =
// 0.3, 1.2), rough and smooth. The list is rebuilt exactly when a vertex has moved beyond half the skin (or
// the box, the strain or the particles change); a contact formed by smaller motions is found without a
// rebuild, and the results do not depend on when the list was built.
//
// Tolerance of the comparison with the reference: 1e-12 relative to the largest entry (energy: to its
// value). Both sum the same terms, in another order and with the image translation applied in another way
// (r_j + n L - r_i against r_j - r_i + n L with n L from the particle centres): each term differs by a few
// round_off relative to the largest, and at most a few hundred terms meet in one entry, so the difference is
// below 1e3 round_off = 2e-13; 1e-12 leaves a factor 5 and is still far below any physical difference (one
// missed contact changes the energy by ~1e-4 of it here).
#include "core/rng.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/laws/interactions.hpp"
#include "dpm/system/system.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

const double pi = std::numbers::pi;

// n particles at random places in a box of sides L (periodic or not), deformed polygons of random size and
// vertex count 5..10 (or disks), random vertex diameters: many overlaps, also across the box sides.
struct RandomPacking
{
    DpmSystem system;
    Eigen::VectorXd x;
    RandomPacking(int n, bool disks, const Eigen::Vector2d& L, bool periodic, double gamma,
                  InteractionKind kind, std::uint64_t seed)
    {
        Rng rng(seed);
        system.interaction = kind;
        system.kc = rng.uniform(0.5, 2.0);
        if (periodic) system.box = L;
        system.lees_edwards_strain = gamma;
        for (int m = 0; m < n; ++m) {
            const Eigen::Vector2d c(rng.uniform(0, L.x()), rng.uniform(0, L.y()));
            if (disks) {
                system.add_particle(c, rng.uniform(0.8, 1.4), ShapeParameters{}, x);
                continue;
            }
            const int count = 5 + static_cast<int>(rng.uniform(0, 6));
            Eigen::Matrix2Xd v = regular_polygon(count, rng.uniform(0.9, 1.4), c, rng.uniform(0, 2 * pi));
            for (Eigen::Index k = 0; k < v.size(); ++k)
                v(k) += 0.1 * rng.uniform(-1, 1);
            system.add_particle(v, rng.uniform(0.6, 1.0), ShapeParameters{}, x);
        }
    }
};

Eigen::Vector2d vertex(const Eigen::VectorXd& x, int v)
{
    return x.segment<2>(2 * v);
}

Eigen::Vector2d centre(const Particle& p, const Eigen::VectorXd& x)
{
    return x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count).rowwise().mean();
}

struct Evaluation
{
    double energy = 0;
    Eigen::VectorXd gradient;
    Eigen::MatrixXd hessian;
    Eigen::Matrix2d virial = Eigen::Matrix2d::Zero();
    explicit Evaluation(Eigen::Index n)
        : gradient(Eigen::VectorXd::Zero(n)), hessian(Eigen::MatrixXd::Zero(n, n))
    {
    }
};

// Adds one term over `points` whose coordinates `local` hold the images (AutoDiff, as the library's
// Hessian path).
template <int K, class Term>
void add_term(const Term& term, const std::array<int, K>& points,
              const Eigen::Matrix<double, 2 * K, 1>& local, Evaluation& e)
{
    e.energy += add_local_term<2, K>(term, points, local, &e.gradient, &e.hessian, &e.virial);
}

// Eqs. (9.6), (9.8), (9.9) of every vertex of a against every edge and vertex of b (b shifted by `shift`).
void smooth_reference(const DpmSystem& s, const Particle& a, const Particle& b, const Eigen::Vector2d& shift,
                      const Eigen::VectorXd& x, Evaluation& e)
{
    if (b.count < 2) return;
    const double sigma = 0.5 * (a.sigma + b.sigma), k = 0.5 * s.kc;
    const auto of_b = [&](int j) { return b.first + ((j % b.count) + b.count) % b.count; };
    const auto at = [&](int v) { return Eigen::Vector2d(vertex(x, v) + shift); };
    const auto distance = [](const Eigen::Vector2d& p, const Eigen::Vector2d& from,
                             const Eigen::Vector2d& to) {
        Eigen::Matrix<double, 6, 1> local;
        local << p, from, to;
        return signed_edge_distance(local);
    };
    for (int i = a.first; i < a.first + a.count; ++i) {
        const Eigen::Vector2d p = vertex(x, i);
        for (int j = 0; j < b.count; ++j) {
            const Eigen::Vector2d rj = at(of_b(j)), rp = at(of_b(j - 1)), rn = at(of_b(j + 1));
            const double d = distance(p, rp, rj);
            if (d > 0 && d < sigma && (p - rp).dot(rj - rp) > 0 && (p - rj).dot(rp - rj) > 0) {
                Eigen::Matrix<double, 6, 1> local;
                local << p, rp, rj;
                add_term<3>(VertexEdgeEnergy{k, sigma}, {i, of_b(j - 1), of_b(j)}, local, e);
            }
            if ((p - rj).squaredNorm() >= sigma * sigma) continue;
            Eigen::Vector4d local;
            local << p, rj;
            const double previous = (p - rj).dot(rp - rj), next = (p - rj).dot(rn - rj);
            if (previous > 0 && next > 0 && d > 0 && distance(p, rj, rn) > 0)
                add_term<2>(VertexSpringEnergy{-k, sigma}, {i, of_b(j)}, local, e);
            if (previous < 0 && next < 0) add_term<2>(VertexSpringEnergy{k, sigma}, {i, of_b(j)}, local, e);
        }
    }
}

// Every vertex pair of every particle pair, b at its image nearest to a (centre to centre).
Evaluation all_pairs_reference(const DpmSystem& s, const Eigen::VectorXd& x)
{
    Evaluation e(x.size());
    for (std::size_t m = 0; m < s.particles.size(); ++m)
        for (std::size_t n = m + 1; n < s.particles.size(); ++n) {
            const Particle &a = s.particles[m], &b = s.particles[n];
            const Eigen::Vector2d d = centre(b, x) - centre(a, x), shift = s.image(d) - d;
            if (s.interaction == InteractionKind::smooth) {
                smooth_reference(s, a, b, shift, x, e);
                smooth_reference(s, b, a, -shift, x, e);
                continue;
            }
            const double sigma = 0.5 * (a.sigma + b.sigma);
            for (int i = a.first; i < a.first + a.count; ++i)
                for (int j = b.first; j < b.first + b.count; ++j) {
                    Eigen::Vector4d local;
                    local << vertex(x, i), vertex(x, j) + shift;
                    if ((local.tail<2>() - local.head<2>()).norm() < sigma)
                        add_term<2>(VertexSpringEnergy{s.kc, sigma}, {i, j}, local, e);
                }
        }
    return e;
}

double largest(const Eigen::MatrixXd& m)
{
    return m.cwiseAbs().maxCoeff();
}

// The list's energy, gradient (with and without the Hessian), Hessian and virial against the reference.
void check_against_all_pairs(const DpmSystem& s, const Eigen::VectorXd& x)
{
    const Evaluation reference = all_pairs_reference(s, x);
    REQUIRE(reference.energy > 0); // overlaps: the comparison is not between zeros
    Evaluation list(x.size());
    list.energy = interaction_energy(s, x, &list.gradient, &list.hessian, all_smooth, &list.virial);
    Eigen::VectorXd force_only = Eigen::VectorXd::Zero(x.size()); // the analytic gradient of FIRE
    const double energy_force_only = interaction_energy(s, x, &force_only, nullptr);
    const Tolerance relative{1e-12, 0};
    CHECK_CLOSE(list.energy, reference.energy, relative);
    CHECK_CLOSE(energy_force_only, reference.energy, relative);
    const Tolerance entries{0, 1e-12 * largest(reference.gradient)};
    CHECK_CLOSE(largest(list.gradient - reference.gradient), 0.0, entries);
    CHECK_CLOSE(largest(force_only - reference.gradient), 0.0, entries);
    CHECK_CLOSE(largest(list.hessian - reference.hessian), 0.0,
                (Tolerance{0, 1e-12 * largest(reference.hessian)}));
    CHECK_CLOSE(largest(list.virial - reference.virial), 0.0,
                (Tolerance{0, 1e-12 * largest(reference.virial)}));
}

// Touching vertex pairs whose nearest image is not the plain difference (contacts across the box sides)
// and of those, the ones across the sheared side (y image).
std::pair<int, int> contacts_across_sides(const DpmSystem& s, const Eigen::VectorXd& x)
{
    int across = 0, across_y = 0;
    for (const VertexContact& c : vertex_contacts(s, x)) {
        const Eigen::Vector2d plain = vertex(x, c.j) - vertex(x, c.i);
        across += (c.r - plain).norm() > 1e-9;
        across_y += std::abs(c.r.y() - plain.y()) > 1e-9;
    }
    return {across, across_y};
}

} // namespace

TEST_CASE(
    "vertex list = all vertex pairs: periodic, rough and smooth polygons and disks [DPM eqs. (9.4)-(9.9)]")
{
    for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
        const RandomPacking p(40, false, {18.0, 15.0}, true, 0.0, kind, 3);
        REQUIRE(contacts_across_sides(p.system, p.x).first > 0);
        check_against_all_pairs(p.system, p.x);
    }
    const RandomPacking disks(200, true, {16.0, 14.0}, true, 0.0, InteractionKind::rough, 5);
    check_against_all_pairs(disks.system, disks.x);
}

TEST_CASE("vertex list = all vertex pairs: open space [DPM eqs. (9.4)-(9.9)]")
{
    for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
        const RandomPacking p(40, false, {18.0, 15.0}, false, 0.0, kind, 7);
        check_against_all_pairs(p.system, p.x);
    }
}

TEST_CASE("vertex list = all vertex pairs under Lees-Edwards strain 0.3 and 1.2 [DPM sec. 9.4.3]")
{
    for (const double gamma : {0.3, 1.2})
        for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
            CAPTURE(gamma);
            const RandomPacking p(40, false, {18.0, 15.0}, true, gamma, kind, 11);
            // Contacts across the sheared side, where the image is shifted by gamma L_y in x.
            REQUIRE(contacts_across_sides(p.system, p.x).second > 0);
            check_against_all_pairs(p.system, p.x);
        }
}

TEST_CASE("vertex list: rebuilt exactly when a vertex moves beyond half the skin, or the box, strain or "
          "particles change")
{
    // Two rough disks sigma = 1 at distance 1 + 0.8 skin: not touching, but within the list's reach.
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.box = Eigen::Vector2d(20.0, 20.0);
    Eigen::VectorXd x;
    s.add_particle(Eigen::Vector2d(5.0, 5.0), 1.0, ShapeParameters{}, x);
    s.add_particle(Eigen::Vector2d(6.0, 5.0), 1.0, ShapeParameters{}, x);
    const DpmSystem probe = s; // its own cache: s has built nothing yet
    const double skin = probe.contacts.list(probe, x)->skin();
    REQUIRE(skin > 0);
    REQUIRE(s.contacts.builds() == 0);
    x(2) += 0.8 * skin;
    const Eigen::VectorXd built_at = x;
    CHECK(interaction_energy(s, x, nullptr, nullptr) == 0.0);
    CHECK(s.contacts.builds() == 1);
    // Each disk moves 0.45 skin towards the other: overlap 0.1 skin, no rebuild, the contact is found.
    x(0) += 0.45 * skin;
    x(2) -= 0.45 * skin;
    const double overlap = 0.1 * skin;
    CHECK_CLOSE(interaction_energy(s, x, nullptr, nullptr), 0.5 * s.kc * overlap * overlap,
                (Tolerance{1e-10, 0}));
    CHECK(s.contacts.builds() == 1);
    // Just beyond half the skin (0.51 skin from where the list was built): rebuilt once.
    x(0) = built_at(0) + 0.51 * skin;
    interaction_energy(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 2);
    interaction_energy(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 2);
    // A new strain, a new box or another vertex diameter invalidate the list.
    s.lees_edwards_strain = 0.1;
    interaction_energy(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 3);
    s.box = Eigen::Vector2d(21.0, 20.0);
    interaction_energy(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 4);
    s.particles[1].sigma = 1.1;
    interaction_energy(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 5);
}

TEST_CASE("vertex list: results do not depend on when the list was built (bit for bit)")
{
    for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
        RandomPacking p(40, false, {18.0, 15.0}, true, 0.3, kind, 13);
        const Eigen::VectorXd start = p.x;
        interaction_energy(p.system, start, nullptr, nullptr); // the list is built at `start`
        const double skin = p.system.contacts.list(p.system, start)->skin();
        Rng rng(17);
        Eigen::VectorXd moved = start;
        for (Eigen::Index k = 0; k < moved.size(); ++k)
            moved(k) += 0.35 * skin * rng.uniform(-1, 1); // |displacement| < 0.5 skin: the old list is kept
        Evaluation old_list(moved.size()), fresh_list(moved.size());
        old_list.energy = interaction_energy(p.system, moved, &old_list.gradient, &old_list.hessian,
                                             all_smooth, &old_list.virial);
        REQUIRE(p.system.contacts.builds() == 1);
        DpmSystem fresh = p.system;
        fresh.contacts = ContactCache{};
        fresh_list.energy = interaction_energy(fresh, moved, &fresh_list.gradient, &fresh_list.hessian,
                                               all_smooth, &fresh_list.virial);
        REQUIRE(fresh.contacts.builds() == 1);
        CHECK(old_list.energy == fresh_list.energy);
        CHECK(old_list.gradient == fresh_list.gradient);
        CHECK(old_list.hessian == fresh_list.hessian);
        CHECK(old_list.virial == fresh_list.virial);
    }
}
