#include "spd/shell_cores.hpp"

#include "core/checkpoint.hpp"
#include "core/errors.hpp"
#include "core/geometry.hpp"

#include <cmath>
#include <utility>

namespace softgrain::spd {

namespace {
// dA/dx_k = perp(x_(k+1) - x_(k-1))/2, perp(d) = (d_y, -d_x), of a closed shell whose vertex coordinates are
// xs (x and y interleaved, 2 count entries): half its chord from the previous to the next vertex, turned by
// -90 degrees, outward for a CCW polygon [m].
Vec2 vertex_area_gradient(const double* xs, int count, int k)
{
    const int a = (k + count - 1) % count, b = (k + 1) % count;
    return {0.5 * (xs[2 * b + 1] - xs[2 * a + 1]), -0.5 * (xs[2 * b] - xs[2 * a])};
}

// dA/dx of a shell whose vertex coordinates are xs (2 s.count entries) [m].
Eigen::VectorXd area_gradient(const Shell& s, const Eigen::Ref<const Eigen::VectorXd>& xs)
{
    Eigen::VectorXd g(2 * s.count);
    for (int k = 0; k < s.count; ++k)
        g.segment<2>(2 * k) = vertex_area_gradient(xs.data(), s.count, k);
    return g;
}

// A core of finite modulus, the penalty of eq. (4) (an incompressible core is a constraint).
bool finite_core(const Shell& s)
{
    return s.closed && s.K_Omega > 0 && !s.incompressible();
}

// The constraint direction of an incompressible shell at the model's positions: its vertex range [first,
// first + size) in the flat vectors, G = dA/dx and M^-1 G, along which both RATTLE stages move the velocities.
struct ConstraintDirection
{
    Eigen::Index first, size;
    Eigen::VectorXd G, MG;
};
ConstraintDirection constraint_direction(const Shell& s, const ShellView& model,
                                         const Eigen::VectorXd& inverse_mass)
{
    const Eigen::Index first = 2 * s.first, size = 2 * s.count;
    Eigen::VectorXd G = area_gradient(s, model.x.segment(first, size));
    Eigen::VectorXd MG = inverse_mass.segment(first, size).cwiseProduct(G);
    return {first, size, std::move(G), std::move(MG)};
}
} // namespace

double shell_area(const ShellView& model, const Shell& shell)
{
    return polygon_signed_area(Eigen::Map<const Points<2>>(model.x.data() + 2 * shell.first, 2, shell.count));
}

void ShellCores::add(const ShellView& model, int shell)
{
    const Shell& s = model.shells[shell];
    const double V = s.closed ? s.depth * shell_area(model, s) : 0.0;
    V_previous_.push_back(V);
    V0_.push_back(V);
    pressure_.push_back(0.0);
}

// SPD eq. (4) and section 2.4: dp = -K_Omega dV/V0 (undrained), plus a constant applied (drained) pressure;
// each element receives s l p along its outward normal at its midpoint, half to each end (this is
// p dV/dx_k = p s dA/dx_k exactly). The pressure of an incompressible core is the constraint multiplier,
// applied by the RATTLE stages; here it only receives the applied pressure.
void ShellCores::add_forces(const ShellView& model, int shell, Eigen::VectorXd& f)
{
    const Shell& s = model.shells[shell];
    if (!s.closed || (!(s.K_Omega > 0) && s.pressure_applied == 0)) return;
    double p = s.pressure_applied;
    if (!s.incompressible()) {
        const double V = s.depth * shell_area(model, s);
        pressure_[shell] += -s.K_Omega * (V - V_previous_[shell]) / V0_[shell];
        V_previous_[shell] = V;
        p += pressure_[shell];
    }
    if (p == 0.0) return;
    // Added vertex by vertex, without a temporary: no exception (not even bad_alloc) may leave the parallel
    // force region.
    const double scale = s.depth * p;
    const double* xs = model.x.data() + 2 * s.first;
    for (int k = 0; k < s.count; ++k) {
        const Vec2 F = scale * vertex_area_gradient(xs, s.count, k);
        f[2 * (s.first + k)] += F.x();
        f[2 * (s.first + k) + 1] += F.y();
    }
}

double ShellCores::energy(const ShellView& model, int shell) const
{
    const Shell& s = model.shells[shell];
    if (!finite_core(s)) return 0.0;
    return V0_[shell] * pressure_[shell] * pressure_[shell] / (2 * s.K_Omega);
}

double ShellCores::stiffness(const ShellView& model, int shell) const
{
    const Shell& s = model.shells[shell];
    if (!finite_core(s)) return 0.0;
    const double gradient_sq = area_gradient(s, model.x.segment(2 * s.first, 2 * s.count)).squaredNorm();
    return s.K_Omega * s.depth * s.depth * gradient_sq / V0_[shell];
}

// The polygon area is a quadratic form, so A(y + lambda d) = A(y) + lambda dA/dx(y).d + lambda^2 A(d) with
// y = x + dt v_half, d = dt^2/2 M^-1 dA/dx(x), and A = A0 is solved exactly for lambda (the root of smallest
// magnitude); the half-step velocity receives dt/2 lambda M^-1 dA/dx(x).
void ShellCores::constrain_positions(const ShellView& model, const Eigen::VectorXd& inverse_mass, double dt,
                                     Eigen::VectorXd& v, std::int64_t step) const
{
    for (std::size_t index = 0; index < model.shells.size(); ++index) {
        const Shell& s = model.shells[index];
        if (!s.incompressible()) continue;
        const auto [o, n, G, MG] = constraint_direction(s, model, inverse_mass);
        const Eigen::VectorXd y = model.x.segment(o, n) + dt * v.segment(o, n);
        const Eigen::VectorXd d = 0.5 * dt * dt * MG;
        const auto area_of = [&](const Eigen::VectorXd& xs) {
            return polygon_signed_area(Eigen::Map<const Points<2>>(xs.data(), 2, s.count));
        };
        const double a = area_of(d), b = area_gradient(s, y).dot(d);
        const double c = area_of(y) - V0_[index] / s.depth;
        const double discriminant = b * b - 4 * a * c;
        if (discriminant < 0 || b == 0)
            throw NumericalError(
                "incompressible core (area constraint)", step,
                "no multiplier restores the area within one step: the time step is too large "
                "for the motion");
        const double lambda = -2 * c / (b + std::copysign(std::sqrt(discriminant), b));
        v.segment(o, n) += 0.5 * dt * lambda * MG;
    }
}

// dA/dx . v = 0 at the new positions, linear in mu. f keeps the constraint force mu dA/dx, so the next
// position stage only adds the increment of the multiplier.
void ShellCores::constrain_velocities(const ShellView& model, const Eigen::VectorXd& inverse_mass, double dt,
                                      Eigen::VectorXd& v, Eigen::VectorXd& f)
{
    for (std::size_t index = 0; index < model.shells.size(); ++index) {
        const Shell& s = model.shells[index];
        if (!s.incompressible()) continue;
        const auto [o, n, G, MG] = constraint_direction(s, model, inverse_mass);
        const double mu = -G.dot(v.segment(o, n)) / (0.5 * dt * G.dot(MG));
        v.segment(o, n) += 0.5 * dt * mu * MG;
        f.segment(o, n) += mu * G;
        pressure_[index] = mu / s.depth;
    }
}

void ShellCores::transfer(Archive& archive)
{
    archive(V_previous_);
    archive(pressure_);
    archive(V0_);
}

} // namespace softgrain::spd
