// Measures of the tensile fracture of a tissue (Trivino et al., section 6, Figs. 31-34; decision
// spd-tissue-measures): the stress curve's peak, failure strain and stress drops, the crack, and the
// strength of one link loaded through the model (eq. (39)).
//
// Units: sigma = F_top/(W s) [Pa]; drops and their growth in sigma_max; strains ln(H/H0); forces [N].
#pragma once

#include "spd/tissue.hpp"

#include <cstddef>
#include <vector>

namespace softgrain::spd {

// Stress drops: sigma falls by more than `threshold` from a running maximum before it rises by `threshold`
// above the running minimum; a drop's size is maximum - minimum (a drop still open at the end counts).
std::vector<double> stress_drops(const std::vector<double>& sigma, double threshold);

// The stored snapshot closest in strain to `strain` (the first of equally close ones).
std::size_t nearest_snapshot(const std::vector<TissueSnapshot>& snapshots, double strain);

// The measures of Fig. 33 on the recorded curve: sigma = F_top/(W s), its peak, the failure strain (first
// record after the peak below 0.1 sigma_max), the stress drops of more than 0.05 sigma_max and the growth of
// their size (mean of the later half over mean of the earlier half; NaN below two drops).
struct CurveMeasures
{
    std::vector<double> sigma; // [Pa], one per record
    double sigma_max = 0;
    std::size_t peak = 0; // record of sigma_max
    double strain_at_failure = NAN;
    std::vector<double> drops; // [sigma_max]
    double growth = NAN;
};
CurveMeasures curve_measures(const std::vector<TissueRecord>& records, double width_depth);

// Mean height of the broken links (the midpoints of their vertices) above the bottom clamp, over H; NaN
// without any broken link.
double crack_height(const Tissue& tissue);

// Fig. 31: one link of a built tissue, loaded through the model's own force evaluation
// (ShellModel::compute_forces, which tests eq. (39) and breaks the link): both vertices of its cell-j side
// (b and b' for an opening, b alone for a slip) are first moved by `approach` along -n (closing, f_n > 0),
// then step by step by `increment` along n (opening) or t (slip) until the link breaks. Returns the link's
// f_n, f_t at the break [N] and the distance moved [m] (NaN if it never broke in 20000 steps or the model
// stopped with a numerical failure).
struct LinkBreak
{
    double f_n = NAN, f_t = NAN, moved = NAN;
};
LinkBreak break_one_link(ShellModel model, std::size_t index, double approach, bool opening, double increment,
                         double dt);

// The first link of the tissue broken in pure opening (mode I) and in shear under the compression
// f_n = |f_n^0|/2, in increments of 7e-4 of the threshold per step (the contact law, which acts between
// linked cells too, holds an overlap of |f_n^0|/(2 k_n) = 0.48 (r_i + r_j) at the default cohesion;
// |f_n^0|/k_n would exceed its 0.95 (r_i + r_j)).
struct LinkStrength
{
    LinkBreak mode_one, shear;
};
LinkStrength measure_link_strength(const Tissue& tissue, double dt);

} // namespace softgrain::spd
