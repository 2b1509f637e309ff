#include "dpm/laws/interactions3d.hpp"

#include "core/errors.hpp"
#include "dpm/laws/interactions.hpp"
#include "dpm/system/system3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <compare>
#include <memory>
#include <stdexcept>
#include <string>

namespace softgrain::dpm {

TriangleFeature nearest_triangle_feature(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                         const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
    // Barycentric tests of Ericson's ClosestPtPointTriangle, in the same order.
    const Eigen::Vector3d ab = b - a, ac = c - a;
    const double d1 = ab.dot(p - a), d2 = ac.dot(p - a);
    if (d1 <= 0 && d2 <= 0) return TriangleFeature::vertex_a;
    const double d3 = ab.dot(p - b), d4 = ac.dot(p - b);
    if (d3 >= 0 && d4 <= d3) return TriangleFeature::vertex_b;
    if (d1 * d4 - d3 * d2 <= 0 && d1 >= 0 && d3 <= 0) return TriangleFeature::edge_ab;
    const double d5 = ab.dot(p - c), d6 = ac.dot(p - c);
    if (d6 >= 0 && d5 <= d6) return TriangleFeature::vertex_c;
    if (d5 * d2 - d1 * d6 <= 0 && d2 >= 0 && d6 <= 0) return TriangleFeature::edge_ca;
    if (d3 * d6 - d5 * d4 <= 0 && d4 >= d3 && d5 >= d6) return TriangleFeature::edge_bc;
    return TriangleFeature::face;
}

namespace {

// Vertex i of particle mu near the image `image` of particle beta (mu != beta): an ordered term of the
// smooth interaction.
struct NearSurface
{
    int mu = 0, beta = 0;
    std::array<int, 3> image{}; // (n_x, n_y, n_z), image_translation
    int i = 0;

    auto operator<=>(const NearSurface&) const = default;
};

// The lattice translation of the image with indices n = (n_x, n_y, n_z):
// -(n_x L + n_y gamma L, n_y L, n_z L), gamma wrapped (wrapped_strain3d); made from the indices, so the
// same vector for every vertex pair that finds the image.
Eigen::Vector3d image_translation(const DpmSystem3d& s, const std::array<int, 3>& n)
{
    if (!s.box) return Eigen::Vector3d::Zero();
    const double L = *s.box;
    return -Eigen::Vector3d((n[0] + n[1] * wrapped_strain3d(s)) * L, n[1] * L, n[2] * L);
}

// Adds (mu of i, beta of j, n, i) for the images n of vertex j within the list's contact range of vertex i
// (vertex_pairs3d.hpp): the nearest image of r_j - r_i in the unsheared coordinates u = (x - gamma y, y, z),
// and where the list may hold several images per pair (a box below twice its reach) its 26 neighbours.
void add_images(const DpmSystem3d& s, const VertexPairList3d& list, const Eigen::VectorXd& x, int i, int j,
                std::vector<NearSurface>& near)
{
    const Eigen::Vector3d d = x.segment<3>(3 * j) - x.segment<3>(3 * i);
    std::array<int, 3> nearest{0, 0, 0};
    if (s.box) {
        const double L = *s.box;
        nearest = {static_cast<int>(std::round((d.x() - wrapped_strain3d(s) * d.y()) / L)),
                   static_cast<int>(std::round(d.y() / L)), static_cast<int>(std::round(d.z() / L))};
    }
    const int spread = list.one_image() ? 0 : 1;
    const double range = list.contact_range();
    for (int a = -spread; a <= spread; ++a)
        for (int b = -spread; b <= spread; ++b)
            for (int c = -spread; c <= spread; ++c) {
                const std::array<int, 3> n{nearest[0] + a, nearest[1] + b, nearest[2] + c};
                if ((d + image_translation(s, n)).squaredNorm() < range * range)
                    near.push_back({list.particle_of(i), list.particle_of(j), n, i});
            }
}

// The ordered terms of the smooth interaction at x and the contact range of the list they came from.
struct SmoothTerms
{
    std::vector<NearSurface> near;
    double range = 0;
};

// Every (vertex i of mu, image of particle beta) with a vertex of that image within the contact range of i,
// from the system's Verlet list (vertex_pairs3d.hpp), once, in (mu, beta, image, i) order. A vertex within
// sigma_mb of a face, edge or vertex of the image is within the contact range of a corner of it, so every
// term that is not zero is here; the others add nothing, and the order depends on indices alone: the sums
// do not depend on the list.
SmoothTerms smooth_terms(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    SmoothTerms terms;
    if (s.particles.size() < 2) return terms;
    const std::shared_ptr<const VertexPairList3d> list = s.contacts.list(s, x);
    terms.range = list->contact_range();
    for (const CandidatePair3d& pair : list->pairs()) {
        add_images(s, *list, x, pair.i, pair.j, terms.near);
        add_images(s, *list, x, pair.j, pair.i, terms.near);
    }
    std::sort(terms.near.begin(), terms.near.end());
    terms.near.erase(std::unique(terms.near.begin(), terms.near.end()), terms.near.end());
    return terms;
}

// Local coordinates of `points`: the first (the vertex of mu) as stored, the others (of beta) shifted.
template <int K>
Eigen::Matrix<double, 3 * K, 1> gather_shifted(const Eigen::VectorXd& x, const std::array<int, K>& points,
                                               const Eigen::Vector3d& shift)
{
    Eigen::Matrix<double, 3 * K, 1> local = gather<3, K>(x, points);
    for (int k = 1; k < K; ++k)
        local.template segment<3>(3 * k) += shift;
    return local;
}

// Vertex i against the surface of particle b at the translation `shift`: the inclusion-exclusion sum of
// the header with spring constant k. Calls `contact()` once if the vertex is within sigma of the surface.
// Terms go to the global arrays when given. A face, edge or vertex none of whose corners lies within
// `range` (the list's contact range) is farther than sigma_mb and skipped unevaluated; `in_range` is the
// caller's buffer for that test, kept over its terms.
template <class OnContact>
double vertex_surface(const DpmSystem3d& s, const NearSurface& near, double range,
                      std::vector<char>& in_range, double k, const Eigen::VectorXd& x,
                      Eigen::VectorXd* gradient, HessianSink hessian, Eigen::Matrix3d* virial,
                      const OnContact& contact)
{
    const auto [mu, beta, image, i] = near;
    const Particle3d& b = s.particles[beta];
    const double sigma = 0.5 * (s.particles[mu].sigma + b.sigma);
    const Eigen::Vector3d shift = image_translation(s, image);
    const TriangleMesh& mesh = s.meshes[b.mesh];
    const Eigen::Vector3d p = x.segment<3>(3 * i);
    const auto point = [&](int v) { return Eigen::Vector3d(x.segment<3>(3 * (b.first + v)) + shift); };
    in_range.resize(static_cast<std::size_t>(b.count));
    for (int v = 0; v < b.count; ++v)
        in_range[v] = (point(v) - p).squaredNorm() < range * range;
    double energy = 0;
    bool touching = false;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        if (!in_range[face[0]] && !in_range[face[1]] && !in_range[face[2]]) continue;
        const std::array<int, 4> points{i, b.first + face[0], b.first + face[1], b.first + face[2]};
        const Eigen::Matrix<double, 12, 1> local = gather_shifted<4>(x, points, shift);
        const double d = point_triangle_distance(local);
        if (d >= sigma) continue; // Theta(sigma - d)
        touching = true;
        const Eigen::Vector3d a = point(face[0]), n = (point(face[1]) - a).cross(point(face[2]) - a);
        if (nearest_triangle_feature(p, a, point(face[1]), point(face[2])) == TriangleFeature::face &&
            (p - a).dot(n) < 0)
            throw NumericalError("smooth 3D contact: vertex " + std::to_string(i) + " of particle " +
                                     std::to_string(mu) + " has passed through face " + std::to_string(f) +
                                     " of particle " + std::to_string(beta),
                                 0,
                                 "overlap beyond the model's range (the vertex must stay outside); "
                                 "smaller steps or a stiffer k_c");
        energy +=
            add_local_term<3, 4>(PointTriangleSpring{k, sigma}, points, local, gradient, hessian, virial);
    }
    if (!touching) return 0; // every edge and vertex is farther than its faces
    contact();
    for (const MeshEdge& e : mesh.edges) {
        if (!in_range[e.a] && !in_range[e.b]) continue;
        const std::array<int, 3> points{i, b.first + e.a, b.first + e.b};
        const Eigen::Matrix<double, 9, 1> local = gather_shifted<3>(x, points, shift);
        if (point_segment_distance(local) < sigma)
            energy +=
                add_local_term<3, 3>(PointSegmentSpring{-k, sigma}, points, local, gradient, hessian, virial);
    }
    for (int v = 0; v < b.count; ++v) {
        if (!in_range[v]) continue;
        const std::array<int, 2> points{i, b.first + v};
        const Eigen::Matrix<double, 6, 1> local = gather_shifted<2>(x, points, shift);
        if ((local.segment<3>(3) - p).squaredNorm() < sigma * sigma)
            energy +=
                add_local_term<3, 2>(VertexSpring<3>{k, sigma}, points, local, gradient, hessian, virial);
    }
    return energy;
}

// The sum of term(near) over the ordered terms, taken per ordered particle pair (mu, beta) and then over
// the pairs, in their order: the energy of each ordered pair is a quantity of its own
// (smooth_vertex_surface_energy3d).
template <class Term>
double sum_over_particle_pairs(const std::vector<NearSurface>& near, const Term& term)
{
    double energy = 0;
    for (auto first = near.begin(); first != near.end();) {
        const auto last = std::find_if(first, near.end(), [&](const NearSurface& n) {
            return n.mu != first->mu || n.beta != first->beta;
        });
        double pair = 0;
        for (auto t = first; t != last; ++t)
            pair += term(*t);
        energy += pair;
        first = last;
    }
    return energy;
}

// Calls touch(i, mu, beta) for every vertex i of particle mu within sigma_mb of the surface of an image of
// particle beta (mu != beta), in (mu, beta, image, i) order: the contacts of the smooth interaction.
template <class Touch>
void for_each_smooth_contact(const DpmSystem3d& s, const Eigen::VectorXd& x, const Touch& touch)
{
    const SmoothTerms terms = smooth_terms(s, x);
    std::vector<char> in_range; // vertex_surface's buffer, kept over the terms
    for (const NearSurface& near : terms.near)
        vertex_surface(s, near, terms.range, in_range, 0.0, x, nullptr, nullptr, nullptr,
                       [&] { touch(near.i, near.mu, near.beta); });
}

} // namespace

double smooth_interaction_energy3d(const DpmSystem3d& s, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                                   HessianSink hessian, Eigen::Matrix3d* virial)
{
    if (s.kc == 0) return 0;
    const double k = 0.5 * s.kc; // the 1/2 of eq. (9.5) on every ordered term (decision dpm-smooth-half)
    const SmoothTerms terms = smooth_terms(s, x);
    std::vector<char> in_range;
    return sum_over_particle_pairs(terms.near, [&](const NearSurface& near) {
        return vertex_surface(s, near, terms.range, in_range, k, x, gradient, hessian, virial, [] {});
    });
}

double smooth_vertex_surface_energy3d(const DpmSystem3d& s, int mu, int beta, const Eigen::VectorXd& x)
{
    if (mu == beta) throw std::logic_error("smooth_vertex_surface_energy3d: a particle against itself");
    SmoothTerms terms = smooth_terms(s, x);
    std::vector<char> in_range;
    std::erase_if(terms.near, [&](const NearSurface& n) { return n.mu != mu || n.beta != beta; });
    return sum_over_particle_pairs(terms.near, [&](const NearSurface& n) {
        return vertex_surface(s, n, terms.range, in_range, 0.5 * s.kc, x, nullptr, nullptr, nullptr, [] {});
    });
}

std::vector<int> smooth_contact_counts3d(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    std::vector<int> counts(s.particles.size(), 0);
    for_each_smooth_contact(s, x, [&](int, int mu, int beta) {
        ++counts[mu];
        ++counts[beta];
    });
    return counts;
}

std::vector<std::pair<int, int>> smooth_touching_pairs3d(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    std::vector<std::pair<int, int>> pairs;
    for_each_smooth_contact(s, x, [&](int i, int, int beta) { pairs.emplace_back(i, beta); });
    return pairs;
}

} // namespace softgrain::dpm
