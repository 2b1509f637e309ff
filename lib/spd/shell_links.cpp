#include "spd/shell_links.hpp"

#include "core/checkpoint.hpp"

#include <algorithm>

namespace softgrain::spd {

namespace {
void add_force(Eigen::VectorXd& f, int i, const Vec2& F)
{
    f[2 * i] += F.x();
    f[2 * i + 1] += F.y();
}
} // namespace

// Section 6: the intact links, in their fixed order (forces independent of the thread count). A link is
// tested against eq. (39) with the forces of the current geometry; at zeta >= 0 it breaks before acting, and
// the pair is left to the contact law (eqs. (6)-(7), decision spd-tissue-link-breaking).
void ShellLinks::add_forces(const ShellView& model, Eigen::VectorXd& f)
{
    for (CohesiveLink& link : links_) {
        if (link.broken) continue;
        const LinkKinematics kinematics =
            link_kinematics(link, model.vertex(link.a), model.vertex(link.b), model.vertex(link.partner_a),
                            model.vertex(link.partner_b));
        const LinkForces forces = link_forces(link, law_, kinematics);
        link.f_n = forces.f_n;
        link.f_t = forces.f_t;
        if (yield_function(forces.f_n, forces.f_t, law_) >= 0) {
            link.broken = true;
            continue;
        }
        add_force(f, link.a, forces.a);
        add_force(f, link.b, forces.b);
        add_force(f, link.partner_a, forces.partner_a);
        add_force(f, link.partner_b, forces.partner_b);
    }
}

int ShellLinks::broken() const
{
    return static_cast<int>(
        std::count_if(links_.begin(), links_.end(), [](const CohesiveLink& link) { return link.broken; }));
}

double ShellLinks::energy(const ShellView& model) const
{
    double W = 0;
    for (const CohesiveLink& link : links_)
        if (!link.broken)
            W += spd::link_energy<double>(link, law_, model.vertex(link.a), model.vertex(link.b),
                                          model.vertex(link.partner_a), model.vertex(link.partner_b));
    return W;
}

void ShellLinks::transfer(Archive& archive)
{
    archive(links_);
    archive(law_);
}

} // namespace softgrain::spd
