#include "dpm/protocols/jam_schedule.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::dpm {

std::vector<double> pressure_targets(double onset, double pressure_max, int count)
{
    std::vector<double> targets{onset};
    for (int k = 1; k <= count; ++k)
        targets.push_back(onset * std::pow(pressure_max / onset, double(k) / count));
    return targets;
}

long reach_pressure(double target, bool compressing, BoxSchedule& schedule,
                    const CompressiblePacking& packing)
{
    long iterations = 0;
    double& step = schedule.step;
    for (;; ++schedule.step_index) {
        const double p = packing.pressure();
        if (p >= target && p < 1.01 * target) break;
        if (step < 1e-15)
            throw NumericalError("box step below 1e-15 before 1 <= P/P_target < 1.01", schedule.step_index,
                                 "a rearrangement makes the pressure jump over the window");
        packing.save();
        packing.scale(compressing ? 1.0 - step : 1.0 + step);
        iterations += packing.relax(schedule.step_index);
        const double after = packing.pressure();
        if (compressing && after >= 1.01 * target && step < schedule.jump_step) {
            compressing = false; // a jump over the window: approach it from above (BoxSchedule::jump_step)
            ++schedule.jumps;
        } else if (compressing ? after >= 1.01 * target : after < target) { // beyond the window: back, halve
            packing.restore();
            step *= 0.5;
        } else if (compressing ? target > schedule.onset && after < 0.5 * target && after > 0
                               : after > 2 * target) {
            step = std::min(2 * step, schedule.largest_step);
        }
    }
    return iterations;
}

long reach_stable_pressure(double target, BoxSchedule& schedule, const CompressiblePacking& packing,
                           int max_escapes, int& escapes)
{
    long iterations = reach_pressure(target, true, schedule, packing);
    while (packing.leave_saddle && escapes < max_escapes && packing.leave_saddle()) {
        ++escapes;
        iterations += packing.relax(schedule.step_index);
        schedule.step = schedule.largest_step;
        iterations += reach_pressure(target, packing.pressure() < target, schedule, packing);
    }
    return iterations;
}

} // namespace softgrain::dpm
