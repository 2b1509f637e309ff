// The vertex-level Verlet list of 3D rough contacts (dpm/system/vertex_pairs3d.hpp). It is rebuilt exactly
// when a vertex has moved beyond half the skin in the unsheared coordinates (or the box, the strain or the
// particles change), a contact formed by smaller motions is found without a rebuild, and energy, gradient,
// Hessian and virial do not depend on when the list was built: bit for bit, since the contact loop takes
// the same pairs in the same (i, j) order and measures each by the same minimum image. That every contact
// is found at all is checked against a sum over all vertex pairs in lees_edwards3d.cpp.
#include "core/rng.hpp"
#include "dpm/system/system3d.hpp"
#include "support/jammed3d.hpp"

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_same_with_fresh_list3d;
using softgrain::verification::random_sheared3d;

namespace {

int contact_total(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    int total = 0;
    for (int count : contact_counts3d(s, x))
        total += count;
    return total;
}

} // namespace

TEST_CASE("3D vertex list: rebuilt exactly when a vertex moves beyond half the skin, or the box, strain or "
          "particles change [DPM eq. (9.4) in 3D]")
{
    Rng rng(31);
    Eigen::VectorXd x;
    DpmSystem3d s = random_sheared3d(ShapeModel::shell, rng, x);
    REQUIRE(s.contacts.builds() == 0);
    const double skin = s.contacts.list(s, x)->skin();
    REQUIRE(skin > 0);
    CHECK(s.contacts.builds() == 1);
    // Vertex 5 moves 0.45 skin along x (also 0.45 skin in the unsheared coordinates): kept.
    const Eigen::VectorXd built_at = x;
    x(15) += 0.45 * skin;
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 1);
    // (-0.28, 0.4, 0) skin: 0.49 skin in space, but (-0.28 - 0.23 0.4, 0.4, 0) skin, 0.55 skin long, in the
    // unsheared coordinates where the list was binned: rebuilt.
    x = built_at;
    x(15) -= 0.28 * skin;
    x(16) += 0.4 * skin;
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 2);
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 2);
    x = built_at;
    x(15) += 0.51 * skin;
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 3);
    // A new strain, a new box or another vertex diameter invalidate the list.
    s.lees_edwards_strain = 0.1;
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 4);
    s.box = 4.3;
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 5);
    s.particles[1].sigma = 0.95;
    interaction_energy3d(s, x, nullptr, nullptr);
    CHECK(s.contacts.builds() == 6);
}

TEST_CASE("3D vertex list: results do not depend on when the list was built (bit for bit) [DPM eq. (9.4) "
          "in 3D]")
{
    Rng rng(32);
    Eigen::VectorXd start;
    DpmSystem3d s = random_sheared3d(ShapeModel::shell, rng, start);
    interaction_energy3d(s, start, nullptr, nullptr); // the list is built at `start`
    const double skin = s.contacts.list(s, start)->skin();
    // Each vertex moves less than skin/2 in the unsheared coordinates: |d| (1 + gamma) sqrt(3) 0.2 skin.
    Eigen::VectorXd moved = start;
    for (Eigen::Index k = 0; k < moved.size(); ++k)
        moved(k) += 0.2 * skin * rng.uniform(-1, 1);
    // Non-vacuous: the motion changes the contacts, and the old list must hold the new ones.
    REQUIRE(contact_total(s, moved) != contact_total(s, start));
    check_same_with_fresh_list3d(s, moved);
}
