#include "compare/ring.hpp"

#include "core/errors.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/compress.hpp"
#include "dpm/system/system.hpp"
#include "spd/elastica.hpp"
#include "spd/ring.hpp"
#include "spd/time_step_limits.hpp"
#include "spd/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softgrain::compare {

namespace {

constexpr double pi = std::numbers::pi;

// The SPD ring of the same material: eta = 0, elastic, out-of-plane length 1 m (it enters neither the
// elastic ring's laws nor its observables).
spd::RingSetup spd_setup(const RingComparisonSetup& comparison)
{
    spd::RingSetup ring;
    ring.nodes = comparison.nodes;
    ring.radius = comparison.radius;
    ring.material = {comparison.E, comparison.nu, comparison.h, 1.0, INFINITY};
    ring.eta = 0;
    ring.plastic_ratio = INFINITY;
    ring.dt_factor = comparison.dt_factor;
    return ring;
}

// The observables of a recorded SPD state; B the bending rigidity.
RingObservation spd_observation(const RingComparisonSetup& comparison, double B,
                                const spd::CompressionState& state)
{
    // profile_x spans the top-wall contact from its leftmost to its rightmost touching vertex.
    const auto [lo, hi] = std::minmax_element(state.profile_x.begin(), state.profile_x.end());
    const double contact = state.profile_x.empty() ? 0.0 : *hi - *lo;
    return {state.strain, state.wall_force * comparison.radius * comparison.radius / B, state.width,
            state.volume, contact / (2 * comparison.radius)};
}

RingComparison compress_spd(const RingComparisonSetup& comparison,
                            const std::function<void(double)>& progress, const RingFrameObserver& frame)
{
    const spd::RingSetup setup = spd_setup(comparison);
    const spd::RingScales scales = spd::ring_scales(setup);
    const double B = scales.flexural_rigidity;
    spd::CompressionObserver observe;
    if (frame)
        observe = [&](const spd::RingBetweenWalls& walls, const spd::CompressionState& state) {
            frame(spd_observation(comparison, B, state),
                  spd::shell_frame(walls.model, {walls.ring}, {walls.bottom_wall, walls.top_wall}));
        };
    const spd::CompressionResult result =
        spd::ring_compression(setup, comparison.strain_max, comparison.strain_step, false,
                              comparison.relax_tolerance, progress, observe);
    RingComparison out;
    out.bending_rigidity = B;
    out.steps = result.steps;
    out.dt = result.dt;
    out.dt_critical = result.dt_critical;
    out.dt_stable = spd::stable_time_step(spd::ring_between_walls(setup).model);
    for (const spd::CompressionState& state : result.states)
        out.states.push_back(spd_observation(comparison, B, state));
    return out;
}

RingComparison compress_dpm(const RingComparisonSetup& comparison,
                            const std::function<void(double)>& progress, const RingFrameObserver& frame)
{
    // The same constants as the SPD ring (decision compare-ring-mapping).
    const spd::RingScales scales = spd::ring_scales(spd_setup(comparison));
    const int n = comparison.nodes;
    const double R = comparison.radius, b0 = 2 * R, sigma = comparison.h;
    const Eigen::Matrix2Xd polygon = dpm::regular_polygon(n, R, Eigen::Vector2d::Zero(), 0.0);
    dpm::ShapeParameters shape;
    shape.kl = scales.laws.k_s;
    shape.l0 = scales.l0;
    shape.kb = scales.laws.k_b;
    shape.theta0 = 2 * pi / n;
    shape.a0 = 0.5 * n * R * R * std::sin(2 * pi / n); // unused: k_a = 0 (no enclosed fluid, as eta = 0)
    dpm::DpmSystem system;
    Eigen::VectorXd x;
    system.add_particle(polygon, sigma, shape, x);
    const dpm::BodyEnergy body = [&system](const Eigen::VectorXd& y, Eigen::VectorXd* gradient) {
        return dpm::total_energy(system, y, gradient, nullptr);
    };
    // Unit vertex masses, as the SPD ring. lambda_max <= 4 k_l (a chain of springs) + 16 k_b/l0^2 (the
    // zig-zag bending mode): the eigenvalue of a sum is at most the sum of the largest ones.
    const double lambda_max = 4 * shape.kl + 16 * shape.kb / (shape.l0 * shape.l0);
    RingComparison out;
    out.bending_rigidity = scales.flexural_rigidity;
    out.dt = out.dt_critical = out.dt_stable = NAN;
    const double force_scale = out.bending_rigidity / (R * R);

    dpm::PlateSchedule schedule;
    schedule.kp = scales.laws.k_s; // decision compare-ring-plates: the SPD wall contact k_n = k_s
    // The rms force bound that implies a largest force component below relax_tolerance B/R^2, as in SPD.
    schedule.force_tolerance = comparison.relax_tolerance * force_scale / std::sqrt(2.0 * n);
    // A velocity below the one the tolerance force gives in one largest FIRE step, dt_max = 0.5/sqrt(lambda).
    const double dt_max = 0.5 / std::sqrt(std::max(schedule.kp, lambda_max));
    schedule.kinetic_tolerance = 0.5 * std::pow(schedule.force_tolerance * dt_max, 2);
    // The driver lifts the ring onto the bottom plate (lowest vertex at sigma/2) and starts the top plate
    // at the highest vertex + sigma/2: D = 2R + sigma, and the mid-line gap is b = b0 - delta.
    const double D = polygon.row(1).maxCoeff() - polygon.row(1).minCoeff() + sigma;
    const int increments = static_cast<int>(std::lround(comparison.strain_max / comparison.strain_step));
    schedule.compressions.push_back(0.0);
    for (int k = 1; k <= increments; ++k)
        schedule.compressions.push_back(comparison.strain_max * k / increments * b0 / D);
    const double A0 = dpm::particle_area(x, 0, n);
    const auto observe = [&](const Eigen::VectorXd& y, double top, const dpm::CompressionSample& sample) {
        const auto points = y.reshaped(2, n);
        double xmin = INFINITY, xmax = -INFINITY, cmin = INFINITY, cmax = -INFINITY;
        for (int i = 0; i < n; ++i) {
            xmin = std::min(xmin, points(0, i));
            xmax = std::max(xmax, points(0, i));
            if (top - points(1, i) < 0.5 * sigma) { // touches the top plate
                cmin = std::min(cmin, points(0, i));
                cmax = std::max(cmax, points(0, i));
            }
        }
        const double contact = cmax > cmin ? cmax - cmin : 0.0;
        out.states.push_back({sample.delta_over_d * D / b0, sample.force * R * R / out.bending_rigidity,
                              (xmax - xmin) / b0, dpm::particle_area(y, 0, n) / A0, contact / b0});
        if (frame)
            frame(out.states.back(), {{"particles", dpm::dpm_particles(system, y)},
                                      {"plates", dpm::plates(xmin - sigma, xmax + sigma, 0.0, top)}});
        progress(static_cast<double>(out.states.size()) / schedule.compressions.size());
    };
    try {
        out.steps = dpm::compress_between_plates<2>(x, body, sigma, lambda_max, schedule, observe).iterations;
    } catch (const NumericalError& error) {
        throw NumericalError(
            error.quantity + " at strain " + std::to_string(comparison.strain_step * (error.step)),
            error.step, "FIRE did not reach relax_tolerance; raise relax_tolerance or check the inputs");
    }
    return out;
}

} // namespace

RingComparison compress_ring(const RingComparisonSetup& setup, const std::function<void(double)>& progress,
                             const RingFrameObserver& frame)
{
    if (setup.nodes % 4 != 0)
        throw InputError("nodes = " + std::to_string(setup.nodes) +
                         ": allowed a multiple of 4 (a vertex on each plate at eps = 0)");
    const auto whole = [](double ratio) { return ratio > 0.5 && std::abs(ratio - std::round(ratio)) < 1e-9; };
    if (!whole(0.1 / setup.strain_step))
        throw InputError(
            "strain_step = " + std::to_string(setup.strain_step) +
            ": allowed 0.1/k for an integer k (the observables are reported at eps = 0.1, 0.2, ...)");
    if (!whole(setup.strain_max / setup.strain_step))
        throw InputError("strain_max = " + std::to_string(setup.strain_max) +
                         ": allowed a whole multiple of strain_step = " + std::to_string(setup.strain_step));
    return setup.method == RingMethod::spd ? compress_spd(setup, progress, frame)
                                           : compress_dpm(setup, progress, frame);
}

RingErrors elastica_errors(const RingObservation& observation)
{
    const spd::ElasticaState elastica = spd::elastica_ring_between_plates(observation.strain);
    return {std::abs(observation.force / elastica.force - 1),
            std::abs(observation.width / elastica.width - 1), std::abs(observation.volume - elastica.volume),
            std::abs(observation.contact_length - elastica.contact_length)};
}

bool reported_strain(double strain)
{
    const double tenths = 10 * strain;
    return strain > 0 && std::abs(tenths - std::round(tenths)) <= 1e-6;
}

std::optional<RingErrors> largest_elastica_errors(const RingComparison& comparison)
{
    std::optional<RingErrors> worst;
    for (const RingObservation& state : comparison.states) {
        if (!reported_strain(state.strain)) continue;
        const RingErrors errors = elastica_errors(state);
        const RingErrors so_far = worst.value_or(RingErrors{});
        worst = RingErrors{std::max(so_far.force, errors.force), std::max(so_far.width, errors.width),
                           std::max(so_far.volume, errors.volume),
                           std::max(so_far.contact_length, errors.contact_length)};
    }
    return worst;
}

} // namespace softgrain::compare
