#include "core/geometry.hpp"

#include <stdexcept>

namespace softgrain {

SegmentProximity point_segment_proximity(const Vec2& c, const Vec2& a, const Vec2& b)
{
    SegmentProximity p;
    const Vec2 ab = b - a;
    p.length = ab.norm();
    if (!(p.length > 0)) throw std::invalid_argument("point_segment_proximity: segment of zero length");
    const Vec2 axis = ab / p.length;
    p.a = (c - a).dot(axis); // SPD section 2.3: a = AC.AB / |AB|
    if (p.a < 0) {
        p.branch = SegmentBranch::end_a;
        p.closest = a;
    } else if (p.a > p.length) {
        p.branch = SegmentBranch::end_b;
        p.closest = b;
    } else {
        p.branch = SegmentBranch::interior;
        p.closest = a + p.a * axis;
    }
    const Vec2 offset = c - p.closest;
    p.distance = offset.norm();
    p.normal = p.distance > 0 ? Vec2(offset / p.distance) : Vec2(-axis.y(), axis.x());
    return p;
}

} // namespace softgrain
