#include "dpm/protocols/shear_modulus_ensemble.hpp"

#include "core/fits.hpp"
#include "core/output.hpp"
#include "dpm/analysis/stress.hpp"

#include <cmath>

namespace softgrain::dpm {

double smallest_normal_stress(const DpmSystem& system, const Eigen::VectorXd& x)
{
    const Eigen::Matrix2d sigma = stress_tensor(system, x);
    return sigma.diagonal().minCoeff() / pressure(sigma);
}

double smallest_normal_stress(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    const Eigen::Matrix3d sigma = stress_tensor3d(system, x);
    return sigma.diagonal().minCoeff() / pressure3d(sigma);
}

namespace {

// The least-squares line of ln<G> against ln<P> over the pressures above onset where <G> > 0, the means over
// the members other than `left_out` (pass members.size() to keep every member); absent with fewer than two
// such pressures.
std::optional<Line> mean_modulus_fit(const std::vector<ModulusMember>& members, std::size_t left_out)
{
    const std::size_t levels = members.front().pressure.size();
    const auto kept = static_cast<double>(members.size() - (left_out < members.size() ? 1 : 0));
    std::vector<double> fitted_p, fitted_g;
    for (std::size_t l = 1; l < levels; ++l) {
        double p = 0, g = 0;
        for (std::size_t k = 0; k < members.size(); ++k)
            if (k != left_out) p += members[k].pressure[l] / kept, g += members[k].modulus[l] / kept;
        if (g > 0) fitted_p.push_back(p), fitted_g.push_back(g);
    }
    return fit_power_law(fitted_p, fitted_g);
}

} // namespace

// Tukey's jackknife (Efron and Stein, Ann. Statist. 9, 586 (1981)); why it and not the fit's error: the header.
std::optional<double> jackknife_exponent_error(const std::vector<ModulusMember>& members)
{
    const std::size_t n = members.size();
    if (n < 2) return std::nullopt;
    std::vector<double> exponents;
    for (std::size_t k = 0; k < n; ++k) {
        const auto line = mean_modulus_fit(members, k);
        if (!line) return std::nullopt;
        exponents.push_back(line->slope);
    }
    double mean = 0, squares = 0;
    for (double e : exponents)
        mean += e / static_cast<double>(n);
    for (double e : exponents)
        squares += (e - mean) * (e - mean);
    return std::sqrt(static_cast<double>(n - 1) / static_cast<double>(n) * squares);
}

EnsembleModulus report_ensemble(const std::vector<ModulusMember>& members, const ModulusTables& tables,
                                RunContext& context)
{
    const std::string& unit = tables.pressure_unit;
    auto& each = context.table(tables.per_packing,
                               {{"packing", "1", "ensemble member (seed - first seed)"},
                                {"P", unit, tables.pressure_meaning},
                                {"phi", "1", "packing fraction"},
                                {"G", unit, "shear modulus d(-Sigma_xy)/d gamma"},
                                {"G_linear", unit, "linear response G_affine - Xi^T H^+ Xi"},
                                {"stress_min", "1",
                                 "smallest normal stress min_a Sigma_aa over the pressure: about 1 "
                                 "jammed along every axis, ~0 along fewer (then G can vanish)"},
                                {"negative_modes", "1", "negative eigenvalues of H"}});
    EnsembleModulus out;
    const auto packings = static_cast<double>(members.size());
    const std::size_t levels = members.front().pressure.size();
    std::vector<double> mean_p(levels, 0.0), mean_g(levels, 0.0), mean_linear(levels, 0.0);
    for (std::size_t k = 0; k < members.size(); ++k) {
        const ModulusMember& m = members[k];
        out.fire_iterations += m.fire_iterations;
        out.force_max = std::max(out.force_max, m.force_max);
        for (std::size_t l = 0; l < levels; ++l) {
            each.row({double(k), m.pressure[l], m.phi[l], m.modulus[l], m.modulus_linear[l],
                      m.normal_stress_min[l], double(m.negative_modes[l])});
            mean_p[l] += m.pressure[l] / packings;
            mean_g[l] += m.modulus[l] / packings;
            mean_linear[l] += m.modulus_linear[l] / packings;
            if (m.negative_modes[l] > 0) ++out.saddles;
        }
    }
    auto& mean =
        context.table(tables.mean, {{"P", unit, "ensemble mean pressure"},
                                    {"G", unit, "ensemble mean shear modulus <G>"},
                                    {"G_linear", unit, "ensemble mean linear-response shear modulus"}});
    for (std::size_t l = 0; l < levels; ++l)
        mean.row({mean_p[l], mean_g[l], mean_linear[l]});
    std::vector<double> slopes;
    for (const ModulusMember& m : members) {
        std::vector<double> p, g;
        for (std::size_t l = 1; l < levels; ++l)
            if (m.modulus[l] > 0) p.push_back(m.pressure[l]), g.push_back(m.modulus[l]);
        if (const auto exponent = fit_power_law_exponent(p, g)) slopes.push_back(*exponent);
    }
    out.packings_with_slope = static_cast<int>(slopes.size());
    if (slopes.size() >= 2) {
        double mean_slope = 0, var = 0;
        for (double v : slopes)
            mean_slope += v / static_cast<double>(slopes.size());
        for (double v : slopes)
            var += (v - mean_slope) * (v - mean_slope) / static_cast<double>(slopes.size() - 1);
        out.eta_spread = std::sqrt(var);
    }
    out.G_onset = mean_g.front();
    out.G_max_pressure = mean_g.back();
    out.G_linear_onset = mean_linear.front();
    out.G_linear_max_pressure = mean_linear.back();
    if (const auto line = mean_modulus_fit(members, members.size())) {
        out.eta = line->slope;
        out.eta_error = std::sqrt(line->slope_variance);
        out.eta_standard_error = jackknife_exponent_error(members);
    }
    return out;
}

void write_modulus_summary(const EnsembleModulus& e, const std::string& suffix, nlohmann::json& s)
{
    s["G_onset" + suffix] = e.G_onset;
    s["G_max_pressure" + suffix] = e.G_max_pressure;
    s["shear_modulus_exponent" + suffix] = e.eta ? nlohmann::json(*e.eta) : nlohmann::json(nullptr);
    s["shear_modulus_exponent_error" + suffix] =
        e.eta_error ? nlohmann::json(*e.eta_error) : nlohmann::json(nullptr);
    s["force_max" + suffix] = e.force_max;
    s["shear_modulus_exponent_standard_error" + suffix] =
        e.eta_standard_error ? nlohmann::json(*e.eta_standard_error) : nlohmann::json(nullptr);
    s["shear_modulus_exponent_spread" + suffix] =
        e.eta_spread ? nlohmann::json(*e.eta_spread) : nlohmann::json(nullptr);
    s["packings_with_slope" + suffix] = e.packings_with_slope;
    s["G_linear_onset" + suffix] = e.G_linear_onset;
    s["G_linear_max_pressure" + suffix] = e.G_linear_max_pressure;
    s["saddles" + suffix] = e.saddles;
}

} // namespace softgrain::dpm
