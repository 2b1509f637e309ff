// The compression schedule of the jamming protocol (DPM sec. 9.4, jam_schedule.hpp) on a one-dimensional
// packing whose pressure jumps over the target window at a rearrangement (decision dpm-3d-jam-paper-size):
// bisection from below cannot land in the window, approach from above by decompression can.
#include "dpm/protocols/jam_schedule.hpp"
#include "core/errors.hpp"

#include <doctest/doctest.h>

#include <algorithm>

using namespace softgrain;
using namespace softgrain::dpm;

namespace {

// A packing of box side L that is loose (P = 0) until a compression to L <= 1 rearranges it into a jammed
// state whose branch is P = max(0, 1.001 - L): compressed from above it jumps from 0 to at least 1e-3, and
// decompressed it follows that branch down, so a target P = 1e-4 lies on the jammed branch at
// L in (1.001 - 1.01e-4, 1.001 - 1e-4], above L = 1, where the loose state has P = 0.
struct RearrangingPacking
{
    double L = 1.05, saved_L = 1.05;
    bool jammed = false, saved_jammed = false;

    CompressiblePacking operations()
    {
        return {[this] { return jammed ? std::max(0.0, 1.001 - L) : 0.0; },
                [this](double f) { L *= f; },
                [this](long) {
                    jammed = jammed || L <= 1.0;
                    return 1L;
                },
                [this] {
                    saved_L = L;
                    saved_jammed = jammed;
                },
                [this] {
                    L = saved_L;
                    jammed = saved_jammed;
                },
                {}};
    }
};

} // namespace

TEST_CASE("a pressure jump over the window: bisection fails, an overshoot kept and decompressed lands in "
          "it [decision dpm-3d-jam-paper-size]")
{
    const double target = 1e-4;
    {
        RearrangingPacking packing;
        BoxSchedule schedule;
        schedule.onset = target;
        CHECK_THROWS_AS(reach_pressure(target, true, schedule, packing.operations()), NumericalError);
        CHECK_FALSE(packing.jammed); // every overshoot was undone
    }
    RearrangingPacking packing;
    BoxSchedule schedule;
    schedule.onset = target;
    schedule.jump_step = 1e-3; // the first step 5e-3 halved three times: 6.25e-4
    reach_pressure(target, true, schedule, packing.operations());
    CHECK(packing.jammed);
    CHECK(schedule.jumps == 1);
    const double p = packing.operations().pressure();
    CHECK(p >= target);
    CHECK(p < 1.01 * target);
    CHECK(packing.L > 1.0); // on the jammed branch above the rearrangement, reached by decompression
}
