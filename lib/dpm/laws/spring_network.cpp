#include "dpm/laws/spring_network.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/laws/local_derivatives.hpp"

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

namespace {

template <int Dim>
double springs_energy(const SpringNetwork& network, const Eigen::VectorXd& x, Eigen::VectorXd* gradient)
{
    double u = 0;
    for (const Spring& s : network.springs) {
        const std::array<int, 2> ends{s.i, s.j};
        u += add_local_term<Dim, 2>(SpringEnergy<Dim>{network.k, s.rest_length}, ends,
                                    gather<Dim, 2>(x, ends), gradient, nullptr);
    }
    return u;
}

// n points spread evenly on the sphere of radius R (Fibonacci spiral).
std::vector<Eigen::Vector3d> fibonacci_sphere(int n, double R)
{
    std::vector<Eigen::Vector3d> points;
    const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
    for (int k = 0; k < n; ++k) {
        const double z = 1 - (2 * k + 1.0) / n, rho = std::sqrt(1 - z * z), phi = golden * k;
        points.push_back(R * Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), z));
    }
    return points;
}

} // namespace

double spring_network_energy(const SpringNetwork& network, const Eigen::VectorXd& x,
                             Eigen::VectorXd* gradient)
{
    return network.dim == 3 ? springs_energy<3>(network, x, gradient)
                            : springs_energy<2>(network, x, gradient);
}

SpringNetwork disordered_sphere_network(int nodes, double cutoff, double k, std::uint64_t seed)
{
    if (nodes < 50)
        throw InputError("network_nodes = " + std::to_string(nodes) +
                         ": a 3D network ball needs at least 50");
    // Radius R (spacing a = 1): 4 pi R^2 surface nodes plus 4/3 pi (R - 0.35)^3 interior nodes = nodes.
    const double pi = std::numbers::pi, gap = 0.35;
    const auto count = [&](double R) { return 4 * pi * R * R + 4.0 / 3.0 * pi * std::pow(R - gap, 3); };
    double lo = 1, hi = std::cbrt(double(nodes));
    for (int it = 0; it < 60; ++it)
        (count(0.5 * (lo + hi)) < nodes ? lo : hi) = 0.5 * (lo + hi);
    const double R = 0.5 * (lo + hi);
    const int surface = static_cast<int>(std::lround(4 * pi * R * R));
    std::vector<Eigen::Vector3d> points = fibonacci_sphere(surface, R);
    // Interior: random sequential addition, minimum distance 2 gap to every node placed.
    Rng rng(seed);
    const double inner = R - gap, min_distance = 2 * gap;
    long attempts = 0;
    while (static_cast<int>(points.size()) < nodes) {
        if (++attempts > 1000L * nodes)
            throw NumericalError("interior nodes of the network ball placed: " +
                                     std::to_string(points.size()),
                                 attempts, "random sequential addition saturated");
        const Eigen::Vector3d p(rng.uniform(-inner, inner), rng.uniform(-inner, inner),
                                rng.uniform(-inner, inner));
        if (p.norm() > inner) continue;
        const bool free = std::none_of(points.begin(), points.end(), [&](const Eigen::Vector3d& q) {
            return (p - q).norm() < min_distance;
        });
        if (free) points.push_back(p);
    }
    SpringNetwork network;
    network.k = k;
    network.dim = 3;
    network.x.resize(3 * static_cast<Eigen::Index>(points.size()));
    for (std::size_t v = 0; v < points.size(); ++v)
        network.x.segment<3>(3 * static_cast<Eigen::Index>(v)) = points[v];
    for (int i = 0; i < nodes; ++i)
        for (int j = i + 1; j < nodes; ++j) {
            const double l =
                (points[static_cast<std::size_t>(i)] - points[static_cast<std::size_t>(j)]).norm();
            if (l < cutoff) network.springs.push_back({i, j, l});
        }
    return network;
}

double affine_network_young_modulus(const SpringNetwork& network, double volume)
{
    double sum = 0;
    for (const Spring& s : network.springs)
        sum += network.k * s.rest_length * s.rest_length;
    return sum / (6 * volume);
}

} // namespace softgrain::dpm
