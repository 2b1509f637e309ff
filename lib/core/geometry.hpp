// Geometry kernels shared by the methods.
//
// Polygon measures are templated on the scalar so that energies built on them (DPM eq. 9.1) can be
// differentiated with Eigen's AutoDiff. Vertices are the columns of a 2 x N matrix, in order; the polygon
// closes from the last vertex back to the first. Counter-clockwise order gives a positive signed area.
#pragma once

#include "core/vector.hpp"

#include <cmath>

namespace softgrain {

// Shoelace formula: A = 1/2 sum_i (x_i y_{i+1} - x_{i+1} y_i). Units: length^2; positive when CCW.
template <class Derived>
typename Derived::Scalar polygon_signed_area(const Eigen::MatrixBase<Derived>& vertices)
{
    using Scalar = typename Derived::Scalar;
    const Eigen::Index n = vertices.cols();
    Scalar twice_area(0);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = (i + 1) % n;
        twice_area += vertices(0, i) * vertices(1, j) - vertices(0, j) * vertices(1, i);
    }
    return twice_area / Scalar(2);
}

// Sum of edge lengths of the closed polygon. Units: length.
template <class Derived>
typename Derived::Scalar polygon_perimeter(const Eigen::MatrixBase<Derived>& vertices)
{
    using Scalar = typename Derived::Scalar;
    const Eigen::Index n = vertices.cols();
    Scalar perimeter(0);
    for (Eigen::Index i = 0; i < n; ++i)
        perimeter += (vertices.col((i + 1) % n) - vertices.col(i)).norm();
    return perimeter;
}

// Area centroid of a simple polygon: c = 1/(6A) sum_i (p_i + p_{i+1}) (x_i y_{i+1} - x_{i+1} y_i).
// Undefined (division by zero) for a polygon of zero area.
template <class Derived>
Eigen::Matrix<typename Derived::Scalar, 2, 1> polygon_centroid(const Eigen::MatrixBase<Derived>& vertices)
{
    using Scalar = typename Derived::Scalar;
    const Eigen::Index n = vertices.cols();
    Eigen::Matrix<Scalar, 2, 1> weighted = Eigen::Matrix<Scalar, 2, 1>::Zero();
    Scalar twice_area(0);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = (i + 1) % n;
        const Scalar cross = vertices(0, i) * vertices(1, j) - vertices(0, j) * vertices(1, i);
        twice_area += cross;
        weighted += (vertices.col(i) + vertices.col(j)) * cross;
    }
    return weighted / (Scalar(3) * twice_area);
}

// Which part of a segment AB is closest to a point C (SPD section 2.3, Fig. 4).
enum class SegmentBranch {
    end_a,    // a < 0:       the closest point is A
    interior, // 0 <= a <= l: the closest point is the projection C' of C on AB
    end_b     // a > l:       the closest point is B
};

struct SegmentProximity
{
    double a = 0;      // signed projection AC.AB/|AB| of C on the segment axis, measured from A [length]
    double length = 0; // l = |AB| [length]
    // |C - closest point| [length]; the overlap of sphero-objects is distance - (r_i + r_j)
    double distance = 0;
    Vec2 closest = Vec2::Zero(); // closest point of the segment
    Vec2 normal = Vec2::Zero();  // unit vector from the closest point towards C; where C lies on the segment,
                                 // the left-hand normal of AB
    SegmentBranch branch = SegmentBranch::interior;
};

// Distance from C to segment AB with the three branches of SPD section 2.3. The distance and the closest
// point are continuous across the branch boundaries a = 0 and a = l (the branches meet at A and B).
// The segment must have a positive length.
SegmentProximity point_segment_proximity(const Vec2& c, const Vec2& a, const Vec2& b);

} // namespace softgrain
