// The cohesive links of the SPD shell model (Trivino et al., section 6): links between vertices of
// different shells with the law of lib/spd/cohesive_link.hpp, their forces and their breaking. Part of
// ShellModel (spd/shell_model.hpp), which adds their forces at each force evaluation.
#pragma once

#include "spd/cohesive_link.hpp"
#include "spd/shell_contacts.hpp"

#include <Eigen/Core>

#include <vector>

namespace softgrain {
class Archive;
}

namespace softgrain::spd {

class ShellLinks
{
  public:
    void set(std::vector<CohesiveLink> links, const CohesiveLaw& law)
    {
        links_ = std::move(links);
        law_ = law;
    }
    const std::vector<CohesiveLink>& links() const { return links_; }
    const CohesiveLaw& law() const { return law_; }
    bool empty() const { return links_.empty(); }
    int broken() const;
    // Sum of the intact links' energies k_n u_n^2/2 + k_t u_t^2/2 [J].
    double energy(const ShellView& model) const;
    // Adds the forces of the intact links to f (x and y of each vertex, interleaved) and breaks those whose
    // yield function reaches 0.
    void add_forces(const ShellView& model, Eigen::VectorXd& f);
    void transfer(Archive& archive);

  private:
    std::vector<CohesiveLink> links_;
    CohesiveLaw law_;
};

} // namespace softgrain::spd
