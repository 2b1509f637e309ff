// Reductions of the quasi-static diametral compression of a ring (Trivino et al., section 4, Figs. 12-25) to
// the numbers its figures check: the growth of the contact, the force against the contact length
// (eq. (31)), how the wall contact carries the force, the late force growth, and the deviations from the
// inextensible elastica (eta = 0, elastic rings; lib/spd/elastica.hpp).
//
// Units: strains, a/b0, L_c/b0, V/V0 and N' = L_c/l0 are ratios; forces are over F* = k_b/R (eq. (30)), or
// F** = M^Y/l (eq. (33)) where stated for a plastic ring; pressures over p* = F*/(s l0).
#pragma once

#include "spd/elastica.hpp"
#include "spd/ring.hpp"

#include <optional>
#include <vector>

namespace softgrain::spd {

// The largest change of the least-squares slope over the abscissae x when each ordinate moves by at most
// delta: delta sum|x - mean| / sum (x - mean)^2, reached with every error of the sign of x - mean. NaN below
// two abscissae.
double slope_error_bound(const std::vector<double>& x, double delta);

// The loading state whose strain is nearest eps (the first of equally near ones). states holds one.
const CompressionState& loading_state_nearest(const std::vector<CompressionState>& states, double eps);

// How the top-wall contact carries the force (Figs. 16, 18, 24): the pressure at the vertex nearest the
// middle (0 if none lies within l0/2 of it), and the shares of the wall force on that vertex, on the
// outermost vertex at each edge, and on the edge zones (the outermost two at each edge: the discrete
// lift-off spreads an edge line load of the elastica over the edge vertex and its neighbour). The shares are
// NaN without any force on the wall.
struct ProfileShape
{
    double centre_pressure = 0, centre_share = NAN, edge_share = NAN, edge_zone_share = NAN;
};
ProfileShape profile_shape(const CompressionState& state, double l0);

// Whether the inextensible elastica is the reference of the ring: no core (eta = 0) and elastic.
bool elastica_applies(const RingSetup& setup);

// The loading curve against the inextensible elastica at the same strains (eta = 0, elastic rings only).
struct ElasticaDeviations
{
    std::optional<double> contact_length_slope; // its L_c/b0 against eps over eps >= 0.3
    double volume_deviation_max = 0;            // max |V/V0 - (1 - eps^2)| of the elastica itself
    double width_error_max = 0;                 // max |a/a_elastica - 1|
    double volume_error_max = 0;                // max |V/V0 - V_elastica/V0|
    double force_error_max = 0;                 // max |F/F_elastica - 1| from eps = 0.05 (point load below)
    // max |(N' - 1) l0 - 2c|/l0: N' vertices span (N' - 1) l0 (decision spd-Lc-definition).
    double contact_length_error_max = 0;
    double force_second_difference = NAN; // of the elastica, at the strains of the ring's (Fig. 25)
    ElasticaState final;                  // at the largest strain
};

struct CompressionMeasures
{
    CompressionState final;  // the last loading state, at the largest strain
    CompressionState middle; // the last loading state at or below half of that strain (Figs. 14, 19)
    CompressionState early;  // the loading state nearest eps = 0.1 (Fig. 16's first profile)
    // The first loading state touching the wall (Fig. 23: eta = 0 and inf compared at the same L_c/l0 = 1).
    std::optional<CompressionState> first_contact;
    // L_c/b0 at eps = 0.25, where the paper puts the onset of faceting (Fig. 12), when reached.
    std::optional<double> contact_length_eps025;
    // Fig. 12: the slope of L_c/b0 against eps over the loading states at eps >= 0.3, and the bound on its
    // departure from the elastica's that the contact's growth by whole vertices allows (N' l0 - 2c stays
    // within +-l0 of a constant offset).
    std::optional<double> contact_length_slope;
    double contact_length_slope_quantisation = NAN;
    double volume_deviation_max = 0; // max |V/V0 - (1 - eps^2)| over the loading
    // Fig. 15: F/F* (F/F** for a plastic ring) against N' over the loading states in contact: the fitted
    // slope, and max (F/F* - N'), <= 0 where eq. (31) bounds F from above (NaN without contact).
    std::optional<double> force_contact_slope;
    double force_contact_excess_max = NAN;
    // Fig. 25, the shape of the late force growth: relative second differences of F and of ln F over the
    // loading states nearest to 1/2, 3/4 and 1 of the largest strain; 0 for a linear law (F) or an
    // exponential law (ln F), -0.17 (ln F) for any power law F ~ eps^k over eps = 0.2, 0.3, 0.4. NaN unless
    // the three states differ and carry a force.
    double force_second_difference = NAN, log_force_second_difference = NAN;
    // Eq. (35) at the largest strain: F/F* over (1 + p s l0/F*) N' (NaN without contact).
    double eq35_ratio_final = NAN;
    ProfileShape early_profile, final_profile;  // of the early and the final state
    std::optional<ElasticaDeviations> elastica; // eta = 0, elastic rings
};

// The measures of a compression of the ring `setup`, from its recorded states (result.states, which start
// with the undeformed loading state at eps = 0).
CompressionMeasures measure_compression(const RingSetup& setup, const CompressionResult& result);

} // namespace softgrain::spd
