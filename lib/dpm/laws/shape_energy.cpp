#include "dpm/laws/shape_energy.hpp"

#include "core/errors.hpp"
#include "core/geometry.hpp"

#include <stdexcept>

namespace softgrain::dpm {

namespace {

// Index of vertex i (mod n), -n <= i < 2n, of the particle starting at `first` (a comparison, not an
// integer division: these indices are taken at every vertex of every force evaluation).
int vertex(int first, int n, int i)
{
    return first + (i < 0 ? i + n : (i >= n ? i - n : i));
}

// The edge from vertex i to vertex i + 1, the corner (i - 1, i, i + 1) at vertex i.
std::array<int, 2> edge_points(int first, int n, int i)
{
    return {vertex(first, n, i), vertex(first, n, i + 1)};
}

std::array<int, 3> corner_points(int first, int n, int i)
{
    return {vertex(first, n, i - 1), vertex(first, n, i), vertex(first, n, i + 1)};
}

} // namespace

double shape_energy(const ShapeParameters& shape, const Eigen::VectorXd& x, int first, int n,
                    Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms)
{
    const auto edge = [first, n](int i) { return edge_points(first, n, i); };
    return with_dense_block(hessian, 2 * first, 2 * n, [&](HessianSink block) {
        double energy = 0;
        if ((terms & area_term) && shape.ka != 0)
            energy += penalty_of_sum<2, 2>(shape.ka, shape.a0, shoelace_term, shoelace_term_slope, n, edge,
                                           first, n, x, gradient, block);
        const double kl = (terms & edge_term) ? shape.kl : 0;
        const double gamma = (terms & line_tension_term) ? shape.gamma : 0;
        if (kl != 0 || gamma != 0)
            for (int i = 0; i < n; ++i)
                energy += measure_term<2, 2>(edge_length, edge_length_slope, edge(i), x, kl, shape.l0, gamma,
                                             gradient, block);
        if ((terms & bending_term) && shape.kb != 0)
            for (int i = 0; i < n; ++i)
                energy += measure_term<2, 3>(turning_angle, turning_angle_slope, corner_points(first, n, i),
                                             x, shape.kb, shape.theta0, 0.0, gradient, block);
        return energy;
    });
}

double particle_area(const Eigen::VectorXd& x, int first, int n)
{
    return polygon_signed_area(x.segment(2 * first, 2 * n).reshaped(2, n));
}

double particle_perimeter(const Eigen::VectorXd& x, int first, int n)
{
    return polygon_perimeter(x.segment(2 * first, 2 * n).reshaped(2, n));
}

std::string shape_model_name(ShapeModel model)
{
    switch (model) {
    case ShapeModel::floppy:
        return "floppy";
    case ShapeModel::shell:
        return "shell";
    case ShapeModel::surface_tension:
        return "surface_tension";
    }
    throw std::logic_error("shape_model_name: not a ShapeModel");
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
