#include "dpm/shape_energy.hpp"

#include "core/errors.hpp"
#include "core/geometry.hpp"

namespace softgrain::dpm {

namespace {

// Index of vertex i (mod n) of the particle starting at `first`.
int vertex(int first, int n, int i)
{
    return first + ((i % n) + n) % n;
}

// k_a/2 (a - a0)^2 with a = sum of the shoelace terms of the edges: gradient k_a (a - a0) grad a, Hessian
// k_a (grad a grad a^T + (a - a0) hess a); grad a and hess a are assembled from the local shoelace terms over
// the particle's own 2n coordinates (the rank-one term couples every pair of them, and only them).
double area_energy(const ShapeParameters& shape, const Eigen::VectorXd& x, int first, int n,
                   Eigen::VectorXd* gradient, HessianSink hessian)
{
    const Eigen::VectorXd own_x = x.segment(2 * first, 2 * n);
    Eigen::VectorXd grad_a = Eigen::VectorXd::Zero(gradient || hessian ? 2 * n : 0);
    Eigen::MatrixXd hess_a = Eigen::MatrixXd::Zero(hessian ? 2 * n : 0, hessian ? 2 * n : 0);
    const auto term = [](const auto& local) { return shoelace_term(local); };
    double area = 0;
    for (int i = 0; i < n; ++i) {
        const std::array<int, 2> points{vertex(0, n, i), vertex(0, n, i + 1)};
        area += add_local_term<2, 2>(term, points, gather<2, 2>(own_x, points),
                                     gradient || hessian ? &grad_a : nullptr, hessian ? &hess_a : nullptr);
    }
    const double deviation = area - shape.a0;
    if (gradient) gradient->segment(2 * first, 2 * n) += shape.ka * deviation * grad_a;
    if (hessian)
        hessian.add(2 * first, 2 * first, shape.ka * (grad_a * grad_a.transpose() + deviation * hess_a));
    return harmonic_penalty(shape.ka, area, shape.a0);
}

} // namespace

double shape_energy(const ShapeParameters& shape, const Eigen::VectorXd& x, int first, int n,
                    Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms)
{
    double energy = 0;
    if ((terms & area_term) && shape.ka != 0) energy += area_energy(shape, x, first, n, gradient, hessian);
    const EdgeLengthEnergy edge{shape.kl, shape.l0};
    const LineTensionEnergy tension{shape.gamma};
    const BendingEnergy bending{shape.kb, shape.theta0};
    for (int i = 0; i < n; ++i) {
        const std::array<int, 2> edge_points{vertex(first, n, i - 1), vertex(first, n, i)};
        if ((terms & edge_term) && shape.kl != 0)
            energy +=
                add_local_term<2, 2>(edge, edge_points, gather<2, 2>(x, edge_points), gradient, hessian);
        if ((terms & line_tension_term) && shape.gamma != 0)
            energy +=
                add_local_term<2, 2>(tension, edge_points, gather<2, 2>(x, edge_points), gradient, hessian);
        const std::array<int, 3> corner{vertex(first, n, i - 1), vertex(first, n, i),
                                        vertex(first, n, i + 1)};
        if ((terms & bending_term) && shape.kb != 0)
            energy += add_local_term<2, 3>(bending, corner, gather<2, 3>(x, corner), gradient, hessian);
    }
    return energy;
}

double particle_area(const Eigen::VectorXd& x, int first, int n)
{
    return polygon_signed_area(x.segment(2 * first, 2 * n).reshaped(2, n));
}

double particle_perimeter(const Eigen::VectorXd& x, int first, int n)
{
    return polygon_perimeter(x.segment(2 * first, 2 * n).reshaped(2, n));
}

ShapeModel shape_model_from_name(const std::string& name)
{
    if (name == "floppy") return ShapeModel::floppy;
    if (name == "shell") return ShapeModel::shell;
    if (name == "surface_tension") return ShapeModel::surface_tension;
    throw InputError("model = '" + name + "': allowed floppy | shell | surface_tension");
}

ShapeParameters table_9_1_parameters(ShapeModel model, int n, double a0, double A0, const ShapeStiffness& k)
{
    ShapeParameters shape;
    shape.ka = k.ka;
    shape.a0 = a0;
    shape.l0 = std::sqrt(4.0 * std::numbers::pi * a0 * A0) / n;
    shape.theta0 = 2.0 * std::numbers::pi / n;
    switch (model) {
    case ShapeModel::floppy:
        shape.kl = k.kl;
        break;
    case ShapeModel::shell:
        shape.kl = k.kl;
        shape.kb = k.kb;
        break;
    case ShapeModel::surface_tension:
        shape.kl = k.kl_surface;
        shape.gamma = k.gamma;
        break;
    }
    return shape;
}

} // namespace softgrain::dpm
