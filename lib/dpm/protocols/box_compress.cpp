#include "dpm/protocols/box_compress.hpp"

#include "core/errors.hpp"
#include "core/fire.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>

namespace softgrain::dpm {

namespace {

// System energy plus the four walls of the box [0, w] x [0, h]; wall forces per length when asked.
double energy_in_box(const DpmSystem& system, const Eigen::VectorXd& x, double w, double h,
                     Eigen::VectorXd* gradient, double* pressure_x, double* pressure_y)
{
    double u = total_energy(system, x, gradient, nullptr);
    double fx = 0, fy = 0;
    for (const Particle& p : system.particles)
        for (int v = p.first; v < p.first + p.count; ++v) {
            const std::array<int, 1> point{v};
            const double half = 0.5 * p.sigma;
            const WallEnergy walls[] = {{system.kc, half, 0.0, 1.0, 0},
                                        {system.kc, half, w, -1.0, 0},
                                        {system.kc, half, 0.0, 1.0, 1},
                                        {system.kc, half, h, -1.0, 1}};
            for (const WallEnergy& wall : walls) {
                const double overlap = half - wall.facing * (x(2 * v + wall.axis) - wall.position);
                if (overlap <= 0) continue;
                u += add_local_term<2, 1>(wall, point, gather<2, 1>(x, point), gradient, nullptr);
                (wall.axis == 0 ? fx : fy) += system.kc * overlap;
            }
        }
    if (pressure_x) *pressure_x = 0.5 * fx / h; // two side walls
    if (pressure_y) *pressure_y = 0.5 * fy / w; // top and bottom
    return u;
}

} // namespace

BoxCompressResult compress_in_box(const BoxCompressOptions& options)
{
    const double pi = std::numbers::pi, sigma = 1.0, ratio = 1.4;
    BoxCompressResult out;
    DpmSystem& s = out.system;
    s.interaction = InteractionKind::rough;
    // Deformable particles: edge 0.85 sigma, k_a a0^2 = k_c sigma^2 for the small ones (decision
    // dpm-jam-polygons).
    const double r_small = 0.85 * sigma / (2 * std::sin(pi / options.nodes_small));
    const double a0_small =
        0.5 * options.nodes_small * r_small * r_small * std::sin(2 * pi / options.nodes_small);
    const double ka = 1.0 / (a0_small * a0_small);
    out.pressure_unit = ka * a0_small; // k_a a0: the area (bulk) modulus of one particle
    s.kc = options.deformable ? 1.0 : out.pressure_unit;
    // Outer diameter of the small particle (vertex disks included).
    const double d_small = 2 * r_small + sigma;
    out.diameter_small = d_small;
    double area = 0;
    for (int m = 0; m < options.particles; ++m)
        area += std::pow(m < options.particles / 2 ? d_small : ratio * d_small, 2);
    double L = std::sqrt(area / 0.35); // start: particles' squared diameters fill 35 % of the box
    Rng rng(options.seed);
    std::vector<Eigen::Vector2d> centres;
    std::vector<double> diameters;
    Eigen::VectorXd x;
    for (int m = 0; m < options.particles; ++m) {
        const bool small = m < options.particles / 2;
        const double d = small ? d_small : ratio * d_small;
        Eigen::Vector2d c;
        for (int tries = 0;; ++tries) {
            if (tries > 100000)
                throw InputError("particles = " + std::to_string(options.particles) + ": no room");
            c = Eigen::Vector2d(rng.uniform(0.5 * d, L - 0.5 * d), rng.uniform(0.5 * d, L - 0.5 * d));
            bool free = true;
            for (std::size_t q = 0; q < centres.size(); ++q)
                free = free && (c - centres[q]).norm() > 0.5 * (d + diameters[q]);
            if (free) break;
        }
        centres.push_back(c);
        diameters.push_back(d);
        if (options.deformable) {
            const int n = small ? options.nodes_small : options.nodes_large;
            const double r = 0.5 * (d - sigma), a0 = 0.5 * n * r * r * std::sin(2 * pi / n);
            ShapeStiffness k;
            k.ka = ka;
            k.kl = 1.0;
            k.kb = 0.1;
            s.add_particle(regular_polygon(n, r, c, rng.uniform(0, 2 * pi)), sigma,
                           table_9_1_parameters(ShapeModel::shell, n, a0, minimum_shape_parameter(n), k), x);
        } else {
            s.add_particle(Eigen::Matrix2Xd(c), d, ShapeParameters{}, x);
        }
    }
    FireOptions fire;
    fire.dt_max = 0.3 / std::sqrt(std::max(4 * s.kc, vibrational_modes(s, x).eigenvalues.maxCoeff()));
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-3 * options.pressure_start * out.pressure_unit;
    double w = L, h = L;
    const auto relax = [&](long step) {
        const FireResult r = fire_minimise(
            x,
            [&](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
                f.setZero(y.size());
                const double u = energy_in_box(s, y, w, h, &f, nullptr, nullptr);
                f = -f;
                return u;
            },
            fire);
        out.iterations += r.iterations;
        if (!r.converged)
            throw NumericalError("relaxation in the box (" + fire_shortfall(r, fire) + ")", step,
                                 "time step too large for the stiffest term");
        BoxState state{x, w, h, 0, 0};
        energy_in_box(s, x, w, h, nullptr, &state.pressure_x, &state.pressure_y);
        state.pressure_x /= out.pressure_unit;
        state.pressure_y /= out.pressure_unit;
        return state;
    };
    // Isotropic stage: shrink the box about its centre by 1 % steps (particle centres scaled) until the mean
    // wall pressure reaches P0.
    long step = 0;
    for (BoxState state = relax(step);; state = relax(++step)) {
        if (0.5 * (state.pressure_x + state.pressure_y) >= options.pressure_start) {
            out.states.push_back(state);
            break;
        }
        if (step > 2000) throw NumericalError("isotropic compression to P0", step, "P0 unreachable");
        const double f = 0.99;
        for (const Particle& p : s.particles) {
            Eigen::Vector2d c = Eigen::Vector2d::Zero();
            for (int v = p.first; v < p.first + p.count; ++v)
                c += x.segment<2>(2 * v) / p.count;
            const Eigen::Vector2d shift = (f - 1) * c;
            for (int v = p.first; v < p.first + p.count; ++v)
                x.segment<2>(2 * v) += shift;
        }
        w *= f;
        h *= f;
    }
    // Uniaxial stage: the top wall moves down to (1 - strain) h0 in equal steps.
    const double h0 = h;
    for (int k = 1; k <= options.steps; ++k) {
        h = h0 * (1 - options.strain * k / options.steps);
        out.states.push_back(relax(++step));
    }
    return out;
}

double largest_interparticle_overlap(const DpmSystem& system, const Eigen::VectorXd& x)
{
    double largest = 0;
    for (const VertexContact& c : vertex_contacts(system, x))
        largest = std::max(largest, c.sigma - c.r.norm());
    return largest;
}

double vertex_contacts_per_particle_contact(const DpmSystem& system, const Eigen::VectorXd& x)
{
    const std::vector<VertexContact> contacts = vertex_contacts(system, x);
    std::set<std::pair<int, int>> particle_pairs;
    for (const VertexContact& c : contacts)
        particle_pairs.insert(std::minmax(c.a, c.b));
    return particle_pairs.empty() ? 0.0 : double(contacts.size()) / double(particle_pairs.size());
}

} // namespace softgrain::dpm
