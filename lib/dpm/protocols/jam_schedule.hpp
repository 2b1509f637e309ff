// The compression schedule of the jamming protocol, DPM section 9.4 (P-DPM-JAM), independent of the
// dimension and of the particle model: change the box by Delta L/L, relax (FIRE) and read the pressure;
// compressing, a step that overshoots 1 <= P/P_target < 1.01 is undone and halved; decompressing, one that
// undershoots it. Far from a target the step grows again, never beyond the first (decision
// dpm-jam-protocol; below onset the pressure is FIRE round-off and says nothing, so compression towards
// onset never grows it). Used by the 2D protocol (jam.hpp) and the 3D one (jam3d.hpp).
#pragma once

#include <functional>
#include <vector>

namespace softgrain::dpm {

// The operations the schedule needs from a packing.
struct CompressiblePacking
{
    std::function<double()> pressure;  // P in the unit of the targets
    std::function<void(double)> scale; // box side and particle centres scaled by the factor f, shapes kept
    std::function<long(long)> relax;   // FIRE from the current state (argument: step index); iterations
    std::function<void()> save;        // remember the state (coordinates and box)
    std::function<void()> restore;     // return to the state saved last
    // Optional (decision dpm-packing-minimum): moves the packing off a saddle and returns true, or returns
    // false at a minimum (leave_saddle, modes.hpp).
    std::function<bool()> leave_saddle;
};

struct BoxSchedule
{
    double step = 5e-3;         // current Delta L/L
    double largest_step = 5e-3; // the first step and the cap of its growth (decision dpm-jam-protocol)
    double onset = 0;           // P_t: below it the step never grows
    long step_index = 0;        // box changes so far (diagnostics)
    // Compressing: an overshoot of the window at a step below this is kept, and the target is approached
    // from above by decompression (a rearrangement makes P jump over the window, so no smaller step lands
    // in it from below; decision dpm-3d-jam-paper-size). 0: every overshoot is undone and halved.
    double jump_step = 0;
    long jumps = 0; // overshoots kept under jump_step (diagnostics)
};

// The targets of a compression: P_t, then `count` pressures log-spaced in (P_t, pressure_max]
// (P_t (pressure_max/P_t)^(k/count), k = 1 ... count).
std::vector<double> pressure_targets(double onset, double pressure_max, int count);

// Changes the box until 1 <= P/target < 1.01; returns the FIRE iterations spent. NumericalError if the
// step falls below 1e-15 (a rearrangement makes the pressure jump over the window). Compressing, an
// overshoot at a step below schedule.jump_step is kept and the rest is decompression.
long reach_pressure(double target, bool compressing, BoxSchedule& schedule,
                    const CompressiblePacking& packing);

// reach_pressure, then, while the packing there is a saddle (packing.leave_saddle) and fewer than
// `max_escapes` moves were made: move off it, relax, and reach the target again from the new state with
// the box step reset to the first, compressing or decompressing as the pressure requires. A saddle of a
// jammed packing is unstable: relaxed from it, the packing falls to another state, at a lower pressure
// (the 16 x 42 shell packing: P from 1e-7 to 3.5e-12), and is compressed to the target again. `escapes`
// counts the moves. Returns the FIRE iterations spent.
long reach_stable_pressure(double target, BoxSchedule& schedule, const CompressiblePacking& packing,
                           int max_escapes, int& escapes);

} // namespace softgrain::dpm
