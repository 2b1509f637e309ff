#include "spd/compression_measures.hpp"

#include "core/fits.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace softgrain::spd {

namespace {

// The loading state at the largest strain: the last one recorded while loading.
const CompressionState& last_loading_state(const std::vector<CompressionState>& states)
{
    const CompressionState* last = nullptr;
    for (const CompressionState& state : states)
        if (state.loading) last = &state;
    return *last;
}

// The last loading state at or below the strain eps.
const CompressionState& last_loading_state_below(const std::vector<CompressionState>& states, double eps)
{
    const CompressionState* found = nullptr;
    for (const CompressionState& state : states)
        if (state.loading && state.strain <= eps + 1e-9) found = &state;
    return *found;
}

// The loading curve's measures that compare the ring with itself and with eq. (31) (Figs. 12, 15): they
// collect the late states (eps >= 0.3) and the states in contact.
void measure_loading_curve(const RingSetup& setup, const RingScales& scales, const CompressionResult& result,
                           CompressionMeasures& measures)
{
    const bool plastic = std::isfinite(setup.plastic_ratio);
    const double l0 = scales.l0;
    std::vector<double> eps_late, contact_late, contact_vertices, force_ratio;
    for (const CompressionState& state : result.states) {
        if (!state.loading) continue;
        const double eps = state.strain;
        measures.volume_deviation_max =
            std::max(measures.volume_deviation_max, std::abs(state.volume - (1 - eps * eps)));
        if (eps > 0.3 - 1e-9) eps_late.push_back(eps), contact_late.push_back(state.contact_length);
        if (state.contact_vertices > 0) {
            contact_vertices.push_back(state.contact_vertices);
            force_ratio.push_back(plastic ? state.wall_force / scales.characteristic.F_2star
                                          : state.wall_force / scales.characteristic.F_star);
        }
    }
    measures.contact_length_slope = fit_line_slope(eps_late, contact_late);
    measures.contact_length_slope_quantisation = slope_error_bound(eps_late, l0 / (2 * setup.radius));
    measures.force_contact_slope = fit_line_slope(contact_vertices, force_ratio);
    double excess = -INFINITY;
    for (std::size_t k = 0; k < contact_vertices.size(); ++k)
        excess = std::max(excess, force_ratio[k] - contact_vertices[k]);
    measures.force_contact_excess_max = std::isfinite(excess) ? excess : NAN;
}

// The loading curve against the elastica at the same strains (eta = 0, elastic ring).
ElasticaDeviations elastica_deviations(const RingSetup& setup, const RingScales& scales,
                                       const CompressionResult& result)
{
    const double R = setup.radius, l0 = scales.l0;
    ElasticaDeviations deviations;
    std::vector<double> eps_late, contact_late;
    for (const CompressionState& state : result.states) {
        if (!state.loading) continue;
        const double eps = state.strain;
        const ElasticaState elastica = elastica_ring_between_plates(eps);
        if (eps > 0.3 - 1e-9) eps_late.push_back(eps), contact_late.push_back(elastica.contact_length);
        if (eps <= 0) continue;
        deviations.volume_deviation_max =
            std::max(deviations.volume_deviation_max, std::abs(elastica.volume - (1 - eps * eps)));
        deviations.width_error_max =
            std::max(deviations.width_error_max, std::abs(state.width / elastica.width - 1));
        deviations.volume_error_max =
            std::max(deviations.volume_error_max, std::abs(state.volume - elastica.volume));
        const double elastica_force = elastica.force * scales.flexural_rigidity / (R * R);
        if (eps >= 0.05 - 1e-9)
            deviations.force_error_max =
                std::max(deviations.force_error_max, std::abs(state.wall_force / elastica_force - 1));
        if (state.contact_vertices > 0)
            deviations.contact_length_error_max =
                std::max(deviations.contact_length_error_max,
                         std::abs((state.contact_vertices - 1) * l0 - elastica.contact_length * 2 * R) / l0);
    }
    deviations.contact_length_slope = fit_line_slope(eps_late, contact_late);
    deviations.final = elastica_ring_between_plates(last_loading_state(result.states).strain);
    return deviations;
}

// The relative second difference (c - 2b + a)/(c - a) of three values.
double relative_second_difference(double a, double b, double c)
{
    return (c - 2 * b + a) / (c - a);
}

// Fig. 25: the second differences of F (and of the elastica's) over the loading states nearest to 1/2 and
// 3/4 of the largest strain and the last one.
void measure_late_force_growth(const CompressionResult& result, CompressionMeasures& measures)
{
    const CompressionState& last = last_loading_state(result.states);
    const CompressionState& half = loading_state_nearest(result.states, 0.5 * last.strain);
    const CompressionState& three_quarters = loading_state_nearest(result.states, 0.75 * last.strain);
    const double Fa = half.wall_force, Fb = three_quarters.wall_force, Fc = last.wall_force;
    if (!(Fa > 0 && Fb > 0 && Fc > 0 && &half != &three_quarters && &three_quarters != &last)) return;
    measures.force_second_difference = relative_second_difference(Fa, Fb, Fc);
    measures.log_force_second_difference =
        (std::log(Fc) - 2 * std::log(Fb) + std::log(Fa)) / std::log(Fc / Fa);
    if (measures.elastica)
        measures.elastica->force_second_difference =
            relative_second_difference(elastica_ring_between_plates(half.strain).force,
                                       elastica_ring_between_plates(three_quarters.strain).force,
                                       elastica_ring_between_plates(last.strain).force);
}

} // namespace

bool elastica_applies(const RingSetup& setup)
{
    return setup.eta == 0 && !std::isfinite(setup.plastic_ratio);
}

double slope_error_bound(const std::vector<double>& x, double delta)
{
    if (x.size() < 2) return NAN;
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
    double spread = 0, variance = 0;
    for (const double xi : x) {
        spread += std::abs(xi - mean);
        variance += (xi - mean) * (xi - mean);
    }
    return delta * spread / variance;
}

const CompressionState& loading_state_nearest(const std::vector<CompressionState>& states, double eps)
{
    const CompressionState* best = nullptr;
    for (const CompressionState& state : states)
        if (state.loading && (!best || std::abs(state.strain - eps) < std::abs(best->strain - eps)))
            best = &state;
    return *best;
}

ProfileShape profile_shape(const CompressionState& state, double l0)
{
    ProfileShape shape;
    const std::size_t n = state.profile_x.size();
    if (n == 0) return shape;
    std::vector<std::size_t> by_x(n);
    std::iota(by_x.begin(), by_x.end(), 0);
    std::sort(by_x.begin(), by_x.end(),
              [&](std::size_t a, std::size_t b) { return state.profile_x[a] < state.profile_x[b]; });
    const auto pressure = [&](std::size_t rank) { return state.profile_pressure[by_x[rank]]; };
    double total = 0, centre_distance = INFINITY, edge = 0, edge_zone = 0;
    for (std::size_t k = 0; k < n; ++k) {
        total += pressure(k);
        const std::size_t from_edge = std::min(k, n - 1 - k);
        edge += from_edge == 0 ? pressure(k) : 0.0;
        edge_zone += from_edge <= 1 ? pressure(k) : 0.0;
        if (std::abs(state.profile_x[by_x[k]]) < centre_distance)
            centre_distance = std::abs(state.profile_x[by_x[k]]), shape.centre_pressure = pressure(k);
    }
    if (centre_distance >= 0.5 * l0) shape.centre_pressure = 0;
    if (total > 0)
        shape.centre_share = shape.centre_pressure / total, shape.edge_share = edge / total,
        shape.edge_zone_share = edge_zone / total;
    return shape;
}

CompressionMeasures measure_compression(const RingSetup& setup, const CompressionResult& result)
{
    const RingScales scales = ring_scales(setup);
    const double F_star = scales.characteristic.F_star, l0 = scales.l0;
    CompressionMeasures measures;
    measures.final = last_loading_state(result.states);
    measures.middle = last_loading_state_below(result.states, 0.5 * measures.final.strain);
    measures.early = loading_state_nearest(result.states, 0.1);
    const auto first =
        std::find_if(result.states.begin(), result.states.end(), [](const CompressionState& state) {
            return state.loading && state.contact_vertices > 0;
        });
    if (first != result.states.end()) measures.first_contact = *first;
    if (measures.final.strain >= 0.25 - 1e-9)
        measures.contact_length_eps025 = loading_state_nearest(result.states, 0.25).contact_length;
    measure_loading_curve(setup, scales, result, measures);
    if (elastica_applies(setup)) measures.elastica = elastica_deviations(setup, scales, result);
    measure_late_force_growth(result, measures);
    const CompressionState& last = measures.final;
    if (last.contact_vertices > 0)
        measures.eq35_ratio_final =
            last.wall_force / F_star /
            ((1 + last.core_pressure * setup.material.s * l0 / F_star) * last.contact_vertices);
    measures.early_profile = profile_shape(measures.early, l0);
    measures.final_profile = profile_shape(last, l0);
    return measures;
}

} // namespace softgrain::spd
