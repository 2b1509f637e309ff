#include "spd/tissue_measures.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace softgrain::spd {

std::vector<double> stress_drops(const std::vector<double>& sigma, double threshold)
{
    std::vector<double> drops;
    double high = sigma.front(), low = sigma.front();
    bool falling = false;
    for (double value : sigma) {
        if (!falling) {
            high = std::max(high, value);
            if (value < high - threshold) falling = true, low = value;
        } else {
            low = std::min(low, value);
            if (value > low + threshold) {
                drops.push_back(high - low);
                falling = false;
                high = value;
            }
        }
    }
    if (falling) drops.push_back(high - low);
    return drops;
}

std::size_t nearest_snapshot(const std::vector<TissueSnapshot>& snapshots, double strain)
{
    std::size_t best = 0;
    for (std::size_t k = 0; k < snapshots.size(); ++k)
        if (std::abs(snapshots[k].strain - strain) < std::abs(snapshots[best].strain - strain)) best = k;
    return best;
}

CurveMeasures curve_measures(const std::vector<TissueRecord>& records, double width_depth)
{
    CurveMeasures measures;
    for (std::size_t k = 0; k < records.size(); ++k) {
        measures.sigma.push_back(records[k].force_top / width_depth);
        if (measures.sigma.back() > measures.sigma_max)
            measures.sigma_max = measures.sigma.back(), measures.peak = k;
    }
    for (std::size_t k = measures.peak; k < records.size(); ++k)
        if (measures.sigma[k] < 0.1 * measures.sigma_max) {
            measures.strain_at_failure = records[k].strain;
            break;
        }
    std::vector<double> normalised;
    for (double sigma : measures.sigma)
        normalised.push_back(sigma / measures.sigma_max);
    measures.drops = stress_drops(normalised, 0.05);
    if (measures.drops.size() >= 2) {
        const std::size_t half = measures.drops.size() / 2;
        double first = 0, second = 0;
        for (std::size_t k = 0; k < measures.drops.size(); ++k)
            (k < half ? first : second) += measures.drops[k];
        measures.growth = (second / static_cast<double>(measures.drops.size() - half)) /
                          (first / static_cast<double>(half));
    }
    return measures;
}

double crack_height(const Tissue& tissue)
{
    const ShellModel& model = tissue.model;
    const double y_bottom = model.vertex(tissue.bottom.front()).y(), H = clamp_height(tissue);
    double height = 0;
    for (const CohesiveLink& link : model.links())
        if (link.broken)
            height += (0.5 * (model.vertex(link.a).y() + model.vertex(link.b).y()) - y_bottom) / H;
    return height / model.broken_links();
}

LinkBreak break_one_link(ShellModel model, std::size_t index, double approach, bool opening, double increment,
                         double dt)
{
    // Opening moves b and b' (the frame stays); a slip of f_t^0/k_t ~ 0.4 m would carry b' past the end of
    // the interface into the next cell, so a slip moves b alone, along t into the interface (m moves along
    // t: the frame stays; the approach turns it by approach/(2 |m' - m|) ~ 1e-2, which the measured f_n, f_t
    // at the break include).
    const CohesiveLink link = model.links()[index];
    const LinkKinematics kinematics =
        link_kinematics(link, model.vertex(link.a), model.vertex(link.b), model.vertex(link.partner_a),
                        model.vertex(link.partner_b));
    const Vec2 direction = opening ? kinematics.n : kinematics.t;
    const Vec2 b = model.vertex(link.b) - approach * kinematics.n, partner_b = model.vertex(link.partner_b);
    try {
        for (int step = 0; step <= 20000; ++step) {
            model.set_vertex(link.b, b + step * increment * direction);
            if (opening) model.set_vertex(link.partner_b, partner_b + step * increment * direction);
            model.compute_forces(dt);
            const CohesiveLink& now = model.links()[index];
            if (now.broken) return {now.f_n, now.f_t, step * increment};
        }
    } catch (const NumericalError&) { // e.g. the contact law refusing the overlap: reported as no break (NaN)
    }
    return {};
}

LinkStrength measure_link_strength(const Tissue& tissue, double dt)
{
    const CohesiveLaw& law = tissue.model.link_law();
    return {break_one_link(tissue.model, 0, 0.0, true, 7e-4 * std::abs(law.f_n0) / law.k_n, dt),
            break_one_link(tissue.model, 0, 0.5 * std::abs(law.f_n0) / law.k_n, false,
                           7e-4 * law.f_t0 / law.k_t, dt)};
}

} // namespace softgrain::spd
