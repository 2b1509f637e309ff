// DPM Fig. 9.5(a): a periodic triangular (hexagonal) crystal of soft disks, purely repulsive springs
// k/2 (sigma - r)^2 (eq. 9.3 for one-vertex particles), and its exact phonon spectrum, the reference for the
// dynamical matrix of eq. (9.28).
#pragma once

#include "dpm/system/system.hpp"

#include <Eigen/Dense>

#include <vector>

namespace softgrain::dpm {

// n rows of n disks of diameter sigma at spacing a (< sigma: compressed) in a periodic box
// (n a, n a sqrt(3)/2); n even. Fills x.
DpmSystem triangular_crystal(int n, double a, double sigma, double k, Eigen::VectorXd& x);

// The exact spectrum (unit masses), ascending: a pair at distance a < sigma has the Hessian block
// U'' e e^T + (U'/a)(I - e e^T) with U'' = k, U' = -k (sigma - a); the Bloch matrix of a wavevector q is
// D(q) = sum over the 6 bonds b of (1 - cos q.b) times that block, at the n^2 wavevectors of the box,
// q = 2 pi (j/L_x, l/L_y), j, l = 0 ... n-1 (distinct modulo the reciprocal lattice).
struct Phonon
{
    Eigen::Vector2d q;
    double lambda;
};
std::vector<Phonon> phonon_spectrum(int n, double a, double sigma, double k);

} // namespace softgrain::dpm
