#include "dpm/protocols/slump.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace softgrain::dpm {

namespace {

constexpr double sigma = 1.0; // vertex diameter (length unit)

// Plate law of section 9.3.4 with k_p = k_c: normal force k_c (sigma/2 - gap) on a vertex at distance
// `gap` from a wall, zero beyond contact.
double plate_force(double kc, double gap)
{
    return std::max(0.0, kc * (0.5 * sigma - gap));
}

// Coulomb-capped tangential spring of one floor contact (decision dpm-slump-floor-friction): returns
// F_t = -k_t (x - anchor), limited to mu F_n; on slip the anchor follows the vertex.
double floor_friction(double x, double normal, double mu, double kt, double& anchor)
{
    if (std::isnan(anchor)) anchor = x;
    const double stretch = x - anchor, cap = mu * normal;
    if (kt * std::abs(stretch) <= cap) return -kt * stretch;
    const double direction = stretch > 0 ? 1.0 : -1.0;
    anchor = x - direction * cap / kt;
    return -direction * cap;
}

// Shell parameters as dpm.compress_box (decision dpm-jam-polygons): edge 0.85 sigma for the small
// particle, k_a a0_small^2 = k_c sigma^2, k_l = k_c, k_b = 0.1 k_c sigma^2, theta0 = 2 pi/N, A0 = A_min.
struct ShellType
{
    int nodes;
    double radius; // circumradius of the polygon [sigma]
    ShapeParameters shape;
};

ShellType shell_type(int nodes, double radius, double ka)
{
    const double a0 = 0.5 * nodes * radius * radius * std::sin(2 * std::numbers::pi / nodes);
    ShapeStiffness k;
    k.ka = ka;
    k.kl = 1.0;
    k.kb = 0.1;
    return {nodes, radius,
            table_9_1_parameters(ShapeModel::shell, nodes, a0, minimum_shape_parameter(nodes), k)};
}

// Largest over particles of |sum of the vertex forces| / particle weight, and the largest vertex speed.
std::pair<double, double> unbalance(const DpmSystem& s, const Eigen::VectorXd& force,
                                    const Eigen::VectorXd& v, double g)
{
    double worst = 0;
    for (const Particle& p : s.particles) {
        const Eigen::Vector2d net =
            force.segment(2 * p.first, 2 * p.count).reshaped(2, p.count).rowwise().sum();
        worst = std::max(worst, net.norm() / (p.count * g));
    }
    return {worst, v.size() ? v.reshaped(2, v.size() / 2).colwise().norm().maxCoeff() : 0.0};
}

} // namespace

void slump_forces(const DpmSystem& s, const SlumpWorld& world, const Eigen::VectorXd& x, FloorContacts& floor,
                  Eigen::VectorXd& force, WallForces* walls)
{
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    total_energy(s, x, &gradient, nullptr); // eq. (9.1) + (9.3)-(9.9)
    force = -gradient;
    WallForces sum;
    floor.anchor.resize(x.size() / 2, std::numeric_limits<double>::quiet_NaN());
    for (Eigen::Index v = 0; v < x.size() / 2; ++v) {
        const double px = x(2 * v), py = x(2 * v + 1);
        force(2 * v + 1) -= world.gravity; // m = 1
        const double left = world.left_wall ? plate_force(s.kc, px) : 0.0;
        const double right = std::isfinite(world.right_wall) ? plate_force(s.kc, world.right_wall - px) : 0.0;
        const double normal = plate_force(s.kc, py);
        double tangential = 0;
        if (normal > 0)
            tangential =
                floor_friction(px, normal, world.wall_friction, world.tangential_stiffness, floor.anchor[v]);
        else
            floor.anchor[v] = std::numeric_limits<double>::quiet_NaN();
        force(2 * v) += left - right + tangential + world.body_force_x;
        force(2 * v + 1) += normal;
        sum.left += left;
        sum.right -= right;
        sum.floor_normal += normal;
        sum.floor_friction += tangential;
    }
    if (walls) *walls = sum;
}

double slump_time_step(const DpmSystem& s, const Eigen::VectorXd& x)
{
    double stiffest = 0;
    for (std::size_t m = 0; m < std::min<std::size_t>(2, s.particles.size()); ++m) { // one of each type
        const Particle& p = s.particles[m];
        DpmSystem alone;
        Eigen::VectorXd y;
        alone.add_particle(x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count), p.sigma, p.shape, y);
        stiffest = std::max(stiffest, vibrational_modes(alone, y).eigenvalues.maxCoeff());
    }
    // A vertex touches at most ~4 others (two neighbours' vertices, a wall): 8 k_c bounds its contact part.
    return 0.2 / std::sqrt(stiffest + 8 * s.kc);
}

RestResult run_to_rest(const DpmSystem& s, const SlumpWorld& world, Eigen::VectorXd& x, Eigen::VectorXd& v,
                       FloorContacts& floor, double dt, double rest_tolerance, long max_steps,
                       const char* stage, const SlumpObserver& observe, long steps_before)
{
    RestResult out;
    Eigen::VectorXd force;
    slump_forces(s, world, x, floor, force, nullptr);
    const double speed_limit = rest_tolerance * std::sqrt(world.gravity * sigma);
    for (long step = 1; step <= max_steps; ++step) {
        // Velocity Verlet (kick-drift-kick) with the damping -c v of the half-step velocity.
        v += 0.5 * dt * (force - world.damping * v);
        x += dt * v;
        slump_forces(s, world, x, floor, force, nullptr);
        v += 0.5 * dt * (force - world.damping * v);
        if (observe)
            observe(s, world, x, v, steps_before + step, static_cast<double>(steps_before + step) * dt);
        if (step % 50 != 0) continue;
        if (!x.allFinite())
            throw NumericalError(std::string(stage) + ": non-finite vertex position", step,
                                 "time step above the stability limit of the stiffest spring");
        const auto [unbalanced, speed] = unbalance(s, force, v, world.gravity);
        out.unbalanced = unbalanced;
        if (unbalanced < rest_tolerance && speed < speed_limit) {
            out.steps = step;
            slump_forces(s, world, x, floor, force, &out.walls);
            return out;
        }
    }
    throw NumericalError(std::string(stage) + ": not at rest (max unbalanced force / weight " +
                             std::to_string(out.unbalanced) + ")",
                         max_steps,
                         "the pile still creeps or rings: raise max_steps or the damping, or loosen "
                         "rest_tolerance");
}

SlumpResult run_slump(const SlumpOptions& options, const SlumpObserver& observe)
{
    const double pi = std::numbers::pi, ratio = 1.4;
    SlumpResult out;
    DpmSystem& s = out.system;
    s.interaction = options.interaction;
    s.kc = 1.0;
    const double r_small = 0.85 * sigma / (2 * std::sin(pi / options.nodes_small));
    const double d_small = 2 * r_small + sigma, d_large = ratio * d_small;
    const double a0_small =
        0.5 * options.nodes_small * r_small * r_small * std::sin(2 * pi / options.nodes_small);
    const double ka = 1.0 / (a0_small * a0_small);
    const ShellType types[2] = {shell_type(options.nodes_small, r_small, ka),
                                shell_type(options.nodes_large, 0.5 * (d_large - sigma), ka)};
    out.diameter = 0.5 * (d_small + d_large);
    out.box_width = options.box_width * out.diameter;
    // Placement (decision dpm-slump-protocol): a shuffled 50:50 sequence of sizes on a square grid of cells
    // 1.05 D_large wide, filled row by row from the floor, random orientation and a small random offset.
    const double cell = 1.05 * d_large;
    const int columns = static_cast<int>(std::floor(out.box_width / cell));
    if (columns < 1)
        throw InputError("box_width = " + std::to_string(options.box_width) +
                         ": narrower than one large particle (" + std::to_string(d_large / out.diameter) +
                         " D)");
    Rng rng(options.seed);
    std::vector<int> kinds(options.particles);
    for (int m = 0; m < options.particles; ++m)
        kinds[m] = m % 2;
    for (int m = options.particles - 1; m > 1;
         --m) // Fisher-Yates on all but the first two (one of each type)
        std::swap(kinds[m], kinds[2 + static_cast<int>(rng.uniform() * (m - 1))]);
    const double margin = 0.5 * (out.box_width - columns * cell);
    Eigen::VectorXd x;
    for (int m = 0; m < options.particles; ++m) {
        const ShellType& t = types[kinds[m]];
        const double jitter = 0.5 * (cell - (kinds[m] ? d_large : d_small));
        const Eigen::Vector2d c(margin + cell * (m % columns + 0.5) + rng.uniform(-jitter, jitter),
                                cell * (m / columns + 0.5) + rng.uniform(0, jitter));
        s.add_particle(regular_polygon(t.nodes, t.radius, c, rng.uniform(0, 2 * pi)), sigma, t.shape, x);
    }
    out.dt = slump_time_step(s, x);
    SlumpWorld world{options.gravity, options.wall_friction, options.tangential_stiffness,
                     options.damping, out.box_width,         true};
    Eigen::VectorXd v = Eigen::VectorXd::Zero(x.size());
    FloorContacts floor;
    if (observe) observe(s, world, x, v, 0, 0.0);
    out.confined.rest = run_to_rest(s, world, x, v, floor, out.dt, options.rest_tolerance, options.max_steps,
                                    "confined", observe);
    out.confined.x = x;
    world.right_wall = std::numeric_limits<double>::infinity(); // the right wall is removed
    out.released.rest = run_to_rest(s, world, x, v, floor, out.dt, options.rest_tolerance, options.max_steps,
                                    "released", observe, out.confined.rest.steps);
    out.released.x = x;
    return out;
}

std::vector<double> surface_profile(const Eigen::VectorXd& x, double bin)
{
    std::vector<double> top;
    for (Eigen::Index v = 0; v < x.size() / 2; ++v) {
        const auto k = static_cast<std::size_t>(std::max(0.0, std::floor(x(2 * v) / bin)));
        if (k >= top.size()) top.resize(k + 1, std::numeric_limits<double>::quiet_NaN());
        const double height = x(2 * v + 1) + 0.5 * sigma;
        if (!(top[k] >= height)) top[k] = height;
    }
    return top;
}

SurfaceFit fit_free_surface(const Eigen::VectorXd& x, double diameter)
{
    SurfaceFit fit;
    const std::vector<double> top = surface_profile(x, diameter);
    for (std::size_t k = 0; k < top.size(); ++k)
        if (!std::isnan(top[k])) {
            fit.centre.push_back(k + 0.5);
            fit.height.push_back(top[k] / diameter);
        }
    if (const auto line = fit_line(fit.centre, fit.height)) {
        fit.intercept = line->intercept;
        fit.slope = line->slope;
    }
    return fit;
}

double pile_front(const Eigen::VectorXd& x)
{
    return x.reshaped(2, x.size() / 2).row(0).maxCoeff() + 0.5 * sigma;
}

int particles_crossing(const DpmSystem& s, const Eigen::VectorXd& x, double at)
{
    int count = 0;
    for (const Particle& p : s.particles) {
        const auto xs = x.segment(2 * p.first, 2 * p.count).reshaped(2, p.count).row(0);
        count += xs.minCoeff() - 0.5 * p.sigma <= at && xs.maxCoeff() + 0.5 * p.sigma >= at;
    }
    return count;
}

} // namespace softgrain::dpm
