#include "dpm/laws/interactions3d.hpp"

#include "core/errors.hpp"
#include "dpm/laws/interactions.hpp"
#include "dpm/system/system3d.hpp"

#include <cmath>
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

struct Sphere
{
    Eigen::Vector3d centre;
    double radius;
};

// Vertex mean and the largest distance of a vertex from it.
Sphere bounding_sphere(const DpmSystem3d& s, const Particle3d& p, const Eigen::VectorXd& x)
{
    const Eigen::Matrix3Xd v = s.vertices(p, x);
    const Eigen::Vector3d centre = v.rowwise().mean();
    return {centre, (v.colwise() - centre).colwise().norm().maxCoeff()};
}

// The translations of particle b (its periodic images, or none without a box) that bring it within
// `reach` of the point `from`, given b's vertex mean.
std::vector<Eigen::Vector3d> images_within(const DpmSystem3d& s, const Eigen::Vector3d& from,
                                           const Eigen::Vector3d& centre, double reach)
{
    const Eigen::Vector3d d = centre - from;
    if (!s.box)
        return d.norm() < reach ? std::vector<Eigen::Vector3d>{Eigen::Vector3d::Zero()}
                                : std::vector<Eigen::Vector3d>{};
    const double L = *s.box;
    // The image lattice is spanned by (L, 0, 0), (gamma L, L, 0), (0, 0, L) under a Lees-Edwards strain
    // gamma (gamma and gamma - 1 span the same lattice: the one in [-1/2, 1/2] is used). Around the nearest
    // image, the others beyond its 26 neighbours are farther than (1.5 - |gamma|) L.
    const double gamma = s.lees_edwards_strain - std::round(s.lees_edwards_strain);
    if (reach >= (1.5 - std::abs(gamma)) * L)
        throw NumericalError("periodic box side " + std::to_string(L) + " below a particle pair's reach " +
                                 std::to_string(reach) + " over 1.5 - |Lees-Edwards strain|",
                             0, "the packing is compressed beyond the image range; lower the pressure");
    const Eigen::Vector3d nearest = s.image(d) - d;
    std::vector<Eigen::Vector3d> shifts;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
                const Eigen::Vector3d shift = nearest + L * Eigen::Vector3d(i + gamma * j, j, k);
                if ((d + shift).norm() < reach) shifts.push_back(shift);
            }
    return shifts;
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
// Terms go to the global arrays when given.
template <class OnContact>
double vertex_surface(const DpmSystem3d& s, int i, int mu, int beta, const Eigen::Vector3d& shift, double k,
                      double sigma, const Eigen::VectorXd& x, Eigen::VectorXd* gradient, HessianSink hessian,
                      Eigen::Matrix3d* virial, const OnContact& contact)
{
    const Particle3d& b = s.particles[beta];
    const TriangleMesh& mesh = s.meshes[b.mesh];
    const Eigen::Vector3d p = x.segment<3>(3 * i);
    const auto point = [&](int v) { return Eigen::Vector3d(x.segment<3>(3 * (b.first + v)) + shift); };
    double energy = 0;
    bool touching = false;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
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
        const std::array<int, 3> points{i, b.first + e.a, b.first + e.b};
        const Eigen::Matrix<double, 9, 1> local = gather_shifted<3>(x, points, shift);
        if (point_segment_distance(local) < sigma)
            energy +=
                add_local_term<3, 3>(PointSegmentSpring{-k, sigma}, points, local, gradient, hessian, virial);
    }
    for (int v = 0; v < b.count; ++v) {
        const std::array<int, 2> points{i, b.first + v};
        const Eigen::Matrix<double, 6, 1> local = gather_shifted<2>(x, points, shift);
        if ((local.segment<3>(3) - p).squaredNorm() < sigma * sigma)
            energy +=
                add_local_term<3, 2>(VertexSpring<3>{k, sigma}, points, local, gradient, hessian, virial);
    }
    return energy;
}

std::vector<Sphere> bounding_spheres(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    std::vector<Sphere> spheres;
    for (const Particle3d& p : s.particles)
        spheres.push_back(bounding_sphere(s, p, x));
    return spheres;
}

// Calls term(i, shift, sigma_mb) for every vertex i of particle mu and every image of particle beta whose
// bounding sphere, widened by sigma_mb, holds the vertex.
template <class Term>
void for_each_vertex_near(const DpmSystem3d& s, const std::vector<Sphere>& spheres, int mu, int beta,
                          const Eigen::VectorXd& x, const Term& term)
{
    const Particle3d &a = s.particles[mu], &b = s.particles[beta];
    const double sigma = 0.5 * (a.sigma + b.sigma);
    const double reach = spheres[mu].radius + spheres[beta].radius + sigma;
    for (const Eigen::Vector3d& shift : images_within(s, spheres[mu].centre, spheres[beta].centre, reach))
        for (int i = a.first; i < a.first + a.count; ++i)
            if ((x.segment<3>(3 * i) - spheres[beta].centre - shift).norm() < spheres[beta].radius + sigma)
                term(i, shift, sigma);
}

// Every vertex of mu against the surface of beta (one ordered pair), with the 1/2 of eq. (9.5).
double ordered_pair_energy(const DpmSystem3d& s, const std::vector<Sphere>& spheres, int mu, int beta,
                           const Eigen::VectorXd& x, Eigen::VectorXd* gradient, HessianSink hessian,
                           Eigen::Matrix3d* virial)
{
    const double k = 0.5 * s.kc; // the 1/2 of eq. (9.5) on every ordered term (decision dpm-smooth-half)
    double energy = 0;
    for_each_vertex_near(s, spheres, mu, beta, x, [&](int i, const Eigen::Vector3d& shift, double sigma) {
        energy += vertex_surface(s, i, mu, beta, shift, k, sigma, x, gradient, hessian, virial, [] {});
    });
    return energy;
}

} // namespace

double smooth_interaction_energy3d(const DpmSystem3d& s, const Eigen::VectorXd& x, Eigen::VectorXd* gradient,
                                   HessianSink hessian, Eigen::Matrix3d* virial)
{
    if (s.kc == 0) return 0;
    const std::vector<Sphere> spheres = bounding_spheres(s, x);
    double energy = 0;
    const int n = static_cast<int>(s.particles.size());
    for (int mu = 0; mu < n; ++mu)
        for (int beta = 0; beta < n; ++beta)
            if (mu != beta) energy += ordered_pair_energy(s, spheres, mu, beta, x, gradient, hessian, virial);
    return energy;
}

double smooth_vertex_surface_energy3d(const DpmSystem3d& s, int mu, int beta, const Eigen::VectorXd& x)
{
    if (mu == beta) throw std::logic_error("smooth_vertex_surface_energy3d: a particle against itself");
    return ordered_pair_energy(s, bounding_spheres(s, x), mu, beta, x, nullptr, nullptr, nullptr);
}

namespace {

// Calls touch(i, mu, beta) for every vertex i of particle mu within sigma_mb of the surface of an image of
// particle beta (mu != beta), in (mu, beta, image, i) order: the contacts of the smooth interaction.
template <class Touch>
void for_each_smooth_contact(const DpmSystem3d& s, const Eigen::VectorXd& x, const Touch& touch)
{
    const std::vector<Sphere> spheres = bounding_spheres(s, x);
    const int n = static_cast<int>(s.particles.size());
    for (int mu = 0; mu < n; ++mu)
        for (int beta = 0; beta < n; ++beta) {
            if (mu == beta) continue;
            for_each_vertex_near(s, spheres, mu, beta, x,
                                 [&](int i, const Eigen::Vector3d& shift, double sigma) {
                                     vertex_surface(s, i, mu, beta, shift, 0.0, sigma, x, nullptr, nullptr,
                                                    nullptr, [&] { touch(i, mu, beta); });
                                 });
        }
}

} // namespace

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
