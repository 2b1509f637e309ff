#include "dpm/spring_network.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/shape_energy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace softgrain::dpm {

SpringNetwork disordered_triangular_disk(int nodes, double jitter, double k, std::uint64_t seed)
{
    if (nodes < 7) throw InputError("nodes = " + std::to_string(nodes) + ": a network disk needs at least 7");
    // Lattice sites (i, j) -> i e1 + j e2, e1 = (1, 0), e2 = (1/2, sqrt(3)/2); the `nodes` nearest to the
    // origin (ties broken by the index, so the disk is reproducible).
    const auto site = [](int i, int j) { return Eigen::Vector2d(i + 0.5 * j, 0.5 * std::sqrt(3.0) * j); };
    const int reach = static_cast<int>(std::ceil(std::sqrt(double(nodes)))) + 2;
    std::vector<std::pair<double, std::pair<int, int>>> sites;
    for (int i = -reach; i <= reach; ++i)
        for (int j = -reach; j <= reach; ++j)
            sites.push_back({site(i, j).squaredNorm(), {i, j}});
    std::sort(sites.begin(), sites.end());
    sites.resize(static_cast<std::size_t>(nodes));

    SpringNetwork network;
    network.k = k;
    network.x.resize(2 * nodes);
    std::map<std::pair<int, int>, int> index;
    for (int v = 0; v < nodes; ++v) {
        const auto [i, j] = sites[static_cast<std::size_t>(v)].second;
        index[{i, j}] = v;
        network.x.segment<2>(2 * v) = site(i, j);
    }
    for (const auto& [ij, v] : index)
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{-1, 1}}) { // each bond once
            const auto other = index.find({ij.first + di, ij.second + dj});
            if (other != index.end()) network.springs.push_back({v, other->second, 0.0});
        }
    // Disorder on the interior nodes only (6 springs): the boundary keeps the lattice's mirror symmetry, so
    // the disk seats on frictionless plates without rolling (a jagged boundary rotates freely to lower its
    // height).
    std::vector<int> coordination(static_cast<std::size_t>(nodes), 0);
    for (const Spring& s : network.springs) {
        ++coordination[static_cast<std::size_t>(s.i)];
        ++coordination[static_cast<std::size_t>(s.j)];
    }
    Rng rng(seed);
    for (int v = 0; v < nodes; ++v) {
        const double r = jitter * std::sqrt(rng.uniform()), angle = 2 * std::numbers::pi * rng.uniform();
        if (coordination[static_cast<std::size_t>(v)] == 6)
            network.x.segment<2>(2 * v) += r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
    for (Spring& s : network.springs)
        s.rest_length = (network.x.segment<2>(2 * s.j) - network.x.segment<2>(2 * s.i)).norm();
    return network;
}

double spring_network_energy(const SpringNetwork& network, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient)
{
    double u = 0;
    for (const Spring& s : network.springs) {
        const std::array<int, 2> ends{s.i, s.j};
        u += add_local_term<2, 2>(EdgeLengthEnergy{network.k, s.rest_length}, ends, gather<2, 2>(x, ends),
                                  gradient, nullptr);
    }
    return u;
}

} // namespace softgrain::dpm
