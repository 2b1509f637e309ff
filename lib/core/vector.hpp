// Fixed-size vectors of the 2D and 3D methods (Eigen). Positions of many points are stored as
// Eigen::Matrix<double, Dim, Eigen::Dynamic>, one column per point (structure of arrays).
#pragma once

#include <Eigen/Core>

namespace softgrain {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Points = Eigen::Matrix<double, Dim, Eigen::Dynamic>;

// z-component of the 2D cross product a x b.
template <class Scalar>
Scalar cross2(const Eigen::Matrix<Scalar, 2, 1>& a, const Eigen::Matrix<Scalar, 2, 1>& b)
{
    return a.x() * b.y() - a.y() * b.x();
}

} // namespace softgrain
