// Jammed packings of N = 4 monodisperse disks inside a deformable boundary, DPM Fig. 9.18(a)-(e)
// (section 9.5): a closed ring of N_mu vertices with edge springs only (k_l > 0, k_a = k_b = gamma = 0,
// eq. 9.1) around 4 disks of diameter d = 1; disks and ring vertices repel by eq. (9.4) (one-vertex
// particles; k_c = 1). Protocol (decision dpm-boundary-jam): disks placed at random inside the ring; the
// rest edge length l0 of the ring shrinks in steps, FIRE after each; a step whose relaxed energy exceeds
// 2 U_t is undone and halved; jammed at U_t <= U < 2 U_t (U_t = 1e-8 k_c d^2), the protocol of section 9.4
// with the energy in place of the pressure. The packing is described by its disk-disk contacts and by theta,
// the smaller interior angle of the parallelogram formed by the four contacting disks.
// Fig. 9.18(f): with ka > 0 the ring also carries the area term k_a/2 (a - a0)^2 of eq. (9.1) (a fluid-filled
// boundary) with a0 = (N_mu l0)^2/(4 pi A0), so that its preferred shape parameter is A0; the ring then
// shrinks with A0 fixed (l0 and sqrt(a0) scaled together).
#pragma once

#include "dpm/system/system.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace softgrain::dpm {

struct BoundaryJamOptions
{
    int disks = 4;
    int boundary_nodes = 100;
    double boundary_sigma = 0.25; // ring vertex diameter / disk diameter
    double kl = 1.0;              // ring edge stiffness / k_c
    double ka = 0;                // ring area stiffness k_a [k_c / d^2]; 0: floppy boundary (Fig. 9.18a-e)
    double A0 = 1.1;              // preferred shape parameter of the ring when ka > 0 (Fig. 9.18f)
    std::uint64_t seed = 1;
};

struct BoundaryJamResult
{
    DpmSystem system; // particles 0 .. disks-1: disks; last: the ring
    Eigen::VectorXd x;
    int disk_contacts = 0; // disk pairs closer than d
    double theta = 0;      // degrees; NaN without a 4-cycle of contacts
    double energy = 0;     // at jamming [k_c d^2]
    long iterations = 0;
};

BoundaryJamResult jam_in_boundary(const BoundaryJamOptions& options);

// The ring before shrinking: a circle of radius 2.5 d + boundary_sigma (ka = 0), or with ka > 0 the polygon
// inscribed in an ellipse of that minor semi-axis whose shape parameter is A0 (zero shape energy at the
// start). Refuses (InputError) A0 < A_min and a ring whose edges would exceed the vertex diameter.
Eigen::Matrix2Xd initial_boundary(const BoundaryJamOptions& options);

// Distinct packings (decision dpm-boundary-jam) among jammed packings given as theta [deg] by contact number
// (NaN: no 4-cycle): same contact number and theta within 1 degree of a neighbour in the sorted list
// (single linkage); packings without a 4-cycle count once per contact number.
int count_distinct_packings(const std::map<int, std::vector<double>>& thetas);

// Fig. 9.18(f) measure of the continuity of theta(A0): the largest gap between consecutive sorted thetas
// (NaN ignored) over their range; NaN below two values. Five values (the floppy boundary's packings) give at
// least 1/4; a continuous curve tends to 0.
double largest_gap_over_range(std::vector<double> thetas);

// The packings with a 4-cycle among jammed packings given as theta [deg] (NaN: none) and the range of their
// theta: touching equal disks bound it to [60, 90] deg (the short diagonal of the rhombus cannot be shorter
// than d), up to the overlaps U < 2 U_t allows. min and max are nothing without such a packing.
struct ThetaRange
{
    long packings = 0;
    std::optional<double> min, max;
};
ThetaRange theta_range(const std::vector<double>& thetas);

} // namespace softgrain::dpm
