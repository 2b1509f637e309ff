// Geometry kernels: polygon measures against closed forms; the SPD section 2.3 point-segment distance.
#include "core/geometry.hpp"
#include "support/tolerance.hpp"

#include <numbers>
#include <unsupported/Eigen/AutoDiff>

using namespace softgrain;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

Eigen::Matrix2Xd regular_polygon(int n, double radius, Vec2 centre, double phase)
{
    Eigen::Matrix2Xd v(2, n);
    for (int i = 0; i < n; ++i) {
        const double angle = phase + 2.0 * std::numbers::pi * i / n;
        v.col(i) = centre + radius * Vec2(std::cos(angle), std::sin(angle));
    }
    return v;
}

} // namespace

TEST_CASE("regular N-gon: area N R^2 sin(2 pi/N)/2, perimeter 2 N R sin(pi/N), centroid at its centre")
{
    for (int n : {3, 4, 7, 64}) {
        const double r = 1.7;
        const Vec2 centre(0.3, -2.1);
        const auto v = regular_polygon(n, r, centre, 0.4);
        const double pi = std::numbers::pi;
        CAPTURE(n);
        // Exact formulas evaluated in floating point: agreement to a few hundred ulps of the sum over N
        // terms.
        CHECK_CLOSE(polygon_signed_area(v), 0.5 * n * r * r * std::sin(2 * pi / n),
                    (Tolerance{1e3 * round_off, 0}));
        CHECK_CLOSE(polygon_perimeter(v), 2.0 * n * r * std::sin(pi / n), (Tolerance{1e3 * round_off, 0}));
        const Vec2 c = polygon_centroid(v);
        CHECK_CLOSE(c.x(), centre.x(), (Tolerance{0, 1e3 * round_off}));
        CHECK_CLOSE(c.y(), centre.y(), (Tolerance{0, 1e3 * round_off}));
        // Clockwise order flips the sign of the area.
        CHECK_CLOSE(polygon_signed_area(v.rowwise().reverse().eval()), -polygon_signed_area(v),
                    (Tolerance{1e3 * round_off, 0}));
    }
}

TEST_CASE("polygon area differentiates with AutoDiff: dA/dx_i = (y_{i+1} - y_{i-1})/2, dA/dy_i = (x_{i-1} - "
          "x_{i+1})/2")
{
    using Scalar = Eigen::AutoDiffScalar<Eigen::VectorXd>;
    const auto v = regular_polygon(6, 1.0, Vec2(0.2, 0.1), 0.3);
    const int n = static_cast<int>(v.cols());
    Eigen::Matrix<Scalar, 2, Eigen::Dynamic> ad(2, n);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 2; ++k)
            ad(k, i) = Scalar(v(k, i), 2 * n, 2 * i + k);
    const Eigen::VectorXd gradient = polygon_signed_area(ad).derivatives();
    for (int i = 0; i < n; ++i) {
        const int next = (i + 1) % n, previous = (i + n - 1) % n;
        CHECK_CLOSE(gradient[2 * i], 0.5 * (v(1, next) - v(1, previous)), (Tolerance{0, 10 * round_off}));
        CHECK_CLOSE(gradient[2 * i + 1], 0.5 * (v(0, previous) - v(0, next)), (Tolerance{0, 10 * round_off}));
    }
}

TEST_CASE("point-segment distance: the three branches of SPD section 2.3 (Fig. 4)")
{
    const Vec2 a(0, 0), b(2, 0);
    const auto before = point_segment_proximity(Vec2(-1, 1), a, b);
    CHECK(before.branch == SegmentBranch::end_a);
    CHECK_CLOSE(before.distance, std::sqrt(2.0), (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(before.a, -1.0, (Tolerance{4 * round_off, 0}));

    const auto inside = point_segment_proximity(Vec2(0.5, -0.3), a, b);
    CHECK(inside.branch == SegmentBranch::interior);
    CHECK_CLOSE(inside.distance, 0.3, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(inside.normal.y(), -1.0, (Tolerance{4 * round_off, 0}));

    const auto after = point_segment_proximity(Vec2(5, 4), a, b);
    CHECK(after.branch == SegmentBranch::end_b);
    CHECK_CLOSE(after.distance, 5.0, (Tolerance{4 * round_off, 0}));
}

TEST_CASE("point-segment distance and closest point are continuous across the branch boundaries a = 0, a = l")
{
    const Vec2 a(0.3, -0.2), b(1.9, 0.7);
    const Vec2 axis = (b - a).normalized(), normal(-axis.y(), axis.x());
    const double length = (b - a).norm();
    for (double boundary : {0.0, length}) {
        for (double height : {0.0, 0.37, -1.2}) {
            const double h = 1e-9; // step across the boundary
            const auto left = point_segment_proximity(a + (boundary - h) * axis + height * normal, a, b);
            const auto right = point_segment_proximity(a + (boundary + h) * axis + height * normal, a, b);
            CAPTURE(boundary);
            CAPTURE(height);
            CHECK(left.branch != right.branch);
            // Lipschitz continuity: |d(left) - d(right)| <= |C_left - C_right| = 2h (plus round-off).
            CHECK(std::abs(left.distance - right.distance) <= 2 * h + 1e3 * round_off);
            CHECK((left.closest - right.closest).norm() <= 2 * h + 1e3 * round_off);
        }
    }
}
