// DPM section 9.3.4, Fig. 9.10: an elastic shell and a spring-network disk between two plates, eq. (9.14).
// The shell has a linear force-compression law at
// small compression (exponent 1), and its compliance is that of a thin elastic ring under diametral point
// loads: delta/F = (pi/4 - 2/pi) R^3/(EI) + (4/pi - pi/4) R/(EA) (Roark, ring under diametral load with
// hoop-extension correction alpha = I/(A R^2)), with EI = k_b l0 and EA = k_l l0 for the discrete shell.
#include "core/fits.hpp"
#include "dpm/protocols/box_compress.hpp"
#include "dpm/protocols/compress.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// The exponent of F ~ delta^e: the least-squares slope of ln F against ln(delta/D) over the samples.
double force_exponent(const CompressionResult& r)
{
    std::vector<double> deflections, forces;
    for (const auto& s : r.samples) {
        deflections.push_back(s.delta_over_d);
        forces.push_back(s.force);
    }
    return fit_power_law_exponent(deflections, forces).value();
}

} // namespace

TEST_CASE(
    "shell between plates: F proportional to delta; ring compliance (pi/4 - 2/pi) R^3/EI [DPM Fig. 9.10]")
{
    const double pi = std::numbers::pi;
    CompressionOptions o; // N = 100, sigma = l0 = 1, k_p = 4 k_c
    o.steps = 8;
    o.delta_max = 1e-2;
    const CompressionResult r = compress_shell(o);
    const double c1 = force_exponent(r);
    // Linear springs and linear elasticity of the ring at delta/D <= 1e-2: geometric nonlinearity O(delta/D).
    CHECK_CLOSE(c1, 1.0, (Tolerance{0, 0.01}));
    const double R = 1.0 / (2 * std::sin(pi / o.nodes)), ei = o.kb * 1.0, ea = o.kl * 1.0;
    const double ring = (pi / 4 - 2 / pi) * R * R * R / ei + (4 / pi - pi / 4) * R / ea;
    const auto& first = r.samples.front();
    // Discrete ring of 100 vertices with loads spread over the contact vertices and compliant plate contacts
    // (k_p = 4): O(1/N) and O(k_b/(k_p R^3)) corrections, about 1 %; 2 % allowed.
    CHECK_CLOSE(first.delta_over_d * r.diameter / first.force, ring, (Tolerance{0.02, 0}));
}

TEST_CASE("spring-network disk between plates: F proportional to delta at small delta [DPM Fig. 9.10(a, c)]")
{
    CompressionOptions o;
    o.network_nodes = 300; // a smaller disk than the paper's 1100: same lattice, same contact facet
    o.steps = 6;
    o.delta_max = 5e-3;
    const CompressionResult r = compress_spring_network(o);
    // The lattice disk touches each plate with a flat row of nodes (its boundary keeps the lattice's mirror
    // symmetry): a flat punch on a linear elastic body, F = K delta with a fixed contact set. Geometric
    // nonlinearity changes the slope by O(delta/D) <= 5e-3; 0.01 allowed.
    const double c1 = force_exponent(r);
    CHECK_CLOSE(c1, 1.0, (Tolerance{0, 0.01}));
    CHECK(r.springs == 837); // the 300 lattice sites nearest to a site: 837 bonds (z = 5.58)
}

TEST_CASE("eq. (9.14): local exponent of the cylinder law is 1 + 1/ln(pi/(D~^3 F~)) [DPM eq. (9.14)]")
{
    // delta~ = (4 F~ D~/pi)(1 + L), L = ln(pi/(D~^3 F~)): d ln delta~/d ln F~ = L/(1 + L), so the exponent of
    // F~ against delta~ is (1 + L)/L = 1 + 1/L. Central differences in ln F~ (step 1e-4): error O(1e-8).
    for (const double d_tilde : {0.5, 1.0, 2.0})
        for (const double f : {1e-6, 1e-4, 1e-2}) {
            const double h = 1e-4;
            const double slope = 2 * h /
                                 (std::log(cylinder_compression(f * std::exp(h), d_tilde)) -
                                  std::log(cylinder_compression(f * std::exp(-h), d_tilde)));
            const double L = std::log(std::numbers::pi / (d_tilde * d_tilde * d_tilde * f));
            CHECK_CLOSE(slope, 1 + 1 / L, (Tolerance{1e-7, 0}));
        }
    // The prefactor: at L = 0 (F~ = pi/D~^3) delta~ = 4 F~ D~/pi = 4/D~^2.
    CHECK_CLOSE(cylinder_compression(std::numbers::pi, 1.0), 4.0, (Tolerance{1e-14, 0}));
}

TEST_CASE(
    "wall repulsion k/2 (sigma/2 - gap)^2: force = -gradient on both axes and both faces [DPM sec. 9.3.4]")
{
    // The plate law of section 9.3.4 applied to the four walls of dpm.compress_box (Fig. 9.4). Its AutoDiff
    // gradient against the analytic force k (sigma/2 - gap) along the wall normal: exact to round-off.
    const double k = 4, half = 0.5;
    for (const int axis : {0, 1})
        for (const double facing : {1.0, -1.0}) {
            const WallEnergy wall{k, half, 2.0, facing, axis};
            Eigen::Vector2d r(2.0, 2.0);
            r(axis) += facing * 0.3; // gap 0.3 < sigma/2
            const auto d = local_gradient<2>(wall, Eigen::Matrix<double, 2, 1>(r));
            CHECK_CLOSE(d.value, 0.5 * k * 0.2 * 0.2, (Tolerance{1e-14, 0}));
            CHECK_CLOSE(-d.gradient(axis), facing * k * 0.2, (Tolerance{1e-14, 0}));
            CHECK(d.gradient(1 - axis) == 0.0);
        }
    // The compression plates are the same law: PlateEnergy on y equals WallEnergy with axis 1.
    const Eigen::Vector2d r(0.7, 0.35);
    CHECK_CLOSE(local_value<2>(PlateEnergy{4, 0.5, 0.0, 1.0}, Eigen::Matrix<double, 2, 1>(r)),
                local_value<2>(WallEnergy{4, 0.5, 0.0, 1.0, 1}, Eigen::Matrix<double, 2, 1>(r)),
                (Tolerance{1e-15, 0}));
}
